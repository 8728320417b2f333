"""Rotations and rigid transforms (quaternions in ROS's x, y, z, w order; URDF rpy).

``T_parent_child`` maps points in ``child`` into ``parent``; see :class:`Transform`.

The pose kernels are the one copy of tf2's transform arithmetic in robotmodel, in two
forms with the same semantics:

- scalar, on 7-tuples ``(x, y, z, qx, qy, qz, qw)``: :func:`pose_compose`,
  :func:`pose_inverse`, :func:`pose_interpolate` (tf2's lerp + SLERP) and
  :func:`quat_canonical` (tf2's matrix round trip: normalized, tf2's sign);
- batched, on arrays ``(..., 7)`` / ``(..., 4)``: :func:`poses_compose`,
  :func:`poses_inverse`, :func:`poses_interpolate`, :func:`quats_canonical`.
"""

from __future__ import annotations

from robotmodel.spatial._pose import (
    IDENTITY_POSE,
    Pose7,
    Quat,
    pose_compose,
    pose_interpolate,
    pose_inverse,
    quat_canonical,
)
from robotmodel.spatial._poses import poses_compose, poses_interpolate, poses_inverse, quats_canonical
from robotmodel.spatial._rotations import (
    FloatArray,
    matrix_to_quat,
    matrix_to_rpy,
    quat_multiply,
    quat_normalize,
    quat_to_matrix,
    rpy_to_matrix,
    rpy_to_quat,
    slerp,
)
from robotmodel.spatial._transform import Transform

__all__ = [
    "IDENTITY_POSE",
    "FloatArray",
    "Pose7",
    "Quat",
    "Transform",
    "matrix_to_quat",
    "matrix_to_rpy",
    "pose_compose",
    "pose_interpolate",
    "pose_inverse",
    "poses_compose",
    "poses_interpolate",
    "poses_inverse",
    "quat_canonical",
    "quat_multiply",
    "quat_normalize",
    "quat_to_matrix",
    "quats_canonical",
    "rpy_to_matrix",
    "rpy_to_quat",
    "slerp",
]
