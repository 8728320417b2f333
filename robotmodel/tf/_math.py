"""tf2's transform arithmetic on plain tuples (x, y, z, qx, qy, qz, qw): fast for single lookups."""

from __future__ import annotations

import math

__all__ = ["IDENTITY", "Pose7", "canonical_quat", "compose", "inverse", "lerp_slerp"]

Pose7 = tuple[float, float, float, float, float, float, float]
IDENTITY: Pose7 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def compose(a: Pose7, b: Pose7) -> Pose7:
    """A ∘ b: apply b, then a (T_x_z = T_x_y ∘ T_y_z)."""
    ax, ay, az, qx, qy, qz, qw = a
    bx, by, bz, rx, ry, rz, rw = b
    # Rotate b's translation by a's quaternion: v + 2w(u×v) + 2u×(u×v).
    cx = qy * bz - qz * by
    cy = qz * bx - qx * bz
    cz = qx * by - qy * bx
    tx = bx + 2.0 * (qw * cx + qy * cz - qz * cy)
    ty = by + 2.0 * (qw * cy + qz * cx - qx * cz)
    tz = bz + 2.0 * (qw * cz + qx * cy - qy * cx)
    return (
        ax + tx, ay + ty, az + tz,
        qw * rx + qx * rw + qy * rz - qz * ry,
        qw * ry - qx * rz + qy * rw + qz * rx,
        qw * rz + qx * ry - qy * rx + qz * rw,
        qw * rw - qx * rx - qy * ry - qz * rz,
    )


def inverse(a: Pose7) -> Pose7:
    """The inverse transform (conjugate rotation, as tf2)."""
    x, y, z, qx, qy, qz, qw = a
    inv = (0.0, 0.0, 0.0, -qx, -qy, -qz, qw)
    rx, ry, rz = compose(inv, (x, y, z, 0.0, 0.0, 0.0, 1.0))[:3]
    return (-rx, -ry, -rz, -qx, -qy, -qz, qw)


def lerp_slerp(a: Pose7, b: Pose7, r: float) -> Pose7:
    """tf2's interpolation: linear translation, SLERP rotation (shortest path, no renormalization)."""
    qx, qy, qz, qw = a[3], a[4], a[5], a[6]
    px, py, pz, pw = b[3], b[4], b[5], b[6]
    dot = qx * px + qy * py + qz * pz + qw * pw
    theta = math.acos(max(-1.0, min(1.0, abs(dot))))
    if theta == 0.0:
        rot = (qx, qy, qz, qw)
    else:
        s = math.sin(theta)
        wa = math.sin((1.0 - r) * theta) / s
        wb = math.sin(r * theta) / s
        if dot < 0.0:
            wb = -wb
        rot = (qx * wa + px * wb, qy * wa + py * wb, qz * wa + pz * wb, qw * wa + pw * wb)
    u = 1.0 - r
    return (a[0] * u + b[0] * r, a[1] * u + b[1] * r, a[2] * u + b[2] * r, *rot)


def canonical_quat(x: float, y: float, z: float, w: float) -> tuple[float, float, float, float]:
    """The quaternion as tf2 stores and returns it: through its rotation matrix and back.

    Normalizes and picks tf2's sign (``Matrix3x3::getRotation``). Raises ValueError on NaN
    or a zero quaternion.
    """
    n2 = x * x + y * y + z * z + w * w
    if not n2 > 0.0 or math.isinf(n2):
        raise ValueError("quaternion has zero or non-finite norm")
    if w * w > 0.25 * n2 and w > 0.0:
        # Positive matrix trace: tf2's round trip returns q/|q| (up to rounding).
        inv = 1.0 / math.sqrt(n2)
        return (x * inv, y * inv, z * inv, w * inv)
    s = 2.0 / n2
    m00 = 1.0 - s * (y * y + z * z)
    m01 = s * (x * y - z * w)
    m02 = s * (x * z + y * w)
    m10 = s * (x * y + z * w)
    m11 = 1.0 - s * (x * x + z * z)
    m12 = s * (y * z - x * w)
    m20 = s * (x * z - y * w)
    m21 = s * (y * z + x * w)
    m22 = 1.0 - s * (x * x + y * y)
    trace = m00 + m11 + m22
    if trace > 0.0:
        root = math.sqrt(trace + 1.0)
        half = 0.5 / root
        return ((m21 - m12) * half, (m02 - m20) * half, (m10 - m01) * half, root * 0.5)
    m = ((m00, m01, m02), (m10, m11, m12), (m20, m21, m22))
    i = (2 if m11 < m22 else 1) if m00 < m11 else (2 if m00 < m22 else 0)
    j, k = (i + 1) % 3, (i + 2) % 3
    root = math.sqrt(m[i][i] - m[j][j] - m[k][k] + 1.0)
    q = [0.0, 0.0, 0.0, 0.0]
    q[i] = root * 0.5
    half = 0.5 / root
    q[3] = (m[k][j] - m[j][k]) * half
    q[j] = (m[j][i] + m[i][j]) * half
    q[k] = (m[k][i] + m[i][k]) * half
    return (q[0], q[1], q[2], q[3])
