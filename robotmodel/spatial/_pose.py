"""The scalar pose kernels: tf2's arithmetic on plain 7-tuples (x, y, z, qx, qy, qz, qw).

These are the only scalar copies of composition, inversion, interpolation and tf2's
canonical quaternion in robotmodel; the TF buffer, kinematics and model call them, and
the property tests check them. Plain floats and tuples, because a single lookup of a
few links is faster without NumPy's per-call overhead.
"""

from __future__ import annotations

import math
from math import acos as _acos
from math import copysign as _copysign
from math import sin as _sin
from math import sqrt as _sqrt

__all__ = ["IDENTITY_POSE", "Pose7", "Quat", "pose_compose", "pose_interpolate", "pose_inverse", "quat_canonical"]

#: A rigid transform as (x, y, z, qx, qy, qz, qw): translation, then a quaternion in ROS order.
Pose7 = tuple[float, float, float, float, float, float, float]
#: A quaternion in ROS order (x, y, z, w).
Quat = tuple[float, float, float, float]

#: The identity transform.
IDENTITY_POSE: Pose7 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)

_INF = math.inf
_NAN4: Quat = (math.nan, math.nan, math.nan, math.nan)


def pose_compose(a: Pose7, b: Pose7) -> Pose7:
    """``a ∘ b``: apply ``b``, then ``a`` (T_x_z = T_x_y ∘ T_y_z), with tf2's Hamilton product.

    The quaternion is not renormalized, as in tf2's accumulation along a chain.
    """
    ax, ay, az, qx, qy, qz, qw = a
    bx, by, bz, rx, ry, rz, rw = b
    # Rotate b's translation by a's quaternion: v + 2w(u×v) + 2u×(u×v).
    cx = qy * bz - qz * by
    cy = qz * bx - qx * bz
    cz = qx * by - qy * bx
    return (
        ax + bx + 2.0 * (qw * cx + qy * cz - qz * cy),
        ay + by + 2.0 * (qw * cy + qz * cx - qx * cz),
        az + bz + 2.0 * (qw * cz + qx * cy - qy * cx),
        qw * rx + qx * rw + qy * rz - qz * ry,
        qw * ry - qx * rz + qy * rw + qz * rx,
        qw * rz + qx * ry - qy * rx + qz * rw,
        qw * rw - qx * rx - qy * ry - qz * rz,
    )


def pose_inverse(a: Pose7) -> Pose7:
    """The inverse transform; the rotation is the conjugate, as tf2's inverse."""
    x, y, z, qx, qy, qz, qw = a
    # Rotate (x, y, z) by the conjugate (-u, w): v - 2w(u×v) + 2u×(u×v), then negate.
    cx = qy * z - qz * y
    cy = qz * x - qx * z
    cz = qx * y - qy * x
    return (
        -(x + 2.0 * (-qw * cx + qy * cz - qz * cy)),
        -(y + 2.0 * (-qw * cy + qz * cx - qx * cz)),
        -(z + 2.0 * (-qw * cz + qx * cy - qy * cx)),
        -qx, -qy, -qz, qw,
    )


def pose_interpolate(a: Pose7, b: Pose7, r: float) -> Pose7:
    """tf2's interpolation from ``a`` (r = 0) to ``b`` (r = 1).

    Translation: ``(1-r)·a + r·b``. Rotation: tf2's SLERP — ``θ = acos(|qa·qb|)``
    (clamped), ``qa`` unchanged when θ is 0, the shortest arc (``qb`` negated when the dot
    product is negative), no renormalization afterwards.
    """
    ax, ay, az, qx, qy, qz, qw = a
    bx, by, bz, px, py, pz, pw = b
    u = 1.0 - r
    dot = qx * px + qy * py + qz * pz + qw * pw
    theta = _acos(dot if 0.0 <= dot <= 1.0 else min(1.0, abs(dot)))
    if theta == 0.0:
        return (ax * u + bx * r, ay * u + by * r, az * u + bz * r, qx, qy, qz, qw)
    s = _sin(theta)
    wa = _sin(u * theta) / s
    wb = _sin(r * theta) / s
    if dot < 0.0:
        wb = -wb
    return (ax * u + bx * r, ay * u + by * r, az * u + bz * r,
            qx * wa + px * wb, qy * wa + py * wb, qz * wa + pz * wb, qw * wa + pw * wb)


def quat_canonical(q: Quat) -> Quat:
    """The quaternion as tf2 stores and returns it: through its rotation matrix and back.

    tf2 (``Matrix3x3::setRotation`` then ``getRotation``) returns the rotation of q/|q| with
    w > 0 when the matrix trace is positive, else with a positive component along the
    largest diagonal element (ties resolved as tf2 does). The diagonal is computed with
    tf2's own operation order, so every branch decision matches tf2's; the value is
    ±q/|q|. A zero, NaN or infinite quaternion gives NaN in every component, as tf2's
    round trip does.
    """
    x, y, z, w = q
    n2 = x * x + y * y + z * z + w * w
    # Zero, NaN or infinite norm, or one so small that 2/|q|^2 overflows: tf2's matrix then
    # holds inf - inf and its round trip gives NaN. (Comparisons, not isinf/isnan calls: this
    # runs on every lookup.)
    if not 0.0 < n2 < _INF:
        return _NAN4
    s = 2.0 / n2
    if s == _INF:
        return _NAN4
    xx, yy, zz = x * (x * s), y * (y * s), z * (z * s)
    m00, m11, m22 = 1.0 - (yy + zz), 1.0 - (xx + zz), 1.0 - (xx + yy)
    if m00 + m11 + m22 > 0.0:
        lead = w
    elif m00 < m11:
        lead = z if m11 < m22 else y
    else:
        lead = z if m00 < m22 else x
    inv = _copysign(1.0 / _sqrt(n2), lead)
    return (x * inv, y * inv, z * inv, w * inv)
