"""Per-child-frame storage: tf2's TimeCache (time window, no extrapolation) and StaticCache.

A TimeCache keeps its samples in one preallocated array, ascending by stamp: stamps (int64 ns)
and poses (7 doubles: x, y, z, qx, qy, qz, qw), 64 bytes a sample plus at most 1/8 spare
capacity; a frame's first sample sits in a row of an array shared by up to 255 frames (an array
of its own would add ~80 bytes of object to each of a 100k-frame message's frames), and the
second insert moves it to an array of the frame's own; parent ids (int32) get an array of their
own only once a frame's samples have more than one parent. The live samples are the slice
``[start, end)``: pruning only moves ``start``, appending only moves ``end``, and the storage
is compacted or regrown when ``end`` reaches the capacity, which costs amortized O(1) per
insert at any window length. Scalar code reads and writes the array.array directly (no NumPy
call per sample); vectorized lookups get zero-copy NumPy views.
"""

from __future__ import annotations

import struct
import threading
from array import array
from bisect import bisect_left, bisect_right
from dataclasses import dataclass

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
_SLOTS, _PARENTS = array("q", [0]), array("i", [0])
# Shared arrays of first samples: _SHARED_ROWS rows each, the last one never handed out (a
# cache's storage is shared exactly when _pbase != 8 * _cap; see TimeCache._first_row).
_SHARED_ROWS = 256
_SHARED_PBASE = 8 * _SHARED_ROWS
_shared_lock = threading.Lock()
_shared: list[array[int]] = []
_shared_next = [_SHARED_ROWS]


