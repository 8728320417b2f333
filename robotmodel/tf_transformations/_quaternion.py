"""Quaternions (x, y, z, w) as ROS's transformations module handles them, on robotmodel.spatial's kernels."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from robotmodel.spatial import FloatArray, matrix_to_quat, quat_multiply, quat_to_matrix

__all__ = [
    "quaternion_about_axis",
    "quaternion_conjugate",
    "quaternion_from_matrix",
    "quaternion_inverse",
    "quaternion_matrix",
    "quaternion_multiply",
    "quaternion_slerp",
    "random_quaternion",
    "random_rotation_matrix",
]

_EPS = float(np.finfo(float).eps) * 4.0


def _quat(q: npt.ArrayLike) -> FloatArray:
    a = np.asarray(q, dtype=np.float64)
    if a.shape != (4,):
        raise ValueError(f"a quaternion has 4 elements (x, y, z, w), got shape {a.shape}")
    return a


def quaternion_matrix(quaternion: npt.ArrayLike) -> FloatArray:
    """4x4 homogeneous rotation of a quaternion (x, y, z, w), normalized first; identity for a ~zero one."""
    q = _quat(quaternion)
    m = np.eye(4)
    if float(np.dot(q, q)) < _EPS:
        return m
    m[:3, :3] = quat_to_matrix(q)
    return m


def quaternion_from_matrix(matrix: npt.ArrayLike) -> FloatArray:
    """Quaternion (x, y, z, w), w >= 0, of the rotation part of a 3x3 or 4x4 matrix."""
    m = np.asarray(matrix, dtype=np.float64)
    return np.asarray(matrix_to_quat(m[:3, :3]), dtype=np.float64)


def quaternion_about_axis(angle: float, axis: npt.ArrayLike) -> FloatArray:
    """Quaternion of a rotation by ``angle`` about ``axis`` (normalized)."""
    a = np.asarray(axis, dtype=np.float64)
    n = float(np.linalg.norm(a))
    if n == 0.0:
        raise ValueError("rotation axis must not be zero")
    q = np.empty(4)
    q[:3] = a / n * math.sin(angle / 2.0)
    q[3] = math.cos(angle / 2.0)
    return q


def quaternion_multiply(quaternion1: npt.ArrayLike, quaternion0: npt.ArrayLike) -> FloatArray:
    """Hamilton product ``quaternion1 ⊗ quaternion0`` (rotate by quaternion0 first, then quaternion1)."""
    return np.asarray(quat_multiply(_quat(quaternion1), _quat(quaternion0)), dtype=np.float64)


def quaternion_conjugate(quaternion: npt.ArrayLike) -> FloatArray:
    """(-x, -y, -z, w)."""
    q = _quat(quaternion)
    return np.array([-q[0], -q[1], -q[2], q[3]])


def quaternion_inverse(quaternion: npt.ArrayLike) -> FloatArray:
    """The conjugate divided by the squared norm (so non-unit quaternions invert too)."""
    q = _quat(quaternion)
    result: FloatArray = quaternion_conjugate(q) / float(np.dot(q, q))
    return result


def quaternion_slerp(quat0: npt.ArrayLike, quat1: npt.ArrayLike, fraction: float, spin: int = 0,
                     shortestpath: bool = True) -> FloatArray:
    """Spherical linear interpolation from ``quat0`` (fraction 0) to ``quat1`` (fraction 1).

    Both are normalized first. ``shortestpath`` flips ``quat1`` when the two are more than
    half a turn apart; ``spin`` adds that many extra half turns.
    """
    q0 = _quat(quat0) / float(np.linalg.norm(quat0))
    q1 = _quat(quat1) / float(np.linalg.norm(quat1))
    if fraction == 0.0:
        return q0
    if fraction == 1.0:
        return q1
    d = float(np.dot(q0, q1))
    if abs(abs(d) - 1.0) < _EPS:
        return q0
    if shortestpath and d < 0.0:
        d, q1 = -d, -q1
    angle = math.acos(max(-1.0, min(1.0, d))) + spin * math.pi
    if abs(angle) < _EPS:
        return q0
    s = math.sin(angle)
    result: FloatArray = (math.sin((1.0 - fraction) * angle) * q0 + math.sin(fraction * angle) * q1) / s
    return result


def random_quaternion(rand: npt.ArrayLike | None = None) -> FloatArray:
    """A uniformly distributed unit quaternion; ``rand`` gives the three uniform [0, 1) draws."""
    u = np.random.default_rng().random(3) if rand is None else np.asarray(rand, dtype=np.float64)
    if u.shape != (3,):
        raise ValueError(f"rand must hold 3 numbers, got shape {u.shape}")
    # Shoemake's subgroup method: two circles whose radii split the unit 4-sphere.
    r1, r2 = math.sqrt(1.0 - u[0]), math.sqrt(u[0])
    t1, t2 = 2.0 * math.pi * u[1], 2.0 * math.pi * u[2]
    return np.array([math.sin(t1) * r1, math.cos(t1) * r1, math.sin(t2) * r2, math.cos(t2) * r2])


def random_rotation_matrix(rand: npt.ArrayLike | None = None) -> FloatArray:
    """A uniformly distributed 4x4 homogeneous rotation (see :func:`random_quaternion`)."""
    return quaternion_matrix(random_quaternion(rand))
