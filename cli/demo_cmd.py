"""``robotmodel demo``: a short tour of the toolkit on the bundled robots (no server, no files)."""

from __future__ import annotations

import argparse
import math
from typing import Any


def register(sub: Any) -> None:
    """Add the ``demo`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "demo", help="tour the toolkit on the bundled robots: check, FK, robot_state_publisher, TF lookups")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the tour."""
    # Imported here so `robotmodel --help` does not load NumPy and Pinocchio.
    import numpy as np
    import robotmodel.robots

    from robotmodel.check import lint, tree_report
    from robotmodel.kinematics import KinematicModel, KinematicState, joint_transforms, static_transforms
    from robotmodel.model import load
    from robotmodel.tf import Buffer, Time, make_transform

    print(f"Bundled robots: {', '.join(robotmodel.robots.names())}\n")

    path = robotmodel.robots.path("diffbot.urdf.xacro")
    desc = load(path)
    print(f"== check_urdf diffbot.urdf.xacro (xacro expanded without ROS)\n{tree_report(desc)}")
    findings = lint(desc, base_dir=path.parent)
    print(f"lint: {len(findings)} finding(s)\n")

    arm = KinematicModel.load(robotmodel.robots.path("arm.urdf.xacro"))
    values = {"arm_shoulder_joint": 0.6, "arm_elbow_joint": -1.1, "arm_wrist_pitch_joint": 0.5,
              "gripper_left_finger_joint": 0.02}
    state = KinematicState(arm).update(values)
    pose = state.link_pose("gripper_palm_link")
    print("== forward kinematics (Pinocchio): arm, " + ", ".join(f"{k}={v}" for k, v in values.items()))
    print(f"gripper_palm_link in {arm.root}: xyz {np.round(pose.translation, 4).tolist()} "
          f"rpy {np.round(pose.rpy(), 4).tolist()}")
    fingers = [state.link_matrix(f"gripper_{s}_finger_link")[:3, 3] for s in ("left", "right")]
    print(f"finger gap (right finger mimics left): {np.linalg.norm(fingers[0] - fingers[1]):.4f} m\n")

    # robot_state_publisher + odometry into a tf2-style buffer, then tf2 lookups.
    model = KinematicModel(desc)
    buffer = Buffer()
    statics = static_transforms(model)
    for k in range(len(statics.joints)):
        buffer.set_transform_static(make_transform(statics.parents[k], statics.children[k],
                                                   statics.translations[k], statics.rotations[k]),
                                    "robot_state_publisher")
    buffer.set_transform_static(make_transform("map", "odom", (1.0, 2.0, 0.0)), "static_transform_publisher")
    start = 1_700_000_000 * 1_000_000_000
    for i in range(51):  # one second of driving in a circle at 50 Hz
        t_ns = start + i * 20_000_000
        yaw = 0.5 * i / 50
        buffer.set_transform(make_transform("odom", "base_footprint", (math.sin(yaw), 1 - math.cos(yaw), 0.0),
                                            (0, 0, math.sin(yaw / 2), math.cos(yaw / 2)), t_ns), "odometry")
        wheels = joint_transforms(model, {"left_wheel_joint": 10.0 * i / 50, "right_wheel_joint": 9.0 * i / 50})
        for k in range(len(wheels.joints)):
            buffer.set_transform(make_transform(wheels.parents[k], wheels.children[k], wheels.translations[k],
                                                wheels.rotations[k], t_ns), "robot_state_publisher")
    when = Time(nanoseconds=start + 505_000_000)
    cam = buffer.lookup_transform("map", "camera_link", when)
    tr, q = cam.transform.translation, cam.transform.rotation
    print("== TF: where was the camera in the map frame at t = start + 0.505 s? (interpolated)")
    print(f"translation [{tr.x:.4f}, {tr.y:.4f}, {tr.z:.4f}]  rotation xyzw [{q.x:.4f}, {q.y:.4f}, {q.z:.4f}, "
          f"{q.w:.4f}]")
    stamps = np.linspace(start, start + 1_000_000_000, 1000).astype(np.int64)
    translations, _ = buffer.lookup_transforms("map", "laser_link", stamps)
    path_length = np.linalg.norm(np.diff(translations, axis=0), axis=1).sum()
    print(f"laser_link path over 1 s (1000 vectorized lookups): {path_length:.4f} m")
    try:
        buffer.lookup_transform("map", "camera_link", Time(nanoseconds=start + 2_000_000_000))
    except Exception as exc:
        print(f"asking beyond the data, as tf2: {type(exc).__name__}: {exc}")
    print("\n== frames (tf2's allFramesAsYAML, abridged)")
    for child, parent in buffer.frames().items():
        print(f"{child} -> parent {parent}")
    return 0
