"""Rotation conversions: quaternions (x, y, z, w), 3x3 matrices and URDF/ROS roll-pitch-yaw.

URDF's ``rpy`` is roll about the fixed X axis, then pitch about fixed Y, then yaw about
fixed Z, so R = Rz(yaw) · Ry(pitch) · Rx(roll). Quaternions are in ROS message order
(x, y, z, w). Every function accepts a single value or a stack (leading dimensions
broadcast), so batch code and single lookups share one implementation.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from robotmodel.spatial._poses import poses_compose, poses_interpolate

__all__ = [
    "FloatArray",
    "matrix_to_quat",
    "matrix_to_rpy",
    "quat_multiply",
    "quat_normalize",
    "quat_to_matrix",
    "rpy_to_matrix",
    "rpy_to_quat",
    "slerp",
]

FloatArray = npt.NDArray[np.float64]


def rpy_to_matrix(rpy: npt.ArrayLike) -> FloatArray:
    """Rotation matrix R = Rz(yaw)·Ry(pitch)·Rx(roll) from ``(..., 3)`` roll, pitch, yaw."""
    a = np.asarray(rpy, dtype=np.float64)
    cr, cp, cy = np.cos(a[..., 0]), np.cos(a[..., 1]), np.cos(a[..., 2])
    sr, sp, sy = np.sin(a[..., 0]), np.sin(a[..., 1]), np.sin(a[..., 2])
    out = np.empty((*a.shape[:-1], 3, 3))
    out[..., 0, 0] = cy * cp
    out[..., 0, 1] = cy * sp * sr - sy * cr
    out[..., 0, 2] = cy * sp * cr + sy * sr
    out[..., 1, 0] = sy * cp
    out[..., 1, 1] = sy * sp * sr + cy * cr
    out[..., 1, 2] = sy * sp * cr - cy * sr
    out[..., 2, 0] = -sp
    out[..., 2, 1] = cp * sr
    out[..., 2, 2] = cp * cr
    return out


def matrix_to_rpy(matrix: npt.ArrayLike) -> FloatArray:
    """Roll, pitch, yaw (pitch in [-pi/2, pi/2]) of rotation matrices ``(..., 3, 3)``."""
    m = np.asarray(matrix, dtype=np.float64)
    pitch = np.arctan2(-m[..., 2, 0], np.hypot(m[..., 0, 0], m[..., 1, 0]))
    roll = np.arctan2(m[..., 2, 1], m[..., 2, 2])
    yaw = np.arctan2(m[..., 1, 0], m[..., 0, 0])
    # At gimbal lock roll and yaw share one axis: put it all in yaw, as tf2's getRPY does.
    locked = np.hypot(m[..., 0, 0], m[..., 1, 0]) < 1e-12
    if np.any(locked):
        roll = np.where(locked, 0.0, roll)
        yaw = np.where(locked, np.arctan2(-m[..., 0, 1], m[..., 1, 1]), yaw)
    return np.stack([roll, pitch, yaw], axis=-1)


def quat_normalize(quat: npt.ArrayLike) -> FloatArray:
    """Unit quaternions ``(..., 4)``; raises ValueError on a zero quaternion."""
    q = np.asarray(quat, dtype=np.float64)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(norm == 0.0):
        raise ValueError("zero quaternion cannot be normalized")
    result: FloatArray = q / norm
    return result


def quat_to_matrix(quat: npt.ArrayLike) -> FloatArray:
    """Rotation matrices of quaternions ``(..., 4)`` in (x, y, z, w) order (normalized first)."""
    q = quat_normalize(quat)
    x, y, z, w = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    out = np.empty((*q.shape[:-1], 3, 3))
    out[..., 0, 0] = 1 - 2 * (y * y + z * z)
    out[..., 0, 1] = 2 * (x * y - z * w)
    out[..., 0, 2] = 2 * (x * z + y * w)
    out[..., 1, 0] = 2 * (x * y + z * w)
    out[..., 1, 1] = 1 - 2 * (x * x + z * z)
    out[..., 1, 2] = 2 * (y * z - x * w)
    out[..., 2, 0] = 2 * (x * z - y * w)
    out[..., 2, 1] = 2 * (y * z + x * w)
    out[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return out


def matrix_to_quat(matrix: npt.ArrayLike) -> FloatArray:
    """Quaternions (x, y, z, w) with w >= 0 of rotation matrices ``(..., 3, 3)``."""
    m = np.asarray(matrix, dtype=np.float64)
    # Shepperd's method: pick the largest of the four candidates for numerical stability.
    t = np.stack([
        1 + m[..., 0, 0] - m[..., 1, 1] - m[..., 2, 2],
        1 - m[..., 0, 0] + m[..., 1, 1] - m[..., 2, 2],
        1 - m[..., 0, 0] - m[..., 1, 1] + m[..., 2, 2],
        1 + m[..., 0, 0] + m[..., 1, 1] + m[..., 2, 2],
    ], axis=-1)
    k = np.argmax(t, axis=-1)
    s = 0.5 / np.sqrt(np.maximum(t, 1e-300))
    xy, xz, yz = m[..., 0, 1] + m[..., 1, 0], m[..., 0, 2] + m[..., 2, 0], m[..., 1, 2] + m[..., 2, 1]
    zy, xz_, yx = m[..., 2, 1] - m[..., 1, 2], m[..., 0, 2] - m[..., 2, 0], m[..., 1, 0] - m[..., 0, 1]
    cand = np.stack([
        np.stack([t[..., 0], xy, xz, zy], -1) * s[..., 0, None],
        np.stack([xy, t[..., 1], yz, xz_], -1) * s[..., 1, None],
        np.stack([xz, yz, t[..., 2], yx], -1) * s[..., 2, None],
        np.stack([zy, xz_, yx, t[..., 3]], -1) * s[..., 3, None],
    ], axis=-2)
    q = np.take_along_axis(cand, k[..., None, None], axis=-2)[..., 0, :]
    q = np.where(q[..., 3:4] < 0, -q, q)
    return quat_normalize(q)


def rpy_to_quat(rpy: npt.ArrayLike) -> FloatArray:
    """Quaternion (x, y, z, w) of URDF roll, pitch, yaw ``(..., 3)``."""
    a = np.asarray(rpy, dtype=np.float64) / 2.0
    cr, cp, cy = np.cos(a[..., 0]), np.cos(a[..., 1]), np.cos(a[..., 2])
    sr, sp, sy = np.sin(a[..., 0]), np.sin(a[..., 1]), np.sin(a[..., 2])
    return np.stack([
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    ], axis=-1)


def _rotation_only(quat: npt.ArrayLike) -> FloatArray:
    q = np.asarray(quat, dtype=np.float64)
    return np.concatenate([np.zeros((*q.shape[:-1], 3)), q], axis=-1)


def quat_multiply(a: npt.ArrayLike, b: npt.ArrayLike) -> FloatArray:
    """Hamilton product a ⊗ b of (x, y, z, w) quaternions (rotation b first, then a).

    The rotation part of :func:`~robotmodel.spatial.poses_compose`, which it calls.
    """
    return np.ascontiguousarray(poses_compose(_rotation_only(a), _rotation_only(b))[..., 3:])


def slerp(a: npt.ArrayLike, b: npt.ArrayLike, t: npt.ArrayLike) -> FloatArray:
    """tf2's SLERP from quaternion ``a`` (t=0) to ``b`` (t=1), shortest path, not renormalized.

    The rotation part of :func:`~robotmodel.spatial.poses_interpolate`, which it calls.
    """
    return np.ascontiguousarray(poses_interpolate(_rotation_only(a), _rotation_only(b), t)[..., 3:])
