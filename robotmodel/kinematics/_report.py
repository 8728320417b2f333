"""``fk`` as a program: each link's pose in the root frame, printed as text or JSON."""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription

__all__ = ["run_fk"]


def run_fk(desc: RobotDescription, joints: Mapping[str, float] | None = None, *, link: str | None = None,
           clamp: bool = False, format: str = "text") -> int:
    """Print every link's pose (or ``link``'s) in the root frame for ``joints``, as text or JSON; the exit code.

    Joints not given take joint_state_publisher's default; ``clamp`` clamps values into the
    limits (else a value outside them raises JointValueError); an unknown ``link`` raises
    UnknownLinkError.
    """
    from robotmodel.kinematics._model import KinematicModel
    from robotmodel.kinematics._state import KinematicState

    model = KinematicModel(desc)
    state = KinematicState(model).update(dict(joints or {}), clamp=clamp)
    links = [link] if link else list(model.link_names)
    # An unknown --link is the library's UnknownLinkError, as from every kinematics API.
    poses = {name: state.link_pose(name) for name in links}
    if format == "json":
        report = {"root": model.root, "links": {
            name: {"xyz": list(p.translation), "quat_xyzw": list(p.rotation), "rpy": list(p.rpy())}
            for name, p in poses.items()
        }}
        print(json.dumps(report, indent=2))
        return 0
    print(f"root: {model.root}")
    for name, pose in poses.items():
        x, y, z = pose.translation
        qx, qy, qz, qw = pose.rotation
        r, p, yaw = pose.rpy()
        print(f"{name}:")
        print(f"  Translation: [{x:.6f}, {y:.6f}, {z:.6f}]")
        print(f"  Rotation: in Quaternion (xyzw) [{qx:.6f}, {qy:.6f}, {qz:.6f}, {qw:.6f}]")
        print(f"  Rotation: in RPY (radian) [{r:.6f}, {p:.6f}, {yaw:.6f}]")
        print(f"  Rotation: in RPY (degree) [{math.degrees(r):.6f}, {math.degrees(p):.6f}, "
              f"{math.degrees(yaw):.6f}]")
    return 0
