"""Rotations and rigid transforms (quaternions in ROS's x, y, z, w order; URDF rpy).

``T_parent_child`` maps points in ``child`` into ``parent``; see :class:`Transform`.
"""

from __future__ import annotations

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
    "FloatArray",
    "Transform",
    "matrix_to_quat",
    "matrix_to_rpy",
    "quat_multiply",
    "quat_normalize",
    "quat_to_matrix",
    "rpy_to_matrix",
    "rpy_to_quat",
    "slerp",
]
