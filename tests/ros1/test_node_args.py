"""ROS 1's command-line forms (``__name:=``, ``__ns:=``, ``from:=to``, ``_param:=value``) on the ROS 1 wire.

Unit checks of robotmodel.rcl's reading, then robotmodel's robot_state_publisher on a real
roscore seen by the real rosnode/rosparam/rostopic and a rospy tf2 listener.
"""

from __future__ import annotations

import signal
import sys
from pathlib import Path

import numpy as np
import pytest
from ros1helpers import SYSTEM_PYTHON, GroupProc, Ros1World, wait_until

from robotmodel.errors import RosArgsError
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load
from robotmodel.rcl import take_node_args

HERE = Path(__file__).resolve().parent
LISTENER = HERE / "tf2_listener.py"
JOINT_STATES = HERE / "rospy_joint_states.py"
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
ROS1 = {"ROS_VERSION": "1", "ROS_MASTER_URI": "http://127.0.0.1:1"}


def test_ros1_words_are_read_on_the_ros1_wire_only() -> None:
    words = ["arm.urdf", "__name:=my_rsp", "__ns:=r1", "_publish_frequency:=10.0", "_n:=3", "_on:=true",
             "_s:=hello", "joint_states:=/arm/joint_states", "__master:=http://x:1", "--flag"]
    ros, rest = take_node_args(words, "robot_state_publisher", ROS1)
    assert rest == ["arm.urdf", "--flag"]
    assert (ros.node_name, ros.namespace, ros.remaps) == ("my_rsp", "/r1", ("joint_states:=/arm/joint_states",))
    # typed as rospy reads them (YAML)
    assert [(n, v) for _, n, v in ros.params] == [("publish_frequency", 10.0), ("n", 3), ("on", True), ("s", "hello")]
    # elsewhere they are left to the command (xacro's name:=value mappings)
    ros, rest = take_node_args(words, "robot_state_publisher", {})
    assert rest == words and ros.node_name is None and ros.params == ()
    # --ros-args blocks still work, and their __node wins
    ros, _ = take_node_args(["__name:=a", "--ros-args", "-r", "__node:=b"], "x", ROS1)
    assert ros.node_name == "b"
    with pytest.raises(RosArgsError, match="__bogus"):
        take_node_args(["__bogus:=1"], "x", ROS1)


def robotmodel(ros1: Ros1World, *args: str) -> GroupProc:
    """A robotmodel command as a sourced ROS 1 shell runs it (ROS_VERSION=1, ROS_MASTER_URI: no flag)."""
    ros1.env["ROS_VERSION"] = "1"
    return ros1.start(sys.executable, "-m", "robotmodel.cli.main", *args)


def pose_matrix(x: float, y: float, z: float, qx: float, qy: float, qz: float, qw: float) -> np.ndarray:
    """The 4x4 matrix of a pose (unit quaternion x, y, z, w), written out from the quaternion's definition."""
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                 [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                 [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    m[:3, 3] = [x, y, z]
    return m


def test_rsp_takes_ros1_name_private_params_and_remaps(ros1: Ros1World) -> None:
    rsp = robotmodel(ros1, "robot_state_publisher", str(ARM), "__name:=my_rsp", "_publish_frequency:=10.0",
                     "_tf_prefix:=left", "joint_states:=/arm/joint_states")
    wait_until(lambda: "/my_rsp" in ros1.tool("rosnode", "list").split(), 60, "/my_rsp in the real rosnode list")
    # the private parameters are on the server, as rospy and roscpp put them
    assert ros1.tool("rosparam", "get", "/my_rsp/publish_frequency").strip() == "10.0"
    info = ros1.tool("rostopic", "info", "/arm/joint_states")
    assert " * /my_rsp" in info, info
    values = {"arm_base_joint": 0.3, "arm_shoulder_joint": -0.7, "arm_elbow_joint": 1.1}
    ros1.start(SYSTEM_PYTHON, str(JOINT_STATES), "/arm/joint_states",
               *(f"{n}={v!r}" for n, v in values.items())).wait_line(r"^ready$", 60)
    # tf_prefix as ROS 1's robot_state_publisher applies it: "left/" before every frame
    tf = ros1.start(SYSTEM_PYTHON, str(LISTENER), "left/world", "left/arm_fore_link")
    got = tf.wait_line(r"^pose left/world left/arm_fore_link (.*)$", 60)
    state = KinematicState(KinematicModel(load(ARM)))
    state.update(values)
    np.testing.assert_allclose(pose_matrix(*(float(v) for v in got.group(1).split())),
                               state.link_matrix("arm_fore_link"), atol=1e-9, rtol=0)
    assert rsp.popen.poll() is None


def test_rsp_ros1_namespace_remapped_description_and_a_remap_that_matches_nothing(ros1: Ros1World) -> None:
    ros1.node("setter").params.set_param("/my_desc", load(ARM).source_text)
    # robot_description:= remaps the parameter as rospy and roscpp remap every name; use_gui:= matches nothing
    rsp = robotmodel(ros1, "robot_state_publisher", "__ns:=r1", "robot_description:=/my_desc", "use_gui:=true")
    wait_until(lambda: "/r1/robot_state_publisher" in ros1.tool("rosnode", "list").split(), 60,
               "/r1/robot_state_publisher in rosnode list")
    assert " * /r1/robot_state_publisher" in ros1.tool("rostopic", "info", "/r1/joint_states")
    rsp.wait_line(r"^remap 'use_gui:=true' matches no name robot_state_publisher uses", 60)
    rsp.kill(signal.SIGINT)
    assert rsp.popen.returncode == 0 and rsp.count(r"^remap ") == 1, rsp.lines


def test_static_transform_publisher_and_tf2_echo_take_ros1_forms(ros1: Ros1World) -> None:
    # ROS 1's positional form with __name and a remap of /tf_static, echoed by a renamed tf2_echo
    robotmodel(ros1, "static_transform_publisher", "1", "2", "3", "0", "0", "0", "map", "odom", "__name:=my_stp",
               "/tf_static:=/r1/tf_static")
    wait_until(lambda: "/my_stp" in ros1.tool("rosnode", "list").split(), 60, "/my_stp in rosnode list")
    assert " * /my_stp" in ros1.tool("rostopic", "info", "/r1/tf_static")
    echo = robotmodel(ros1, "tf2_echo", "map", "odom", "__name:=my_echo", "/tf_static:=/r1/tf_static")
    echo.wait_line(r"- Translation: \[1\.000, 2\.000, 3\.000\]", 60)
    assert "/my_echo" in ros1.tool("rosnode", "list").split()
