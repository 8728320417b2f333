"""robot_description from the ROS 1 parameter server: robotmodel's publishers without FILE, against real ROS 1.

As ROS 1's robot_state_publisher (urdf's initParam: roscpp's searchParam) it looks
``robot_description`` up the node's namespace on the real master (joint_state_publisher, as
Debian's, reads its private one or its namespace's only); a rospy JointState publisher
drives robotmodel's robot_state_publisher and a rospy tf2 listener checks the poses against
robotmodel's FK.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from ros1helpers import SYSTEM_PYTHON, GroupProc, Ros1World, wait_until

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

HERE = Path(__file__).resolve().parent
LISTENER = HERE / "tf2_listener.py"
JOINT_STATES = HERE / "rospy_joint_states.py"
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
VALUES = {"arm_base_joint": 0.3, "arm_shoulder_joint": -0.7, "arm_elbow_joint": 1.1, "arm_wrist_pitch_joint": 0.4,
          "arm_wrist_roll_joint": -0.9, "arm_wrist_yaw_joint": 0.2, "gripper_left_finger_joint": 0.01,
          "gripper_right_finger_joint": 0.01}
LINKS = ["gripper_right_finger_link", "arm_wrist_yaw_link", "arm_fore_link"]


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


def urdf_text() -> str:
    text = load(ARM).source_text
    assert text
    return text


def check_fk(ros1: Ros1World, values: dict[str, float]) -> None:
    """A rospy tf2 listener gets robotmodel's FK poses for LINKS (<= 1e-9)."""
    pairs = [arg for link in LINKS for arg in ("world", link)]
    tf = ros1.start(SYSTEM_PYTHON, str(LISTENER), *pairs)
    tf.wait_line(r"^ready$", 60)
    state = KinematicState(KinematicModel(load(ARM)))
    state.update(values)
    for link in LINKS:
        got = tf.wait_line(rf"^pose world {link} (.*)$", 60)
        pose = pose_matrix(*(float(v) for v in got.group(1).split()))
        np.testing.assert_allclose(pose, state.link_matrix(link), atol=1e-9, rtol=0, err_msg=link)


def test_rsp_without_file_reads_robot_description_from_the_parameter_server(ros1: Ros1World) -> None:
    ros1.node("setter").params.set_param("/robot_description", urdf_text())
    rsp = robotmodel(ros1, "robot_state_publisher")
    ros1.start(SYSTEM_PYTHON, str(JOINT_STATES), "/joint_states",
               *(f"{name}={value!r}" for name, value in VALUES.items())).wait_line(r"^ready$", 60)
    check_fk(ros1, VALUES)
    assert rsp.popen.poll() is None


def test_rsp_searches_robot_description_up_the_namespace_and_jsp_does_not(ros1: Ros1World) -> None:
    # Set one level up from the nodes' namespace: RSP's searchParam finds /r1/robot_description from
    # /r1/arm; joint_state_publisher's get_param reads ~robot_description or /r1/arm/robot_description only.
    ros1.node("setter").params.set_param("/r1/robot_description", urdf_text())
    real_jsp = ros1.start(SYSTEM_PYTHON, "/usr/lib/joint_state_publisher/joint_state_publisher", "__ns:=/r1/arm")
    jsp = robotmodel(ros1, "joint_state_publisher", "--namespace", "/r1/arm")
    real_jsp.wait_line(r"RuntimeError: The robot_description parameter is required and not set\.$", 60)
    jsp.wait_line(r"\]: The robot_description parameter is required and not set\.$", 60)
    assert jsp.popen.wait(30) == 1, jsp.lines
    zeros = [f"{name}={value!r}" for name, value in VALUES.items() if name != "gripper_right_finger_joint"]
    robotmodel(ros1, "robot_state_publisher", "--namespace", "/r1/arm")
    robotmodel(ros1, "joint_state_publisher", "--namespace", "/r1", "joint_states:=/r1/arm/joint_states",
               "--zeros", *zeros)
    wait_until(lambda: "pub /r1/arm/joint_states" in ros1.registrations_of("/r1/joint_state_publisher"), 60,
               "joint_state_publisher in /r1 publishing to /r1/arm")
    check_fk(ros1, VALUES)  # the right finger mimics the left one


def test_rsp_without_file_or_parameter_fails_with_ros1s_lines(ros1: Ros1World) -> None:
    rsp = robotmodel(ros1, "robot_state_publisher")
    rsp.wait_line(r"Could not find parameter robot_description on parameter server", 60)
    assert rsp.popen.wait(30) == 1, rsp.lines[-10:]


def test_view_follow_without_file_serves_the_robot_on_the_parameter_server(ros1: Ros1World) -> None:
    import urllib.request

    ros1.node("setter").params.set_param("/robot_description", urdf_text())
    view = robotmodel(ros1, "view", "--follow", "--port", "0")
    url = view.wait_line(r"^(http://\S+) \(view: the robot following /joint_states\)", 60).group(1)
    with urllib.request.urlopen(url, timeout=30) as page:
        assert "<title>arm — robotmodel view</title>" in page.read().decode()
