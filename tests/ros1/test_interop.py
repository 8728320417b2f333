"""robotmodel's commands on the ROS 1 wire against Debian's real ROS 1, both directions.

Each test has a private roscore (the ``ros1`` fixture) and runs robotmodel's commands as a
user with a sourced ROS 1 does: ``ROS_VERSION=1`` and ``ROS_MASTER_URI`` set, no flag. On the
other side are the real C++ static_transform_publisher, a rospy tf2_ros listener
(tests/ros1/tf2_listener.py), rospy publishers and the real rostopic/rosnode.
"""

from __future__ import annotations

import math
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from ros1helpers import SYSTEM_PYTHON, GroupProc, Ros1World, wait_until

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

HERE = Path(__file__).resolve().parent
LISTENER = HERE / "tf2_listener.py"
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
STATIC_TRANSFORM_PUBLISHER = "/usr/lib/tf2_ros/static_transform_publisher"
# tf2_tools' echo.py (it needs python3-numpy, which .ci/run installs with ROS 1).
ECHO = Path("/usr/lib/tf2_tools/echo.py")


def robotmodel(ros1: Ros1World, *args: str) -> GroupProc:
    """A robotmodel command as a sourced ROS 1 shell runs it (ROS_VERSION=1, ROS_MASTER_URI: no flag)."""
    ros1.env["ROS_VERSION"] = "1"
    return ros1.start(sys.executable, "-m", "robotmodel.cli.main", *args)


def listener(ros1: Ros1World, *args: str) -> GroupProc:
    proc = ros1.start(SYSTEM_PYTHON, str(LISTENER), *args)
    proc.wait_line(r"^ready$", 60)
    return proc


def publishes(ros1: Ros1World, node: str, topic: str) -> bool:
    return f"pub {topic}" in ros1.registrations_of(node)


def pose_matrix(x: float, y: float, z: float, qx: float, qy: float, qz: float, qw: float) -> np.ndarray:
    """The 4x4 matrix of a pose (unit quaternion x, y, z, w), written out from the quaternion's definition."""
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                 [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                 [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]]
    m[:3, 3] = [x, y, z]
    return m


def test_real_static_transform_publisher_to_robotmodel_tf2_echo(ros1: Ros1World) -> None:
    stp = ros1.start(STATIC_TRANSFORM_PUBLISHER, "1", "2", "3", "0", "0", "0", "map", "odom")
    wait_until(lambda: any(topic == "/tf_static" for topic, _ in ros1.master.get_system_state()[0]), 30,
               "the real static_transform_publisher's /tf_static")
    echo = robotmodel(ros1, "tf2_echo", "map", "odom")
    echo.wait_line(r"- Translation: \[1\.000, 2\.000, 3\.000\]", 60)
    echo.wait_line(r"- Rotation: in Quaternion \[0\.000, 0\.000, 0\.000, 1\.000\]", 10)
    assert stp.popen.poll() is None


def test_robotmodel_static_transform_publisher_to_a_later_rospy_tf2_listener(ros1: Ros1World) -> None:
    """ROS 1's positional form (x y z yaw pitch roll frame child): a rospy tf2 listener and the real
    tf2_tools echo.py, both started after the one latched message was sent, print it."""
    stp = robotmodel(ros1, "static_transform_publisher", "1", "2", "3", "0.5", "0", "0", "map", "odom")
    wait_until(lambda: any(topic == "/tf_static" for topic, _ in ros1.master.get_system_state()[0]), 60,
               "robotmodel's /tf_static registration")
    # Started after the one message was sent: only a latched /tf_static reaches it.
    got = listener(ros1, "map", "odom").wait_line(r"^pose map odom (.*)$", 60)
    pose = [float(v) for v in got.group(1).split()]
    assert pose == pytest.approx([1.0, 2.0, 3.0, 0.0, 0.0, math.sin(0.25), math.cos(0.25)], abs=1e-12)
    if ECHO.exists() and subprocess.run([SYSTEM_PYTHON, "-c", "import numpy"], capture_output=True, check=False).returncode == 0:
        echo = ros1.start(SYSTEM_PYTHON, str(ECHO), "map", "odom", "-p", "6")
        echo.wait_line(r"^- Translation: \[1\.000000, 2\.000000, 3\.000000\]$", 60)
        q = echo.wait_line(r"^- Rotation: in Quaternion \[(.*)\]$", 30).group(1)
        assert q == ", ".join(f"{v:.6f}" for v in (0.0, 0.0, math.sin(0.25), math.cos(0.25))), q
    assert stp.popen.poll() is None


