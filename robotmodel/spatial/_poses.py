"""The batched pose kernels: the same arithmetic as :mod:`._pose` on NumPy arrays.

Poses are arrays of shape ``(..., 7)`` (x, y, z, qx, qy, qz, qw), quaternions ``(..., 4)``;
leading dimensions broadcast. Results are laid out component-major (each of the 7
components contiguous, returned through ``np.moveaxis``), which is what the next kernel
in a chain reads fastest; ``np.ascontiguousarray`` gives row-major when needed.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["poses_compose", "poses_interpolate", "poses_inverse", "quats_canonical"]

F = npt.NDArray[np.float64]


def _as(a: npt.ArrayLike, width: int) -> F:
    arr = np.asarray(a, dtype=np.float64)
    if arr.shape[-1:] != (width,):
        raise ValueError(f"expected an array of shape (..., {width}), got {arr.shape}")
    return arr


def poses_compose(a: npt.ArrayLike, b: npt.ArrayLike) -> F:
    """``a ∘ b`` row by row (apply ``b``, then ``a``): the batched :func:`pose_compose`."""
    pa, pb = _as(a, 7), _as(b, 7)
    ax, ay, az, qx, qy, qz, qw = (pa[..., k] for k in range(7))
    bx, by, bz, rx, ry, rz, rw = (pb[..., k] for k in range(7))
    out = np.empty((7, *np.broadcast_shapes(pa.shape[:-1], pb.shape[:-1])))
    cx = qy * bz - qz * by
    cy = qz * bx - qx * bz
    cz = qx * by - qy * bx
    out[0] = ax + bx + 2.0 * (qw * cx + qy * cz - qz * cy)
    out[1] = ay + by + 2.0 * (qw * cy + qz * cx - qx * cz)
    out[2] = az + bz + 2.0 * (qw * cz + qx * cy - qy * cx)
    out[3] = qw * rx + qx * rw + qy * rz - qz * ry
    out[4] = qw * ry - qx * rz + qy * rw + qz * rx
    out[5] = qw * rz + qx * ry - qy * rx + qz * rw
    out[6] = qw * rw - qx * rx - qy * ry - qz * rz
    return np.moveaxis(out, 0, -1)


def poses_inverse(a: npt.ArrayLike) -> F:
    """The inverse of each pose (conjugate rotation): the batched :func:`pose_inverse`."""
    p = _as(a, 7)
    x, y, z, qx, qy, qz, qw = (p[..., k] for k in range(7))
    out = np.empty((7, *p.shape[:-1]))
    cx = qy * z - qz * y
    cy = qz * x - qx * z
    cz = qx * y - qy * x
    out[0] = -(x + 2.0 * (-qw * cx + qy * cz - qz * cy))
    out[1] = -(y + 2.0 * (-qw * cy + qz * cx - qx * cz))
    out[2] = -(z + 2.0 * (-qw * cz + qx * cy - qy * cx))
    np.negative(qx, out=out[3])
    np.negative(qy, out=out[4])
    np.negative(qz, out=out[5])
    out[6] = qw
    return np.moveaxis(out, 0, -1)


def poses_interpolate(a: npt.ArrayLike, b: npt.ArrayLike, r: npt.ArrayLike) -> F:
    """tf2's lerp + SLERP from ``a`` (r = 0) to ``b`` (r = 1): the batched :func:`pose_interpolate`."""
    pa, pb = _as(a, 7), _as(b, 7)
    frac = np.asarray(r, dtype=np.float64)
    shape = np.broadcast_shapes(pa.shape[:-1], pb.shape[:-1], frac.shape)
    u = 1.0 - frac
    qa = [pa[..., k] for k in range(3, 7)]
    qb = [pb[..., k] for k in range(3, 7)]
    dot = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3]
    theta = np.arccos(np.minimum(np.abs(dot), 1.0))
    zero = theta == 0.0
    # Where θ is 0 tf2 returns qa itself: weights (1, 0) give exactly that.
    safe = np.where(zero, 1.0, np.sin(theta))
    wa = np.where(zero, 1.0, np.sin(u * theta) / safe)
    wb = np.where(zero, 0.0, np.sin(frac * theta) / safe)
    np.negative(wb, out=wb, where=dot < 0.0)
    out = np.empty((7, *shape))
    for k in range(3):
        out[k] = pa[..., k] * u + pb[..., k] * frac
    for k in range(4):
        out[3 + k] = qa[k] * wa + qb[k] * wb
    return np.moveaxis(out, 0, -1)