def _shared_row() -> tuple[array[int], int]:
    """A free row of the current shared array (a new array when it is full)."""
    with _shared_lock:
        row = _shared_next[0]
        if row >= _SHARED_ROWS - 1:
            _shared[:] = [_SLOTS * (8 * _SHARED_ROWS)]
            row = 0
        _shared_next[0] = row + 1
        return _shared[0], row


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

    __slots__ = ("_cap", "_end", "_newest", "_oldest", "_pbase", "_qmv", "_smv", "_start", "authority", "parent",
                 "window")

    # One fixed-size array.array of 8 * cap int64 slots: the stamps in [0, cap), then the poses
    # (7 doubles a row) from byte _pbase = 8 * cap on. Parent ids get their own array only once
    # two samples differ (until then every sample has ``parent``). An empty or one-sample
    # cache uses row _start of a shared array instead (_pbase = 8 * _SHARED_ROWS, _cap =
    # _start + 1, so _pbase != 8 * _cap): its first sample costs the 64 bytes of the row.
    # NumPy code gets zero-copy views on demand.
    _smv: array[int]
    _qmv: array[int] | None
    _cap: int
    _pbase: int

    def __init__(self, window_ns: int | None) -> None:
        self.window = window_ns
        self.authority: str | None = None  # who sent the newest accepted sample (view_frames' broadcaster)
        # The parent id every stored sample has (0 while empty), -1 once two differ: a cache with
        # one parent gives the same chain at every time, which lets BufferCore reuse its walk.
        self.parent = 0
        self._qmv = None
        self._start = self._end = 0
        self._newest = self._oldest = 0  # stamps at end - 1 and start, valid when not empty
        self._first_row()

    def _first_row(self) -> None:
        """Empty, with room for one sample in a row of a shared array."""
        self._smv, row = _shared_row()
        self._qmv = None
        self._start = self._end = row
        self._cap, self._pbase = row + 1, _SHARED_PBASE  # one int object for all (rows are small ints)

    # ----------------------------------------------------------------- storage
    def _views(self) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], npt.NDArray[np.int32] | None]:
        """Zero-copy NumPy views of the whole storage (capacity included); no parents while they are one."""
        rows, smv = self._pbase >> 3, self._smv
        parents = None if self._qmv is None else np.frombuffer(self._qmv, dtype=np.int32)
        return (np.frombuffer(smv, dtype=np.int64, count=rows),
                np.frombuffer(smv, dtype=np.float64, count=7 * rows, offset=8 * rows).reshape(rows, 7), parents)

    def _allocate(self, cap: int) -> None:
        start, end = self._start, self._end
        live = end - start
        smv = _SLOTS * (8 * cap)
        qmv = None if self._qmv is None else _PARENTS * cap
        if live:
            old, old_rows = self._smv, self._pbase >> 3
            smv[:live] = old[start:end]
            smv[cap:cap + 7 * live] = old[old_rows + 7 * start:old_rows + 7 * end]
            if qmv is not None and self._qmv is not None:
                qmv[:live] = self._qmv[start:end]
        self._smv, self._qmv = smv, qmv
        self._cap, self._pbase = cap, 8 * cap
        self._start, self._end = 0, live

    def _make_room(self, extra: int) -> None:
        """Ensure ``end + extra <= cap``: compact in place when enough was pruned, else regrow."""
        start, end = self._start, self._end
        live = end - start
        need = live + extra
        cap = self._cap
        if start and need <= cap and start >= live >> 3 and cap <= 4 * need + 64 and self._pbase == 8 * cap:
            smv = self._smv
            smv[:live] = smv[start:end]
            smv[cap:cap + 7 * live] = smv[cap + 7 * start:cap + 7 * end]
            if self._qmv is not None:
                self._qmv[:live] = self._qmv[start:end]
            self._start, self._end = 0, live
        else:
            self._allocate(need + max(need >> 3, _MIN_SPARE))

    def _set_parent(self, parent: int) -> None:
        """Before storing a sample with ``parent``: one parent for all, or an array of them from now on."""
        if self._end == self._start:
            self.parent, self._qmv = parent, None
        elif self._qmv is None:
            if self._pbase != 8 * self._cap:  # a shared row: an array of its own first
                self._make_room(1)
            qmv = _PARENTS * self._cap
            if self.parent:
                np.frombuffer(qmv, dtype=np.int32)[self._start:self._end] = self.parent
            self._qmv, self.parent = qmv, -1

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
        if parent != self.parent:
            self._set_parent(parent)  # may move the samples to an array of their own
        start, end = self._start, self._end
        if end == start:
            smv = self._smv
            smv[start] = stamp
            _pack(smv, self._pbase + start * _ROW, *pose)
            self._end = start + 1
            # Stamps are kept as the array's own ints, never the caller's object: that one was
            # typically decoded with a whole message's throw-away objects and would pin their memory.
            self._newest = self._oldest = smv[start]
            return True
        latest = self._newest
        smv = self._smv
        window = self.window
        if window is not None:
            # Prune with the newest stamp before this insert, as tf2 does (lazy by one insert).
            limit = latest - window
            if self._oldest < limit:
                k = start + 1
                if smv[k] >= limit:  # one sample out of the window: the steady state
                    self._start = k
                    self._oldest = smv[k]
                else:
                    self._prune(limit)
            if stamp < limit:
                return False
        if stamp > latest:
            if end == self._cap:
                self._make_room(1)
                end, smv = self._end, self._smv
            smv[end] = stamp
            _pack(smv, self._pbase + end * _ROW, *pose)
            if self._qmv is not None:
                self._qmv[end] = parent
            self._end = end + 1
            self._newest = smv[end]
            return True
        return self._insert_at_or_before_newest(stamp, pose, parent)

    def _insert_at_or_before_newest(self, stamp: int, pose: Pose7, parent: int) -> bool:
        if self._pbase != 8 * self._cap:  # a shared row: an array of its own first (room in front is not ours)
            self._make_room(1)
        smv = self._smv
        pos = bisect_right(smv, stamp, self._start, self._end)
        k = pos - 1
        # An exactly equal sample (stamp, pose and parent) is not stored again, but counts as success.
        while k >= self._start and smv[k] == stamp:
            if (self._qmv is None or self._qmv[k] == parent) and _unpack(smv, self._pbase + k * _ROW) == pose:
                return True
            k -= 1
        start = self._start
        if pos == start and start:
            pos = self._start = start - 1  # older than everything: room in front
        else:
            if self._end == self._cap:
                self._make_room(1)
                pos -= start - self._start
            end, cap = self._end, self._cap
            smv = self._smv
            if pos < end:
                smv[pos + 1:end + 1] = smv[pos:end]
                smv[cap + 7 * pos + 7:cap + 7 * end + 7] = smv[cap + 7 * pos:cap + 7 * end]
                if self._qmv is not None:
                    self._qmv[pos + 1:end + 1] = self._qmv[pos:end]
            self._end = end + 1
        smv = self._smv
        smv[pos] = stamp
        if pos == self._start:
            self._oldest = smv[pos]
        _pack(smv, self._pbase + pos * _ROW, *pose)
        if self._qmv is not None:
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
        if self._pbase != 8 * self._cap:  # a shared row: an array of its own first, sized below
            self._allocate(max(self._end - self._start, 1))
        empty = self._end == self._start
        if parent != self.parent:
            self._set_parent(parent)
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
        all_stamps, all_poses, all_parents = self._views()
        all_stamps[end:end + n] = stamps
        all_poses[end:end + n] = poses
        if all_parents is not None:
            all_parents[end:end + n] = parent
        del all_stamps, all_poses, all_parents
        self._end = end + n
        self._newest = self._smv[end + n - 1]
        if empty:
            self._oldest = self._smv[end]
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
        parents = all_parents[order]
        self._start = self._end = 0
        self._qmv, self.parent = None, int(parents[0])
        self._allocate(live + max(live >> 3, _MIN_SPARE))
        new_stamps, new_poses, _ = self._views()
        new_stamps[:live] = all_stamps[order]
        new_poses[:live] = all_poses[order]
        if (parents != parents[0]).any():
            self._qmv, self.parent = _PARENTS * self._cap, -1
            np.frombuffer(self._qmv, dtype=np.int32)[:live] = parents
        self._end = live
        self._oldest, self._newest = self._smv[0], self._smv[live - 1]

    # ------------------------------------------------------------------ lookup
    def sample(self, t: int) -> tuple[Pose7, int] | CacheMiss:
        """(pose, parent id) at time ``t`` (0 = newest), interpolated; or why not."""
        oldest, newest = self._oldest, self._newest
        start, end = self._start, self._end
        smv, qmv = self._smv, self._qmv
        if oldest < t < newest and end - start > 1:
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
            offset = self._pbase + i * _ROW
            if qmv is None:
                parent = self.parent
            else:
                parent = qmv[i]
                if qmv[i + 1] != parent:
                    return _unpack(smv, offset), parent  # never interpolate across a parent change
            if t0 == t:
                # At the sample's own stamp the interpolation gives its pose (ratio 0: weights 1
                # and 0, up to the sign of a zero): no SLERP to compute.
                return _unpack(smv, offset), parent
            # Two 7-double reads cost less than one 14-double read and two slices.
            return pose_interpolate(_unpack(smv, offset), _unpack(smv, offset + _ROW), (t - t0) / (t1 - t0)), parent
        if end == start:
            return _no_data(t, 0)
        last = end - 1
        if t in (0, newest):
            return _unpack(smv, self._pbase + last * _ROW), self.parent if qmv is None else qmv[last]
        if last == start:
            return _no_data(t, newest)
        if t > newest:
            return CacheMiss(ExtrapolationDirection.FORWARD, "Lookup would require extrapolation into the future.  "
                             f"Requested time {format_time(t)} but the latest data is at time {format_time(newest)}",
                             oldest, newest)
        if t == oldest:  # among equal oldest stamps tf2 takes the earliest inserted
            return _unpack(smv, self._pbase + start * _ROW), self.parent if qmv is None else qmv[start]
        return CacheMiss(ExtrapolationDirection.BACKWARD, "Lookup would require extrapolation into the past.  "
                         f"Requested time {format_time(t)} but the earliest data is at time {format_time(oldest)}",
                         oldest, newest)

    def arrays(self) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], npt.NDArray[np.int32]]:
        """Zero-copy views of the live stamps, poses and parent ids (valid until the next insert)."""
        s, e = self._start, self._end
        stamps, poses, parents = self._views()
        if parents is None:
            return stamps[s:e], poses[s:e], np.full(e - s, self.parent, dtype=np.int32)
        return stamps[s:e], poses[s:e], parents[s:e]

    def latest(self) -> tuple[int, int]:
        """(newest stamp, its parent id); (0, 0) when empty."""
        if self._end == self._start:
            return 0, 0
        return self._newest, self.parent if self._qmv is None else self._qmv[self._end - 1]

    def oldest_stamp(self) -> int:
        """Oldest stamp (0 when empty)."""
        return self._oldest if self._end > self._start else 0

    def __len__(self) -> int:
        return self._end - self._start

    def nbytes(self) -> int:
        """Bytes held by the arrays (capacity included)."""
        if self._pbase != 8 * self._cap:
            return 8 * _SLOTS.itemsize  # its row of a shared array
        return self._cap * (8 * _SLOTS.itemsize + (0 if self._qmv is None else _PARENTS.itemsize))

    def clear(self) -> None:
        """Drop every sample (and the capacity they used)."""
        self.parent = 0
        self._first_row()


def _own(pose: Pose7) -> Pose7:
    """A copy made now, floats included (see TimeCache.insert: the caller's objects would pin memory)."""
    x, y, z, qx, qy, qz, qw = pose
    return x * 1.0, y * 1.0, z * 1.0, qx * 1.0, qy * 1.0, qz * 1.0, qw * 1.0  # * 1.0 keeps -0.0


class StaticCache:
    """One sample, valid at every time."""

    __slots__ = ("authority", "parent", "pose")

    def __init__(self, pose: Pose7, parent: int) -> None:
        self.authority: str | None = None
        self.pose = _own(pose)
        self.parent = parent

    def insert(self, stamp: int, pose: Pose7, parent: int) -> bool:
        """Overwrite the sample (never rejected)."""
        self.pose, self.parent = _own(pose), parent
        return True

    def sample(self, t: int) -> tuple[Pose7, int]:
        """The sample, whatever ``t``."""
        return self.pose, self.parent

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
