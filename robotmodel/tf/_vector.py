"""Lookups at N stamps at once: the same walk as tf2, each link sampled with searchsorted.

When the tree's shape changes between the stamps (a parent switch) or some stamp has
no data, it falls back to one scalar lookup per stamp, so results and errors are
exactly those of N single lookups.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from robotmodel.spatial import IDENTITY_POSE, poses_compose, poses_interpolate, poses_inverse, quats_canonical
from robotmodel.tf._cache import StaticCache, TimeCache

if TYPE_CHECKING:
    from robotmodel.tf._core import BufferCore

__all__ = ["lookup_many"]

F = npt.NDArray[np.float64]


class _Irregular(Exception):
    """The vectorized walk cannot represent this case; use scalar lookups."""


def _snapshot(cache: TimeCache) -> tuple[npt.NDArray[np.int64], F, npt.NDArray[np.int64]]:
    snap = cache.snap
    if snap is None or snap[0] != cache.version:
        data = np.array(cache.data, dtype=np.float64).reshape(-1, 7)
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
        return np.broadcast_to(np.asarray(cache.pose, dtype=np.float64), (t.shape[0], 7)), cache.parent
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
    a, b = data[i], data[j]
    out = poses_interpolate(a, b, r)
    if equal_stamps.any():
        out = np.where(equal_stamps[:, None], b, out)
    return out, int(first)


def _walk(core: BufferCore, t: npt.NDArray[np.int64], target_id: int, source_id: int) -> F:
    caches = core._caches
    n = t.shape[0]
    index = _Index(t)
    source_acc = np.tile(np.asarray(IDENTITY_POSE), (n, 1))
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
        source_acc = poses_compose(pose, source_acc)
        frame = parent
    if frame == target_id:
        return source_acc
    target_acc = np.tile(np.asarray(IDENTITY_POSE), (n, 1))
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
            return poses_inverse(target_acc)
        target_acc = poses_compose(pose, target_acc)
        frame = parent
    if frame == source_id:
        return poses_inverse(target_acc)
    return poses_compose(poses_inverse(target_acc), source_acc)


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
        return np.ascontiguousarray(poses[:, :3]), quats_canonical(poses[:, 3:])
    except _Irregular:
        out = np.array([core._lookup_ids(target_id, source_id, int(s), target, source)[0] for s in stamps])
        return out[:, :3].copy(), out[:, 3:].copy()
