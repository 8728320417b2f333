"""Euler angles in any of the 24 axis sequences, to and from matrices and quaternions.

A static sequence (a, b, c) with angles (ai, aj, ak) is R = R_c(ak) · R_b(aj) · R_a(ai):
ai about the first fixed axis, then aj, then ak. ``'sxyz'`` is therefore URDF's and
tf2's roll-pitch-yaw. A rotating sequence is the static one with the letters and the
first and last angles swapped.

Extraction works in a relabelled frame where the sequence reads x, y, z (or x, y, x):
relabelling the axes by an odd permutation turns every rotation into its reverse, so
those sequences get their angles negated. At gimbal lock the last static angle is 0 and
the first takes the whole turn, as ROS's transformations module does.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from robotmodel.spatial import FloatArray, quat_multiply
from robotmodel.tf_transformations._axes import parse_axes
from robotmodel.tf_transformations._quaternion import quaternion_matrix

__all__ = ["euler_from_matrix", "euler_from_quaternion", "euler_matrix", "quaternion_from_euler"]

# Below this a cosine counts as zero (gimbal lock): four machine epsilons, as ROS's module.
_EPS = float(np.finfo(float).eps) * 4.0


def _axis_rotation(axis: int, angle: float) -> FloatArray:
    c, s = math.cos(angle), math.sin(angle)
    m = np.eye(3)
    u, v = (axis + 1) % 3, (axis + 2) % 3
    m[u, u] = c
    m[v, v] = c
    m[u, v] = -s
    m[v, u] = s
    return m


def _axis_quaternion(axis: int, angle: float) -> FloatArray:
    q = np.zeros(4)
    q[axis] = math.sin(angle / 2.0)
    q[3] = math.cos(angle / 2.0)
    return q


def _static_order(ai: float, aj: float, ak: float, axes: str | tuple[int, int, int, int]
                  ) -> tuple[tuple[int, int, int], tuple[float, float, float]]:
    seq = parse_axes(axes)
    angles = (ak, aj, ai) if seq.rotating else (ai, aj, ak)
    return (seq.first, seq.second, seq.third), angles


def euler_matrix(ai: float, aj: float, ak: float, axes: str | tuple[int, int, int, int] = "sxyz") -> FloatArray:
    """4x4 homogeneous rotation of Euler angles ``ai, aj, ak`` in sequence ``axes`` (default ``'sxyz'``)."""
    order, angles = _static_order(float(ai), float(aj), float(ak), axes)
    r = _axis_rotation(order[2], angles[2]) @ _axis_rotation(order[1], angles[1]) @ _axis_rotation(
        order[0], angles[0])
    m = np.eye(4)
    m[:3, :3] = r
    return m


def quaternion_from_euler(ai: float, aj: float, ak: float,
                          axes: str | tuple[int, int, int, int] = "sxyz") -> FloatArray:
    """Quaternion (x, y, z, w) of Euler angles in sequence ``axes`` (default ``'sxyz'``: roll, pitch, yaw)."""
    order, angles = _static_order(float(ai), float(aj), float(ak), axes)
    q = quat_multiply(_axis_quaternion(order[2], angles[2]),
                      quat_multiply(_axis_quaternion(order[1], angles[1]), _axis_quaternion(order[0], angles[0])))
    return np.asarray(q, dtype=np.float64)


def euler_from_matrix(matrix: npt.ArrayLike, axes: str | tuple[int, int, int, int] = "sxyz"
                      ) -> tuple[float, float, float]:
    """Euler angles ``(ai, aj, ak)`` of a rotation (3x3 or 4x4 matrix) in sequence ``axes``.

    Many triplets describe one rotation; the one returned has the middle angle in
    [-pi/2, pi/2] (three distinct axes) or [0, pi] (first axis repeated).
    """
    seq = parse_axes(axes)
    m = np.asarray(matrix, dtype=np.float64)[:3, :3]
    first, second = seq.first, seq.second
    third = 3 - first - second  # the axis the sequence does not name twice
    perm = [first, second, third]
    r = m[np.ix_(perm, perm)]
    odd = second != (first + 1) % 3
    if seq.third == seq.first:
        s = math.hypot(r[0, 1], r[0, 2])
        if s > _EPS:
            a, b, c = math.atan2(r[0, 1], r[0, 2]), math.atan2(s, r[0, 0]), math.atan2(r[1, 0], -r[2, 0])
        else:
            a, b, c = math.atan2(-r[1, 2], r[1, 1]), math.atan2(s, r[0, 0]), 0.0
    else:
        cb = math.hypot(r[0, 0], r[1, 0])
        if cb > _EPS:
            a, b, c = math.atan2(r[2, 1], r[2, 2]), math.atan2(-r[2, 0], cb), math.atan2(r[1, 0], r[0, 0])
        else:
            a, b, c = math.atan2(-r[1, 2], r[1, 1]), math.atan2(-r[2, 0], cb), 0.0
    if odd:
        a, b, c = -a, -b, -c
    if seq.rotating:
        a, c = c, a
    return a, b, c


def euler_from_quaternion(quaternion: npt.ArrayLike, axes: str | tuple[int, int, int, int] = "sxyz"
                          ) -> tuple[float, float, float]:
    """Euler angles of a quaternion (x, y, z, w) in sequence ``axes`` (default ``'sxyz'``: roll, pitch, yaw)."""
    return euler_from_matrix(quaternion_matrix(quaternion), axes)
