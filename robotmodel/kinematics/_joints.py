"""Per-joint tables and the vectorized local transform of every joint (parent link → child link).

A joint's transform is T_parent_child(q) = T_origin · M(q), where M is a rotation about
the unit axis (revolute, continuous) or a translation along it (prismatic). This is what
robot_state_publisher publishes per joint; the same tables drive batch FK.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from robotmodel.model import JointType, RobotDescription
from robotmodel.spatial import FloatArray, rpy_to_matrix

__all__ = ["JointTable", "local_transforms", "unit_axis"]

# Joint kinds in the tables; planar and floating count as fixed here, as robot_state_publisher does.
KIND_FIXED, KIND_REVOLUTE, KIND_PRISMATIC = 0, 1, 2


def unit_axis(axis: tuple[float, float, float]) -> FloatArray:
    """``axis`` scaled to unit length, as KDL and Pinocchio use it (yourdfpy does not, for prismatic).

    Divided by its largest component first, so neither a tiny axis (1e-300: its squared
    norm underflows to 0) nor a huge one (1e300: overflows) loses its direction.
    """
    v = np.asarray(axis, dtype=np.float64)
    v = v / np.max(np.abs(v))
    unit: FloatArray = v / np.linalg.norm(v)
    return unit


@dataclass(frozen=True)
class JointTable:
    """Every joint of a robot as arrays, in document order (index = position in ``names``)."""

    names: tuple[str, ...]
    parents: tuple[str, ...]
    children: tuple[str, ...]
    kinds: FloatArray  # (J,) of KIND_*
    origin_rotation: FloatArray  # (J, 3, 3)
    origin_translation: FloatArray  # (J, 3)
    axis: FloatArray  # (J, 3) unit axes (zero for fixed)

    @classmethod
    def from_description(cls, desc: RobotDescription) -> JointTable:
        """Build the tables from a description."""
        joints = desc.joints
        kinds = np.zeros(len(joints))
        axes = np.zeros((len(joints), 3))
        for i, joint in enumerate(joints):
            if joint.type in (JointType.REVOLUTE, JointType.CONTINUOUS):
                kinds[i] = KIND_REVOLUTE
            elif joint.type is JointType.PRISMATIC:
                kinds[i] = KIND_PRISMATIC
            if kinds[i] != KIND_FIXED:
                axes[i] = unit_axis(joint.axis)
        return cls(
            names=tuple(j.name for j in joints),
            parents=tuple(j.parent for j in joints),
            children=tuple(j.child for j in joints),
            kinds=kinds,
            origin_rotation=rpy_to_matrix(np.array([j.origin.rpy for j in joints]).reshape(-1, 3)),
            origin_translation=np.array([j.origin.xyz for j in joints], dtype=np.float64).reshape(-1, 3),
            axis=axes,
        )


def local_transforms(table: JointTable, values: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Rotations ``(..., J, 3, 3)`` and translations ``(..., J, 3)`` of every joint.

    ``values`` is ``(..., J)``: each joint's position (ignored for fixed joints).
    """
    q = np.asarray(values, dtype=np.float64)
    revolute = table.kinds == KIND_REVOLUTE
    angle = np.where(revolute, q, 0.0)
    shift = np.where(table.kinds == KIND_PRISMATIC, q, 0.0)
    # Rodrigues: R = I + sin θ K + (1 - cos θ) K², K the cross-product matrix of the axis.
    x, y, z = table.axis[:, 0], table.axis[:, 1], table.axis[:, 2]
    s, c = np.sin(angle), 1.0 - np.cos(angle)
    motion = np.empty((*q.shape, 3, 3))
    motion[..., 0, 0] = 1 - c * (y * y + z * z)
    motion[..., 0, 1] = -s * z + c * x * y
    motion[..., 0, 2] = s * y + c * x * z
    motion[..., 1, 0] = s * z + c * x * y
    motion[..., 1, 1] = 1 - c * (x * x + z * z)
    motion[..., 1, 2] = -s * x + c * y * z
    motion[..., 2, 0] = -s * y + c * x * z
    motion[..., 2, 1] = s * x + c * y * z
    motion[..., 2, 2] = 1 - c * (x * x + y * y)
    rotation = table.origin_rotation @ motion
    translation = table.origin_translation + np.einsum("jab,...jb->...ja", table.origin_rotation,
                                                       shift[..., None] * table.axis)
    return rotation, translation
