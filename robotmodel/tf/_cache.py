"""Per-child-frame storage: tf2's TimeCache (time window, no extrapolation) and StaticCache.

A TimeCache keeps its samples in preallocated arrays, ascending by stamp: stamps
(int64 ns), poses ((n, 7) float64: x, y, z, qx, qy, qz, qw) and parent ids (int32),
68 bytes a sample plus at most 1/8 spare capacity. The live samples are the slice
``[start, end)``: pruning only moves ``start``, appending only moves ``end``, and the
arrays are compacted or regrown when ``end`` reaches the capacity, which costs
amortized O(1) per insert at any window length. Scalar code reads and writes through
memoryviews (no NumPy call per sample); vectorized lookups get zero-copy NumPy views.
"""

from __future__ import annotations

import struct
from bisect import bisect_left, bisect_right
from dataclasses import dataclass
from math import acos as _acos
from math import sin as _sin

import numpy as np
import numpy.typing as npt

from robotmodel.errors import ExtrapolationDirection
from robotmodel.spatial import Pose7, pose_interpolate

__all__ = ["CacheMiss", "StaticCache", "TimeCache", "format_time"]

_POSE = struct.Struct("7d")
_unpack = _POSE.unpack_from
_unpack_pair = struct.Struct("14d").unpack_from
_pack = _POSE.pack_into
_ROW = _POSE.size
_MIN_SPARE = 16


def format_time(ns: int) -> str:
    """tf2's displayTimePoint: seconds with 6 decimals."""
    return f"{ns // 1_000_000_000 + (ns % 1_000_000_000) * 1e-9:.6f}"


@dataclass(frozen=True, slots=True)
class CacheMiss:
    """Why a cache could not give data at a time (tf2's texts and case)."""

    direction: ExtrapolationDirection
    message: str
    earliest_ns: int
    latest_ns: int


def _no_data(t: int, only: int) -> CacheMiss:
    return CacheMiss(ExtrapolationDirection.NO_DATA, f"Lookup would require extrapolation at time {format_time(t)}, "
                     f"but only time {format_time(only)} is in the buffer", only, only)


