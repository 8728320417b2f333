"""The real C++ robot_state_publisher (ROS 1) driven by robotmodel's joint_state_publisher, read by robotmodel's tf2_echo.

robot_description is on the real parameter server (set through the master API, as
``rosparam set`` does); Debian's robot_state_publisher reads it from there, takes
robotmodel's /joint_states and publishes /tf; ``robotmodel tf2_echo`` prints the pose,
compared with robotmodel's FK at tf2_echo's three decimals.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ros1helpers import GroupProc, Ros1World, wait_until

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

ARM = Path(__file__).resolve().parent.parent.parent / "urdf" / "arm.urdf.xacro"
REAL_RSP = "/usr/lib/robot_state_publisher/robot_state_publisher"
VALUES = {"arm_base_joint": 0.3, "arm_shoulder_joint": -0.7, "arm_elbow_joint": 1.1, "arm_wrist_pitch_joint": 0.4,
          "arm_wrist_roll_joint": -0.9, "arm_wrist_yaw_joint": 0.2, "gripper_left_finger_joint": 0.01}


def robotmodel(ros1: Ros1World, *args: str) -> GroupProc:
    """A robotmodel command as a sourced ROS 1 shell runs it (ROS_VERSION=1, ROS_MASTER_URI: no flag)."""
    ros1.env["ROS_VERSION"] = "1"
    return ros1.start(sys.executable, "-m", "robotmodel.cli.main", *args)


def test_real_rsp_from_the_parameter_server_driven_by_robotmodel_jsp_to_robotmodel_tf2_echo(ros1: Ros1World) -> None:
    desc = load(ARM)
    assert desc.source_text
    ros1.node("setter").params.set_param("/robot_description", desc.source_text)
    rsp = ros1.start(REAL_RSP)
    robotmodel(ros1, "joint_state_publisher", str(ARM), "--zeros", *(f"{n}={v!r}" for n, v in VALUES.items()))
    wait_until(lambda: "pub /tf" in ros1.registrations_of("/robot_state_publisher"), 60, "the real RSP's /tf")
    state = KinematicState(KinematicModel(desc))
    state.update({**VALUES, "gripper_right_finger_joint": VALUES["gripper_left_finger_joint"]})  # the mimic
    echo = robotmodel(ros1, "tf2_echo", "world", "gripper_right_finger_link")
    got = echo.wait_line(r"- Translation: \[(\S+), (\S+), (\S+)\]", 60)
    printed = [float(v) for v in got.groups()]
    fk = state.link_matrix("gripper_right_finger_link")[:3, 3]
    assert printed == [float(f"{v:.3f}") for v in fk], (printed, fk)
    assert abs(fk).max() > 0.05  # a pose that tells joints apart, not the origin
    assert rsp.popen.poll() is None, rsp.lines[-10:]
