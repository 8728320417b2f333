"""Lookups at N stamps at once: the same walk as tf2, each link sampled with searchsorted.

Each link reads its cache's arrays through zero-copy views and is interpolated by the
batched kernels of :mod:`robotmodel.spatial` (the same arithmetic as the scalar path).
When the tree's shape changes between the stamps (a parent switch), some stamp has no
data, or there are only a few stamps, it runs one scalar lookup per stamp, so results
and errors are exactly those of N single lookups.
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
I64 = npt.NDArray[np.int64]
_CHUNK = 16384
_SCALAR_BELOW = 4  # fewer stamps than this: scalar lookups are faster than NumPy's per-call cost


class _Irregular(Exception):
    """The vectorized walk cannot represent this case; use scalar lookups."""


class _Index:
    """searchsorted results shared by links whose caches hold the same stamps (published together)."""

    def __init__(self, t: I64) -> None:
        self.t = t
        self.t_min, self.t_max = int(t.min()), int(t.max())
        self.stamps: I64 | None = None
        self.i: npt.NDArray[np.intp] | None = None
        self.j: npt.NDArray[np.intp] | None = None
        self.r: F | None = None

    def lookup(self, stamps: I64) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.intp], F]:
        if self.stamps is None or not np.array_equal(self.stamps, stamps):
            n = stamps.shape[0]
            t = self.t
            # The older neighbour: the last sample at or before t (the newest-inserted of equal
            # stamps), except exactly at the oldest stamp, where tf2 takes the earliest inserted.
            i = np.searchsorted(stamps, t, side="right") - 1
            if stamps[1] == stamps[0]:
                i[t == stamps[0]] = 0
            j = np.minimum(i + 1, n - 1)
            t0 = stamps[i]
            span = (stamps[j] - t0).astype(np.float64)
            # r = 0 on a sample with no newer neighbour (the newest): the sample itself.
            self.r = np.divide((t - t0).astype(np.float64), span, out=np.zeros(span.shape), where=span > 0)
            self.stamps, self.i, self.j = stamps, i, j
        assert self.i is not None and self.j is not None and self.r is not None
        return self.i, self.j, self.r


def _sample(cache: TimeCache | StaticCache, index: _Index) -> tuple[F, int]:
    t = index.t
    if isinstance(cache, StaticCache):
        return np.broadcast_to(np.asarray(cache.pose, dtype=np.float64), (t.shape[0], 7)), cache.parent
    stamps, poses, parents = cache.arrays()
    if stamps.shape[0] < 2 or index.t_min < stamps[0] or index.t_max > stamps[-1]:
        raise _Irregular  # extrapolation or a single sample: the scalar path gives tf2's errors
    i, j, r = index.lookup(stamps)
    first = int(parents[0])
    if parents.min() != parents.max():
        at_i = parents[i]
        first = int(at_i[0])
        if (at_i != first).any() or (parents[j] != first).any():
            raise _Irregular  # a parent switch inside the span: the scalar walk picks per stamp
    # Gathered component-major ((7, N) memory, (N, 7) view): the kernels read whole columns.
    columns = poses.T
    return poses_interpolate(np.take(columns, i, axis=1).T, np.take(columns, j, axis=1).T, r), first


def _walk(core: BufferCore, t: I64, target_id: int, source_id: int) -> F:
    caches = core._caches
    n = t.shape[0]
    index = _Index(t)
    identity = np.broadcast_to(np.asarray(IDENTITY_POSE), (n, 7))
    source_acc: F | None = None
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
        source_acc = pose if source_acc is None else poses_compose(pose, source_acc)
        frame = parent
    source_acc = identity if source_acc is None else source_acc
    if frame == target_id:
        return source_acc
    target_acc: F | None = None
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
            return poses_inverse(identity if target_acc is None else target_acc)
        target_acc = pose if target_acc is None else poses_compose(pose, target_acc)
        frame = parent
    target_acc = identity if target_acc is None else target_acc
    if frame == source_id:
        return poses_inverse(target_acc)
    return poses_compose(poses_inverse(target_acc), source_acc)


def lookup_many(core: BufferCore, target: str, source: str, stamps: I64) -> tuple[F, F]:
    """Translations ``(N, 3)`` and quaternions ``(N, 4)`` of T_target_source at each stamp (checked ns)."""
    n = stamps.shape[0]
    if n == 0:
        return np.zeros((0, 3)), np.zeros((0, 4))
    if target == source:
        return np.zeros((n, 3)), np.tile([0.0, 0.0, 0.0, 1.0], (n, 1))
    target_id = core._validate(target, "lookupTransform argument target_frame")
    source_id = core._validate(source, "lookupTransform argument source_frame")
    if n >= _SCALAR_BELOW:
        if (stamps == 0).any():
            latest = core._latest_common_time(target_id, source_id, target, source)
            stamps = np.where(stamps == 0, latest, stamps)
        translations, quats = np.empty((n, 3)), np.empty((n, 4))
        try:
            # In chunks: the temporaries stay in cache and are reused by the allocator.
            for lo in range(0, n, _CHUNK):
                poses = _walk(core, stamps[lo:lo + _CHUNK], target_id, source_id)
                translations[lo:lo + _CHUNK] = poses[:, :3]
                quats[lo:lo + _CHUNK] = quats_canonical(poses[:, 3:])
        except _Irregular:
            pass
        else:
            return translations, quats
    out = np.array([core._lookup_ids(target_id, source_id, s, target, source)[0] for s in stamps.tolist()])
    return out[:, :3].copy(), out[:, 3:].copy()