class TimeCache:
    """Samples of one child frame within a time window (``None``: unbounded, never pruned)."""

    __slots__ = (
        "_cap",
        "_end",
        "_newest",
        "_oldest",
        "_parents",
        "_pmv",
        "_poses",
        "_qmv",
        "_smv",
        "_stamps",
        "_start",
        "parent",
        "window",
    )

    _stamps: npt.NDArray[np.int64]
    _poses: npt.NDArray[np.float64]
    _parents: npt.NDArray[np.int32]
    _smv: memoryview
    _pmv: memoryview
    _qmv: memoryview

    def __init__(self, window_ns: int | None) -> None:
        self.window = window_ns
        # The parent id every stored sample has (0 while empty), -1 once two differ: a cache with
        # one parent gives the same chain at every time, which lets BufferCore reuse its walk.
        self.parent = 0
        self._start = self._end = 0
        self._newest = self._oldest = 0  # stamps at end - 1 and start, valid when not empty
        self._allocate(_MIN_SPARE)

    # ----------------------------------------------------------------- storage
    def _allocate(self, cap: int) -> None:
        live = self._end - self._start
        stamps = np.empty(cap, dtype=np.int64)
        poses = np.empty((cap, 7), dtype=np.float64)
        parents = np.empty(cap, dtype=np.int32)
        if live:
            stamps[:live] = self._stamps[self._start:self._end]
            poses[:live] = self._poses[self._start:self._end]
            parents[:live] = self._parents[self._start:self._end]
        self._stamps, self._poses, self._parents = stamps, poses, parents
        self._smv = stamps.data
        self._pmv = poses.data.cast("B")
        self._qmv = parents.data
        self._cap = cap
        self._start, self._end = 0, live

    def _make_room(self, extra: int) -> None:
        """Ensure ``end + extra <= cap``: compact in place when enough was pruned, else regrow."""
        start, end = self._start, self._end
        live = end - start
        need = live + extra
        if start and need <= self._cap and start >= live >> 3 and self._cap <= 4 * need + 64:
            self._stamps[:live] = self._stamps[start:end]
            self._poses[:live] = self._poses[start:end]
            self._parents[:live] = self._parents[start:end]
            self._start, self._end = 0, live
        else:
            self._allocate(need + max(need >> 3, _MIN_SPARE))

    def _prune(self, limit: int) -> None:
        """Drop samples older than ``limit`` (there is at least one, and the newest stays)."""
        smv, k, end = self._smv, self._start + 1, self._end
        if k < end and smv[k] < limit:  # more than one to drop: binary search the rest
            k = bisect_left(smv, limit, k + 1, end)
        self._start = k
        self._oldest = smv[k]

    # ------------------------------------------------------------------ insert
    def insert(self, stamp: int, pose: Pose7, parent: int) -> bool:
        """Insert a sample as tf2 does; False when it is older than the window (TF_OLD_DATA)."""
        start, end = self._start, self._end
        if parent != self.parent:
            self.parent = parent if end == start else -1
        if end == start:
            self._smv[0] = stamp
            _pack(self._pmv, 0, *pose)
            self._qmv[0] = parent
            self._start, self._end = 0, 1
            self._newest = self._oldest = stamp
            return True
        latest = self._newest
        if self.window is not None:
            # Prune with the newest stamp before this insert, as tf2 does (lazy by one insert).
            limit = latest - self.window
            if self._oldest < limit:
                k = start + 1
                if self._smv[k] >= limit:  # one sample out of the window: the steady state
                    self._start = k
                    self._oldest = self._smv[k]
                else:
                    self._prune(limit)
            if stamp < limit:
                return False
        if stamp > latest:
            if end == self._cap:
                self._make_room(1)
                end = self._end
            self._smv[end] = stamp
            _pack(self._pmv, end * _ROW, *pose)
            self._qmv[end] = parent
            self._end = end + 1
            self._newest = stamp
            return True
        return self._insert_at_or_before_newest(stamp, pose, parent)

    def _insert_at_or_before_newest(self, stamp: int, pose: Pose7, parent: int) -> bool:
        smv = self._smv
        pos = bisect_right(smv, stamp, self._start, self._end)
        k = pos - 1
        # An exactly equal sample (stamp, pose and parent) is not stored again, but counts as success.
        while k >= self._start and smv[k] == stamp:
            if self._qmv[k] == parent and _unpack(self._pmv, k * _ROW) == pose:
                return True
            k -= 1
        start = self._start
        if pos == start and start:
            pos = self._start = start - 1  # older than everything: room in front
            self._oldest = stamp
        else:
            if self._end == self._cap:
                self._make_room(1)
                pos -= start - self._start
            end = self._end
            if pos < end:
                self._stamps[pos + 1:end + 1] = self._stamps[pos:end]
                self._poses[pos + 1:end + 1] = self._poses[pos:end]
                self._parents[pos + 1:end + 1] = self._parents[pos:end]
            self._end = end + 1
            if pos == self._start:
                self._oldest = stamp
        self._smv[pos] = stamp
        _pack(self._pmv, pos * _ROW, *pose)
        self._qmv[pos] = parent
        return True

    def insert_many(self, stamps: npt.NDArray[np.int64], poses: npt.NDArray[np.float64],
                    parent: int) -> list[int]:
        """Insert rows in order, with exactly the result of one :meth:`insert` per row.

        Returns the indices of the rows rejected as too old. Strictly increasing stamps
        newer than the cache's newest are appended in one step, and an unbounded cache
        merges rows in any order in one step; otherwise (a window and rows out of order or
        repeating stamps) they go row by row.
        """
        n = stamps.shape[0]
        if n == 0:
            return []
        empty = self._end == self._start
        if parent != self.parent:
            self.parent = parent if empty else -1
        increasing = n == 1 or bool((stamps[1:] > stamps[:-1]).all())
        if not increasing or not (empty or int(stamps[0]) > self._newest):
            if self.window is None:
                self._merge(stamps, poses, parent)
                return []
            # With a window, the order decides what is pruned or too old: one row at a time.
            rows = poses.tolist()
            return [k for k, s in enumerate(stamps.tolist()) if not self.insert(s, tuple(rows[k]), parent)]
        if self.window is not None and (n >= 2 or not empty):
            # The state after n single inserts: pruned by the newest stamp before the last one.
            # Rows and samples older than that limit are accepted but not kept.
            limit = (int(stamps[-2]) if n >= 2 else self._newest) - self.window
            if not empty and self._newest < limit:
                empty = True
            elif not empty and self._oldest < limit:
                self._prune(limit)
            skip = int(np.searchsorted(stamps, limit, side="left"))
            stamps, poses, n = stamps[skip:], poses[skip:], n - skip
        if empty:
            self._start = self._end = 0
        if self._end + n > self._cap:
            self._make_room(n)
        end = self._end
        self._stamps[end:end + n] = stamps
        self._poses[end:end + n] = poses
        self._parents[end:end + n] = parent
        self._end = end + n
        self._newest = int(stamps[-1])
        if empty:
            self._oldest = int(stamps[0])
        return []

    def _merge(self, stamps: npt.NDArray[np.int64], poses: npt.NDArray[np.float64], parent: int) -> None:
        """Unbounded cache, rows in any order: the result of inserting them one by one.

        Nothing is pruned or too old, so only the order among equal stamps matters: earlier
        inserted first (a stable sort, existing samples before the rows), and a sample equal
        to an earlier one at its stamp (pose and parent) is not stored again.
        """
        old_stamps, old_poses, old_parents = self.arrays()
        all_stamps = np.concatenate([old_stamps, stamps])
        all_poses = np.concatenate([old_poses, poses])
        all_parents = np.concatenate([old_parents, np.full(stamps.shape[0], parent, dtype=np.int32)])
        order = np.argsort(all_stamps, kind="stable")
        ordered = all_stamps[order]
        repeated = np.flatnonzero(ordered[1:] == ordered[:-1])
        if repeated.size:
            keep = np.ones(order.shape[0], dtype=bool)
            seen: dict[tuple[int, int, bytes], None] = {}
            for k in np.union1d(repeated, repeated + 1).tolist():
                row = int(order[k])
                # + 0.0 turns -0.0 into 0.0: equal as numbers, as the row-by-row comparison has it.
                key = (int(all_stamps[row]), int(all_parents[row]), (all_poses[row] + 0.0).tobytes())
                if key in seen:
                    keep[k] = False
                seen[key] = None
            order = order[keep]
        live = order.shape[0]
        self._start = self._end = 0
        self._allocate(live + max(live >> 3, _MIN_SPARE))
        self._stamps[:live] = all_stamps[order]
        self._poses[:live] = all_poses[order]
        self._parents[:live] = all_parents[order]
        self._end = live
        self._oldest, self._newest = int(self._stamps[0]), int(self._stamps[live - 1])

    # ------------------------------------------------------------------ lookup
    def sample(self, t: int) -> tuple[Pose7, int] | CacheMiss:
        """(pose, parent id) at time ``t`` (0 = newest), interpolated; or why not."""
        oldest, newest = self._oldest, self._newest
        start, end = self._start, self._end
        if oldest < t < newest and end - start > 1:
            smv = self._smv
            # Most streams are regular: guess the index from the rate, check it, else bisect.
            i = start + (t - oldest) * (end - 1 - start) // (newest - oldest)
            t0 = smv[i]
            if t0 <= t:
                t1 = smv[i + 1]
                if t1 <= t:
                    i = bisect_right(smv, t, i + 1, end) - 1
                    t0, t1 = smv[i], smv[i + 1]
            else:
                i = bisect_right(smv, t, start, i) - 1
                t0, t1 = smv[i], smv[i + 1]
            qmv = self._qmv
            parent = qmv[i]
            pmv, offset = self._pmv, i * _ROW
            if qmv[i + 1] != parent:
                return _unpack(pmv, offset), parent  # never interpolate across a parent change
            # Two 7-double reads cost less than one 14-double read and two slices.
            return pose_interpolate(_unpack(pmv, offset), _unpack(pmv, offset + _ROW), (t - t0) / (t1 - t0)), parent
        if end == start:
            return _no_data(t, 0)
        last = end - 1
        if t in (0, newest):
            return _unpack(self._pmv, last * _ROW), self._qmv[last]
        if last == start:
            return _no_data(t, newest)
        if t > newest:
            return CacheMiss(ExtrapolationDirection.FORWARD, "Lookup would require extrapolation into the future.  "
                             f"Requested time {format_time(t)} but the latest data is at time {format_time(newest)}",
                             oldest, newest)
        if t == oldest:  # among equal oldest stamps tf2 takes the earliest inserted
            return _unpack(self._pmv, start * _ROW), self._qmv[start]
        return CacheMiss(ExtrapolationDirection.BACKWARD, "Lookup would require extrapolation into the past.  "
                         f"Requested time {format_time(t)} but the earliest data is at time {format_time(oldest)}",
                         oldest, newest)

    def pose_at(self, t: int) -> Pose7 | None:
        """:meth:`sample`'s pose where it interpolates or hits the newest sample, else None.

        For a cache with one parent (the caller checks ``parent``): the parent test and the
        misses' texts are left out; None sends the caller to :meth:`sample`.
        """
        oldest, newest = self._oldest, self._newest
        if oldest < t < newest:
            smv = self._smv
            start, end = self._start, self._end
            i = start + (t - oldest) * (end - 1 - start) // (newest - oldest)
            t0 = smv[i]
            if t0 <= t:
                t1 = smv[i + 1]
                if t1 <= t:
                    i = bisect_right(smv, t, i + 1, end) - 1
                    t0, t1 = smv[i], smv[i + 1]
            else:
                i = bisect_right(smv, t, start, i) - 1
                t0, t1 = smv[i], smv[i + 1]
            # pose_interpolate inlined, operation for operation (the same results to the bit).
            ax, ay, az, qx, qy, qz, qw, bx, by, bz, px, py, pz, pw = _unpack_pair(self._pmv, i * _ROW)
            r = (t - t0) / (t1 - t0)
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
        if t == newest and self._end > self._start:
            return _unpack(self._pmv, (self._end - 1) * _ROW)
        return None

    def arrays(self) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], npt.NDArray[np.int32]]:
        """Zero-copy views of the live stamps, poses and parent ids (valid until the next insert)."""
        s, e = self._start, self._end
        return self._stamps[s:e], self._poses[s:e], self._parents[s:e]

    def latest(self) -> tuple[int, int]:
        """(newest stamp, its parent id); (0, 0) when empty."""
        if self._end == self._start:
            return 0, 0
        return self._newest, self._qmv[self._end - 1]

    def oldest_stamp(self) -> int:
        """Oldest stamp (0 when empty)."""
        return self._oldest if self._end > self._start else 0

    def __len__(self) -> int:
        return self._end - self._start

    def nbytes(self) -> int:
        """Bytes held by the arrays (capacity included)."""
        return int(self._stamps.nbytes + self._poses.nbytes + self._parents.nbytes)

    def clear(self) -> None:
        """Drop every sample (and the capacity they used)."""
        self.parent = 0
        self._start = self._end = 0
        self._allocate(_MIN_SPARE)


class StaticCache:
    """One sample, valid at every time."""

    __slots__ = ("parent", "pose")

    def __init__(self, pose: Pose7, parent: int) -> None:
        self.pose = pose
        self.parent = parent

    def insert(self, stamp: int, pose: Pose7, parent: int) -> bool:
        """Overwrite the sample (never rejected)."""
        self.pose, self.parent = pose, parent
        return True

    def sample(self, t: int) -> tuple[Pose7, int]:
        """The sample, whatever ``t``."""
        return self.pose, self.parent

    def pose_at(self, t: int) -> Pose7:
        """The sample's pose, whatever ``t``."""
        return self.pose

    def latest(self) -> tuple[int, int]:
        """Static data reports stamp 0."""
        return 0, self.parent

    def oldest_stamp(self) -> int:
        """Static data reports stamp 0."""
        return 0

    def __len__(self) -> int:
        return 1

    def clear(self) -> None:
        """Keep the sample: static data survives a clear."""
