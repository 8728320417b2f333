"""The batched pose kernels: the same arithmetic as :mod:`._pose` on NumPy arrays.

Poses are arrays of shape ``(..., 7)`` (x, y, z, qx, qy, qz, qw), quaternions ``(..., 4)``;
leading dimensions broadcast. Results are laid out component-major (each of the 7
components contiguous, returned through ``np.moveaxis``), which is what the next kernel
in a chain reads fastest; ``np.ascontiguousarray`` gives row-major when needed.
"""

from __future__ import annotations

import math

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


# Taylor coefficients of sin(x)/x in x²: up to x^22 the remainder on [0, π/2] is < 1e-18.
_SIN_COEFFS = [(-1.0) ** k / math.factorial(2 * k + 1) for k in range(11, -1, -1)]


def _sin_quarter_turn(x: F) -> F:
    """sin(x) for x in [0, π/2] (Horner in x², full double precision)."""
    x2 = x * x
    acc = np.full_like(x2, _SIN_COEFFS[0])
    for c in _SIN_COEFFS[1:]:
        acc *= x2
        acc += c
    acc *= x
    return acc


def poses_interpolate(a: npt.ArrayLike, b: npt.ArrayLike, r: npt.ArrayLike) -> F:
    """tf2's lerp + SLERP from ``a`` (r = 0) to ``b`` (r = 1): the batched :func:`pose_interpolate`."""
    pa, pb = _as(a, 7), _as(b, 7)
    frac = np.asarray(r, dtype=np.float64)
    shape = np.broadcast_shapes(pa.shape[:-1], pb.shape[:-1], frac.shape)
    if not shape:  # one pose: as a batch of one, so every step below works on arrays
        one: F = poses_interpolate(pa.reshape(1, 7), pb.reshape(1, 7), frac.reshape(1))[0]
        return one
    u = 1.0 - frac
    qa = [pa[..., k] for k in range(3, 7)]
    qb = [pb[..., k] for k in range(3, 7)]
    dot = qa[0] * qb[0]
    for k in range(1, 4):
        dot += qa[k] * qb[k]
    cos_theta = np.minimum(np.abs(dot), 1.0)
    theta = np.arccos(cos_theta)
    # NumPy's float64 sin is a scalar libm loop (~30x its arccos); θ, rθ and (1-r)θ lie in
    # [0, π/2] here, where a full-precision polynomial is exact to a few ulp and much faster.
    sine = _sin_quarter_turn if bool(((frac >= 0.0) & (frac <= 1.0)).all()) else np.sin
    with np.errstate(divide="ignore", invalid="ignore"):  # θ = 0 rows are replaced below
        sin_theta = sine(theta)
        wa = sine(u * theta)
        wa /= sin_theta
        wb = sine(frac * theta)
        wb /= sin_theta
    zero = theta == 0.0
    if zero.any():
        # Where θ is 0 tf2 returns qa itself: weights (1, 0) give exactly that.
        wa = np.where(zero, 1.0, wa)
        wb = np.where(zero, 0.0, wb)
    np.negative(wb, out=wb, where=dot < 0.0)
    out = np.empty((7, *shape))
    for k in range(3):
        np.multiply(pa[..., k], u, out=out[k])
        out[k] += pb[..., k] * frac
    for k in range(4):
        np.multiply(qa[k], wa, out=out[3 + k])
        out[3 + k] += qb[k] * wb
    return np.moveaxis(out, 0, -1)


def quats_canonical(q: npt.ArrayLike) -> F:
    """tf2's matrix round trip of each quaternion: the batched :func:`quat_canonical`.

    ±q/|q| with tf2's sign (branch decisions on the diagonal computed in tf2's operation
    order); NaN rows for zero, NaN or infinite quaternions.
    """
    quats = _as(q, 4)
    x, y, z, w = (quats[..., k] for k in range(4))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        n2 = x * x + y * y + z * z + w * w
        s = 2.0 / n2
        xx, yy, zz = x * (x * s), y * (y * s), z * (z * s)
        m00, m11, m22 = 1.0 - (yy + zz), 1.0 - (xx + zz), 1.0 - (xx + yy)
        # tf2's getRotation: w > 0 on a positive trace, else the largest diagonal's component > 0.
        lead = np.where(m00 < m11, np.where(m11 < m22, z, y), np.where(m00 < m22, z, x))
        lead = np.where(m00 + m11 + m22 > 0.0, w, lead)
        inv = np.copysign(1.0 / np.sqrt(n2), lead)
        out = np.empty((4, *quats.shape[:-1]))
        for k, c in enumerate((x, y, z, w)):
            np.multiply(c, inv, out=out[k])
        bad = ~((n2 > 0.0) & np.isfinite(n2) & np.isfinite(s))
        if bad.any():
            out[:, bad] = np.nan
    return np.moveaxis(out, 0, -1)