def test_robotmodel_state_publishers_to_rospy_tf2_and_the_real_tools(ros1: Ros1World) -> None:
    rsp = robotmodel(ros1, "robot_state_publisher", str(ARM))
    # Off zero, so that every joint's rotation and the prismatic fingers count.
    jsp = robotmodel(ros1, "joint_state_publisher", str(ARM), "--zeros", "arm_base_joint=0.3",
                     "arm_shoulder_joint=-0.7", "arm_elbow_joint=1.1", "arm_wrist_pitch_joint=0.4",
                     "arm_wrist_roll_joint=-0.9", "arm_wrist_yaw_joint=0.2", "gripper_left_finger_joint=0.01")
    wait_until(lambda: publishes(ros1, "/robot_state_publisher", "/tf")
               and publishes(ros1, "/joint_state_publisher", "/joint_states"), 60, "both publishers registered")
    links = ["gripper_right_finger_link", "arm_wrist_yaw_link", "arm_fore_link"]
    pairs = [arg for link in links for arg in ("world", link)]
    tf = listener(ros1, "--joint-states", *pairs)
    joints = tf.wait_line(r"^joints (.*)$", 60).group(1)
    values = {name: float(value) for name, _, value in (item.partition("=") for item in joints.split())}
    assert values["arm_elbow_joint"] == 1.1 and values["gripper_left_finger_joint"] == 0.01, values
    state = KinematicState(KinematicModel(load(ARM)))
    state.update(values)
    for link in links:
        got = tf.wait_line(rf"^pose world {link} (.*)$", 60)
        pose = pose_matrix(*(float(v) for v in got.group(1).split()))
        np.testing.assert_allclose(pose, state.link_matrix(link), atol=1e-9, rtol=0, err_msg=link)

    nodes = ros1.tool("rosnode", "list").split()
    assert {"/robot_state_publisher", "/joint_state_publisher"} <= set(nodes), nodes
    topics = ros1.tool("rostopic", "list").split()
    assert {"/tf", "/tf_static", "/joint_states"} <= set(topics), topics
    assert "/robot_description" not in topics, topics  # ROS 1's RSP has the parameter only
    info = ros1.tool("rostopic", "info", "/joint_states")
    assert "Type: sensor_msgs/JointState" in info and " * /robot_state_publisher" in info, info

    for proc in (rsp, jsp):
        proc.kill(signal.SIGINT)
        assert proc.popen.returncode == 0, proc.lines[-10:]
    # Nothing of theirs is left at the master.
    assert ros1.registrations_of("/robot_state_publisher") == []
    assert ros1.registrations_of("/joint_state_publisher") == []
    nodes = ros1.tool("rosnode", "list").split()
    assert "/robot_state_publisher" not in nodes and "/joint_state_publisher" not in nodes, nodes


def test_robotmodel_topic_list_shows_a_rospy_talkers_topic_and_type(ros1: Ros1World) -> None:
    talker = ros1.rospy("pub", "/chatter", "std_msgs/String", "--name", "talker")
    talker.wait_line(r"^published", 60)
    listed = robotmodel(ros1, "topic", "list", "-t")
    listed.wait_line(r"^/chatter \[std_msgs/msg/String\]$", 60)
    echo = robotmodel(ros1, "topic", "echo", "/chatter")
    echo.wait_line(r"^data: hello \d+$", 60)


def test_record_of_a_ros1_system_reads_back_with_rosbags_and_tf2_echo(ros1: Ros1World, tmp_path: Path) -> None:
    from rosbags.rosbag2 import Reader

    from robotmodel.msgs import typestore

    ros1.start(STATIC_TRANSFORM_PUBLISHER, "1", "2", "3", "0", "0", "0", "map", "odom")
    talker = ros1.rospy("pub", "/tf", "tf2_msgs/TFMessage", "--text", "hello", "--name", "tf_talker")
    out = tmp_path / "rec.mcap"
    rec = robotmodel(ros1, "record", "-o", str(out), "/tf", "/tf_static")
    rec.wait_line(r"Recording to", 60)
    seen = talker.count(r"^published")
    wait_until(lambda: talker.count(r"^published") >= seen + 5, 60, "five /tf messages while recording")
    rec.kill(signal.SIGINT)
    assert rec.popen.returncode == 0, rec.lines[-10:]

    with Reader(out) as reader:
        got: dict[str, list[tuple[str, str, float]]] = {}
        for conn, _, data in reader.messages():
            msg = typestore().deserialize_cdr(data, conn.msgtype)
            got.setdefault(conn.topic, []).extend(
                (t.header.frame_id, t.child_frame_id, t.transform.translation.x) for t in msg.transforms)
    assert got["/tf_static"] == [("map", "odom", 1.0)]
    # rospy_peer's /tf: world -> hello<i> with x = i (the stamp 1700000000 s + i ns)
    tf = got["/tf"]
    assert len(tf) >= 4 and all(child == f"hello{int(x)}" and parent == "world" for parent, child, x in tf), tf
    # (rospy_peer's /tf frames each hold one stamp 1 ns apart: tf2_echo --bag is shown the static one)
    echo = ros1.start(sys.executable, "-m", "robotmodel.cli.main", "tf2_echo", "--bag", str(out), "map", "odom")
    echo.wait_line(r"- Translation: \[1\.000, 2\.000, 3\.000\]", 60)


def test_rosnode_kill_stops_a_robotmodel_command(ros1: Ros1World) -> None:
    stp = robotmodel(ros1, "static_transform_publisher", "--frame-id", "map", "--child-frame-id", "odom")
    name = wait_until(lambda: next((n for n in ros1.tool("rosnode", "list").split()
                                    if n.startswith("/static_transform_publisher")), None), 60,
                      "robotmodel's static_transform_publisher in rosnode list")
    out = ros1.tool("rosnode", "kill", name)
    assert f"killing {name}" in out and "killed" in out, out
    assert stp.popen.wait(30) == 0, stp.lines[-10:]
    assert ros1.registrations_of(name) == []
    assert name not in ros1.tool("rosnode", "list").split()
