"""Lookups at N stamps at once: the same walk as tf2, each link sampled with searchsorted.

When the tree's shape changes between the stamps (a parent switch) or some stamp has
no data, it falls back to one scalar lookup per stamp, so results and errors are
exactly those of N single lookups.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from robotmodel.tf._cache import StaticCache, TimeCache
from robotmodel.tf._math import IDENTITY

if TYPE_CHECKING:
    from robotmodel.tf._core import BufferCore

__all__ = ["lookup_many"]

F = npt.NDArray[np.float64]


class _Irregular(Exception):
    """The vectorized walk cannot represent this case; use scalar lookups."""


def _compose(a: F, b: F) -> F:
    ax, ay, az, qx, qy, qz, qw = a
    bx, by, bz, rx, ry, rz, rw = b
    cx, cy, cz = qy * bz - qz * by, qz * bx - qx * bz, qx * by - qy * bx
    return np.array([
        ax + bx + 2.0 * (qw * cx + qy * cz - qz * cy),
        ay + by + 2.0 * (qw * cy + qz * cx - qx * cz),
        az + bz + 2.0 * (qw * cz + qx * cy - qy * cx),
        qw * rx + qx * rw + qy * rz - qz * ry,
        qw * ry - qx * rz + qy * rw + qz * rx,
        qw * rz + qx * ry - qy * rx + qz * rw,
        qw * rw - qx * rx - qy * ry - qz * rz,
    ])


def _inverse(a: F) -> F:
    inv = np.zeros_like(a)
    inv[3:6] = -a[3:6]
    inv[6] = a[6]
    point = np.zeros_like(a)
    point[:3] = a[:3]
    point[6] = 1.0
    inv[:3] = -_compose(inv, point)[:3]
    return inv


def _snapshot(cache: TimeCache) -> tuple[npt.NDArray[np.int64], F, npt.NDArray[np.int64]]:
    snap = cache.snap
    if snap is None or snap[0] != cache.version:
        # Column-major (7, n): gathering one column at a time is much cheaper than rows.
        data = np.ascontiguousarray(np.array(cache.data, dtype=np.float64).reshape(-1, 7).T)
        snap = (cache.version, np.array(cache.stamps, dtype=np.int64), data, np.array(cache.parents, dtype=np.int64))
        cache.snap = snap
    return snap[1], snap[2], snap[3]


class _Index:
    """searchsorted results shared by links whose caches hold the same stamps (published together)."""

    def __init__(self, t: npt.NDArray[np.int64]) -> None:
        self.t = t
        self.stamps: npt.NDArray[np.int64] | None = None
        self.i: npt.NDArray[np.intp] | None = None
        self.j: npt.NDArray[np.intp] | None = None
        self.r: F | None = None

    def lookup(self, stamps: npt.NDArray[np.int64]) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], F]:
        if self.stamps is None or not np.array_equal(self.stamps, stamps):
            n = stamps.shape[0]
            i = np.searchsorted(stamps, self.t, side="right") - 1
            j = np.minimum(i + 1, n - 1)
            t0, t1 = stamps[i], stamps[j]
            span = (t1 - t0).astype(np.float64)
            # r = 0 where there is no newer neighbour (exactly on the newest sample).
            self.r = np.divide((self.t - t0).astype(np.float64), span, out=np.zeros(span.shape), where=span > 0)
            self.stamps, self.i, self.j = stamps, i, j
        assert self.i is not None and self.j is not None and self.r is not None
        return self.i, self.j, self.r


def _sample(cache: TimeCache | StaticCache, index: _Index) -> tuple[F, int]:
    t = index.t
    if isinstance(cache, StaticCache):
        return np.broadcast_to(np.asarray(cache.pose, dtype=np.float64)[:, None], (7, t.shape[0])), cache.parent
    stamps, data, parents = _snapshot(cache)
    n = stamps.shape[0]
    if n < 2 or t.min() < stamps[0] or t.max() > stamps[-1]:
        raise _Irregular
    i, j, r = index.lookup(stamps)
    first = parents[i[0]]
    if np.any(parents[i] != first) or np.any(parents[j] != first):
        raise _Irregular  # a parent switch inside the span: scalar walk picks per stamp
    # Equal stamps (a repeated sample) take the newer one, as tf2.
    equal_stamps = (stamps[j] == stamps[i]) & (i != j)
    a = [data[k][i] for k in range(7)]
    b = [data[k][j] for k in range(7)]
    u = 1.0 - r
    dot = a[3] * b[3] + a[4] * b[4] + a[5] * b[5] + a[6] * b[6]
    theta = np.arccos(np.minimum(np.abs(dot), 1.0))
    sin_t = np.sin(theta)
    zero = theta == 0.0
    safe = np.where(zero, 1.0, sin_t)
    wa = np.where(zero, 1.0, np.sin(u * theta) / safe)
    wb = np.where(zero, 0.0, np.sin(r * theta) / safe)
    np.negative(wb, out=wb, where=dot < 0.0)
    out = np.empty((7, t.shape[0]))
    for k in range(3):
        out[k] = a[k] * u + b[k] * r
    for k in range(3, 7):
        out[k] = a[k] * wa + b[k] * wb
    if equal_stamps.any():
        for k in range(7):
            out[k] = np.where(equal_stamps, b[k], out[k])
    return out, int(first)


def _canonical(q: F) -> F:
    """tf2's matrix round trip of each quaternion (normalize, tf2's sign choice)."""
    n2 = np.einsum("ij,ij->i", q, q)
    w = q[:, 3]
    positive_trace = w * w > 0.25 * n2
    if positive_trace.all():
        # tf2's positive-trace branch returns q/|q| with w > 0.
        scale: F = np.copysign(1.0 / np.sqrt(n2), w)
        return q * scale[:, None]
    result: F = q * np.copysign(1.0 / np.sqrt(n2), w)[:, None]
    others = ~positive_trace
    result[others] = _canonical_full(q[others])
    return result


def _canonical_full(q: F) -> F:
    n2 = np.sum(q * q, axis=1)
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


def _walk(core: BufferCore, t: npt.NDArray[np.int64], target_id: int, source_id: int) -> F:
    caches = core._caches
    n = t.shape[0]
    index = _Index(t)
    source_acc = np.tile(np.asarray(IDENTITY)[:, None], (1, n))
    frame, top = source_id, 0
    chain = set()
    while frame:
        if frame in chain:
            raise _Irregular  # a loop: the scalar walk reports it
        chain.add(frame)
        cache = caches[frame]
        top = frame
        if cache is None or frame == target_id:
            if cache is not None:
                _sample(cache, index)  # tf2 samples the target's own link: a miss must surface
            break
        pose, parent = _sample(cache, index)
        source_acc = _compose(pose, source_acc)
        frame = parent
    if frame == target_id:
        return source_acc
    target_acc = np.tile(np.asarray(IDENTITY)[:, None], (1, n))
    frame = target_id
    seen = set()
    while frame != top:
        if frame in seen:
            raise _Irregular
        seen.add(frame)
        cache = caches[frame]
        if cache is None:
            raise _Irregular  # not connected: the scalar walk builds the message
        pose, parent = _sample(cache, index)
        if frame == source_id:
            return _inverse(target_acc)
        target_acc = _compose(pose, target_acc)
        frame = parent
    if frame == source_id:
        return _inverse(target_acc)
    return _compose(_inverse(target_acc), source_acc)


def lookup_many(core: BufferCore, target: str, source: str,
                stamps: npt.NDArray[np.int64]) -> tuple[F, F]:
    """Translations ``(N, 3)`` and quaternions ``(N, 4)`` of T_target_source at each stamp."""
    n = stamps.shape[0]
    if n == 0:
        return np.zeros((0, 3)), np.zeros((0, 4))
    if target == source:
        return np.zeros((n, 3)), np.tile([0.0, 0.0, 0.0, 1.0], (n, 1))
    target_id = core._validate(target, "lookupTransform argument target_frame")
    source_id = core._validate(source, "lookupTransform argument source_frame")
    if np.any(stamps == 0):
        latest = core._latest_common_time(target_id, source_id, target, source)
        stamps = np.where(stamps == 0, latest, stamps)
    try:
        poses = _walk(core, stamps, target_id, source_id)
        return np.ascontiguousarray(poses[:3].T), _canonical(np.ascontiguousarray(poses[3:].T))
    except _Irregular:
        out = np.array([core._lookup_ids(target_id, source_id, int(s), target, source)[0] for s in stamps])
        return out[:, :3].copy(), out[:, 3:].copy()
