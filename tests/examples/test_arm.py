"""Arm: a joint trajectory → /joint_states → robot_state_publisher → the gripper pose a listener prints.

Each printed pose is checked against KinematicState's FK at the trajectory's positions for
that stamp, interpolated here from the example's points (its data, not its code).
"""

from __future__ import annotations

import importlib.util
import re

import numpy as np
import robotmodel.robots
from conftest import REPO

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load
from robotmodel.spatial import quat_to_matrix

ARM = robotmodel.robots.path("arm.urdf.xacro")


def _example_data() -> tuple[list[str], list[tuple[float, list[float]]]]:
    spec = importlib.util.spec_from_file_location("arm_trajectory_data", REPO / "examples" / "arm_trajectory.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.JOINT_NAMES, module.POINTS


def _at(points: list[tuple[float, list[float]]], t: float) -> np.ndarray:
    times = np.array([p[0] for p in points])
    values = np.array([p[1] for p in points])
    return np.array([np.interp(t, times, values[:, j]) for j in range(values.shape[1])])


def test_gripper_pose_follows_the_trajectory(live):
    names, points = _example_data()
    rsp = live.robotmodel("robot-state-publisher", str(ARM))
    listener = live.example("arm_gripper_listener.py", "--duration", "20")
    traj = live.example("arm_trajectory.py", "--duration", "7")
    start = int(traj.wait_line(r"trajectory started at (\d+) ns", timeout=30).group(1))
    assert traj.popen.wait(30) == 0
    listener.stop()
    rsp.stop()
    rx = re.compile(r"at (\d+): xyz \(([^)]*)\) xyzw \(([^)]*)\)")
    poses = [(int(m.group(1)), [float(v) for v in m.group(2).split(",")], [float(v) for v in m.group(3).split(",")])
             for m in map(rx.search, listener.out) if m]
    assert len(poses) >= 30, listener.out[-5:]
    state = KinematicState(KinematicModel(load(ARM)))
    moving = 0
    for stamp, xyz, xyzw in poses:
        q = _at(points, (stamp - start) / 1e9)
        state.update(dict(zip(names, q, strict=True)))
        expected = state.link_matrix("gripper_palm_link")
        np.testing.assert_allclose(xyz, expected[:3, 3], atol=1e-9)
        np.testing.assert_allclose(quat_to_matrix(xyzw), expected[:3, :3], atol=1e-9)
        moving += 0 < stamp - start < 6e9
    assert moving >= 20  # most samples are mid-trajectory, not the resting ends