def quats_canonical(q: npt.ArrayLike) -> F:
    """tf2's matrix round trip of each quaternion: the batched :func:`quat_canonical`.

    Normalized, with tf2's sign; NaN rows for zero, NaN or infinite quaternions.
    """
    quats = _as(q, 4)
    flat = quats.reshape(-1, 4)
    with np.errstate(divide="ignore", invalid="ignore"):
        n2 = np.einsum("ij,ij->i", flat, flat)
        w = flat[:, 3]
        # Positive matrix trace (4w²/|q|² - 1 > 0): tf2 returns ±q/|q| with w > 0.
        positive_trace = w * w > 0.25 * n2
        result: F = flat * np.copysign(1.0 / np.sqrt(n2), w)[:, None]
        if not positive_trace.all():
            others = ~positive_trace
            result[others] = _canonical_by_matrix(flat[others], n2[others])
        bad = ~((n2 > 0.0) & np.isfinite(n2))
        if bad.any():
            result[bad] = np.nan
    return result.reshape(quats.shape)


def _canonical_by_matrix(q: F, n2: F) -> F:
    s = 2.0 / n2
    x, y, z, w = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    m = np.empty((q.shape[0], 3, 3))
    m[:, 0, 0] = 1 - s * (y * y + z * z)
    m[:, 0, 1] = s * (x * y - z * w)
    m[:, 0, 2] = s * (x * z + y * w)
    m[:, 1, 0] = s * (x * y + z * w)
    m[:, 1, 1] = 1 - s * (x * x + z * z)
    m[:, 1, 2] = s * (y * z - x * w)
    m[:, 2, 0] = s * (x * z - y * w)
    m[:, 2, 1] = s * (y * z + x * w)
    m[:, 2, 2] = 1 - s * (x * x + y * y)
    d0, d1, d2 = m[:, 0, 0], m[:, 1, 1], m[:, 2, 2]
    trace = d0 + d1 + d2
    # tf2's choice of the largest diagonal element, ties resolved as Matrix3x3::getRotation.
    i = np.where(d0 < d1, np.where(d1 < d2, 2, 1), np.where(d0 < d2, 2, 0))
    j, k = (i + 1) % 3, (i + 2) % 3
    rows = np.arange(q.shape[0])
    root = np.sqrt(np.maximum(m[rows, i, i] - m[rows, j, j] - m[rows, k, k] + 1.0, 1e-300))
    half = 0.5 / root
    out = np.empty_like(q)
    out[rows, i] = root * 0.5
    out[rows, 3] = (m[rows, k, j] - m[rows, j, k]) * half
    out[rows, j] = (m[rows, j, i] + m[rows, i, j]) * half
    out[rows, k] = (m[rows, k, i] + m[rows, i, k]) * half
    pos_root = np.sqrt(np.maximum(trace + 1.0, 1e-300))
    pos_half = 0.5 / pos_root
    positive = np.stack([(m[:, 2, 1] - m[:, 1, 2]) * pos_half, (m[:, 0, 2] - m[:, 2, 0]) * pos_half,
                         (m[:, 1, 0] - m[:, 0, 1]) * pos_half, pos_root * 0.5], axis=1)
    result: F = np.where((trace > 0.0)[:, None], positive, out)
    return result
