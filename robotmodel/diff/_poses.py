"""How each link moved at the zero configuration: FK of both descriptions, compared pose by pose.

The zero configuration is every joint variable at 0, whatever the limits (not
joint_state_publisher's middle-of-the-limits default: a changed limit must not read as
a moved link). Mimic joints take their offset (their master is at 0); floating and
planar joints stay at their origin. Poses are T_root_link, each in its own robot's root.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from robotmodel.diff._compare import DEGREES, rotation_angle, scaled
from robotmodel.diff._types import PoseChange
from robotmodel.kinematics import KinematicModel, batch_link_poses
from robotmodel.model import RobotDescription
from robotmodel.spatial import FloatArray, matrix_to_rpy

__all__ = ["pose_changes", "zero_poses"]


def zero_poses(desc: RobotDescription) -> dict[str, tuple[FloatArray, FloatArray]]:
    """T_root_link of every link at the zero configuration, as (rotation 3x3, translation) by name."""
    model = KinematicModel(desc)
    rotations, translations = batch_link_poses(model, np.zeros((1, model.nv)))
    return {name: (rotations[i, 0], translations[i, 0]) for i, name in enumerate(model.link_names)}


def _vec3(values: list[float]) -> tuple[float, float, float]:
    return values[0], values[1], values[2]


def pose_changes(old: RobotDescription, new: RobotDescription, links: Mapping[str, str],
                 tolerance: float) -> tuple[PoseChange, ...]:
    """Links on both sides (``links``: old name → new name) whose zero-configuration pose differs.

    Largest translation first, then largest rotation, then by name. A link has moved when
    its origins are further apart than ``tolerance`` (relative beyond 1 m) or its frames
    turned by more than ``tolerance`` radians.
    """
    before, after = zero_poses(old), zero_poses(new)
    out = []
    for old_name, new_name in links.items():
        ra, ta = before[old_name]
        rb, tb = after[new_name]
        moved = float(np.linalg.norm(tb - ta))
        turned = rotation_angle(ra, rb)
        scale = max(1.0, float(np.linalg.norm(ta)), float(np.linalg.norm(tb)))
        if moved <= tolerance * scale and turned <= tolerance:
            continue
        out.append(PoseChange(
            link=new_name, old_link=old_name,
            old_xyz=_vec3([float(v) for v in ta]), old_rpy=_vec3([float(v) for v in matrix_to_rpy(ra)]),
            new_xyz=_vec3([float(v) for v in tb]), new_rpy=_vec3([float(v) for v in matrix_to_rpy(rb)]),
            translation_mm=scaled(moved, 1000.0), rotation_deg=scaled(turned, DEGREES),
        ))
    out.sort(key=lambda c: (-c.translation_mm, -c.rotation_deg, c.link))
    return tuple(out)

