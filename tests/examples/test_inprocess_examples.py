"""The in-process example (robot_state_publisher.py): its printed gripper position against FK."""

from __future__ import annotations

import re
import subprocess
import sys

import numpy as np
import robotmodel.robots
from conftest import REPO

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load


def test_robot_state_publisher_example_prints_fk():
    done = subprocess.run([sys.executable, str(REPO / "examples" / "robot_state_publisher.py")], capture_output=True,
                          text=True, timeout=120, check=True)
    assert "gripper reachable: False" in done.stdout  # wrist joints not published yet, as RSP
    m = re.search(r"gripper_palm_link in world at t=1 s: \[([-\d.]+), ([-\d.]+), ([-\d.]+)\]", done.stdout)
    assert m, done.stdout
    state = KinematicState(KinematicModel(load(robotmodel.robots.path("arm.urdf.xacro"))))
    state.update({"arm_base_joint": 0.3, "arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.8,
                  "gripper_left_finger_joint": 0.01, "arm_wrist_pitch_joint": 0.0, "arm_wrist_roll_joint": 0.0,
                  "arm_wrist_yaw_joint": 0.0})
    np.testing.assert_allclose([float(v) for v in m.groups()], state.link_matrix("gripper_palm_link")[:3, 3],
                               atol=6e-5)
