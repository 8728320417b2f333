"""Rigid transforms named by frame pair.

Convention, used everywhere in robotmodel: ``T_parent_child`` maps a point expressed in
``child`` into ``parent``: p_parent = T_parent_child · p_child. Composition chains the
names: T_a_c = T_a_b @ T_b_c.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robotmodel.spatial._pose import pose_compose, pose_inverse
from robotmodel.spatial._rotations import (
    FloatArray,
    matrix_to_quat,
    matrix_to_rpy,
    quat_to_matrix,
    rpy_to_quat,
)

__all__ = ["Transform"]

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]


@dataclass(frozen=True, slots=True)
class Transform:
    """A rigid transform: ``translation`` (x, y, z) and unit ``rotation`` quaternion (x, y, z, w)."""

    translation: Vec3 = (0.0, 0.0, 0.0)
    rotation: Quat = (0.0, 0.0, 0.0, 1.0)

    @classmethod
    def from_matrix(cls, matrix: npt.ArrayLike) -> Transform:
        """From a 4x4 homogeneous matrix."""
        m = np.asarray(matrix, dtype=np.float64)
        x, y, z = (float(v) for v in m[:3, 3])
        qx, qy, qz, qw = (float(v) for v in matrix_to_quat(m[:3, :3]))
        return cls((x, y, z), (qx, qy, qz, qw))

    @classmethod
    def from_xyz_rpy(cls, xyz: Vec3, rpy: Vec3) -> Transform:
        """From a URDF ``<origin xyz rpy>``."""
        qx, qy, qz, qw = (float(v) for v in rpy_to_quat(rpy))
        return cls(xyz, (qx, qy, qz, qw))

    def matrix(self) -> FloatArray:
        """The 4x4 homogeneous matrix."""
        out = np.eye(4)
        out[:3, :3] = quat_to_matrix(self.rotation)
        out[:3, 3] = self.translation
        return out

    def rpy(self) -> Vec3:
        """Roll, pitch, yaw of the rotation (URDF convention)."""
        r, p, y = (float(v) for v in matrix_to_rpy(quat_to_matrix(self.rotation)))
        return (r, p, y)

    def inverse(self) -> Transform:
        """T_child_parent from T_parent_child."""
        p = pose_inverse((*self.translation, *self.rotation))
        return Transform((p[0], p[1], p[2]), (p[3], p[4], p[5], p[6]))

    def __matmul__(self, other: Transform) -> Transform:
        """Compose: (T_a_b @ T_b_c) = T_a_c (the rotation renormalized)."""
        p = pose_compose((*self.translation, *self.rotation), (*other.translation, *other.rotation))
        n = math.sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6])
        return Transform((p[0], p[1], p[2]), (p[3] / n, p[4] / n, p[5] / n, p[6] / n))
