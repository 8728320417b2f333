"""Per-child-frame storage: tf2's TimeCache (time window, no extrapolation) and StaticCache."""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass
from typing import Any

from robotmodel.spatial import Pose7, pose_interpolate

__all__ = ["CacheMiss", "StaticCache", "TimeCache", "format_time"]

NO_DATA, FORWARD, BACKWARD = "no_data", "forward", "backward"


def format_time(ns: int) -> str:
    """tf2's displayTimePoint: seconds with 6 decimals."""
    return f"{ns // 1_000_000_000 + (ns % 1_000_000_000) * 1e-9:.6f}"


@dataclass(frozen=True, slots=True)
class CacheMiss:
    """Why a cache could not give data at a time (tf2's texts)."""

    kind: str
    message: str
    earliest_ns: int
    latest_ns: int


class TimeCache:
    """Samples of one child frame, ascending by stamp; each sample carries its parent id."""

    __slots__ = ("data", "parents", "snap", "stamps", "version", "window")

    def __init__(self, window_ns: int) -> None:
        self.window = window_ns
        self.stamps: list[int] = []
        self.data: list[Pose7] = []
        self.parents: list[int] = []
        self.version = 0
        # NumPy copy for vectorized lookups, rebuilt when ``version`` moves on.
        self.snap: tuple[int, Any, Any, Any] | None = None

    def insert(self, stamp: int, pose: Pose7, parent: int) -> bool:
        """Insert a sample; False when it is older than the window (TF_OLD_DATA)."""
        stamps = self.stamps
        if stamps:
            latest = stamps[-1]
            # Prune with the newest stamp before this insert, as tf2 does (lazy by one).
            cut = 0
            limit = latest - self.window
            while cut < len(stamps) and stamps[cut] < limit:
                cut += 1
            if cut:
                del stamps[:cut], self.data[:cut], self.parents[:cut]
                self.version += 1
            if stamp < limit:
                return False
            if stamp >= latest:
                if stamp == latest and self._duplicate(stamp, pose, parent):
                    return True
                stamps.append(stamp)
                self.data.append(pose)
                self.parents.append(parent)
                self.version += 1
                return True
        if self._duplicate(stamp, pose, parent):
            return True
        at = bisect_right(stamps, stamp)
        stamps.insert(at, stamp)
        self.data.insert(at, pose)
        self.parents.insert(at, parent)
        self.version += 1
        return True

    def _duplicate(self, stamp: int, pose: Pose7, parent: int) -> bool:
        i = bisect_right(self.stamps, stamp) - 1
        while i >= 0 and self.stamps[i] == stamp:
            if self.data[i] == pose and self.parents[i] == parent:
                return True
            i -= 1
        return False

    def sample(self, t: int) -> tuple[Pose7, int] | CacheMiss:
        """(pose, parent id) at time ``t`` (0 = newest), interpolated; or why not."""
        stamps = self.stamps
        n = len(stamps)
        if n == 0:
            return CacheMiss(NO_DATA, f"Lookup would require extrapolation at time {format_time(t)}, "
                             "but only time 0.000000 is in the buffer", 0, 0)
        if t == 0:
            return self.data[-1], self.parents[-1]
        if n == 1:
            if stamps[0] == t:
                return self.data[0], self.parents[0]
            return CacheMiss(NO_DATA, f"Lookup would require extrapolation at time {format_time(t)}, "
                             f"but only time {format_time(stamps[0])} is in the buffer", stamps[0], stamps[0])
        newest = stamps[-1]
        if t >= newest:
            if t == newest:
                return self.data[-1], self.parents[-1]
            return CacheMiss(FORWARD, "Lookup would require extrapolation into the future.  Requested time "
                             f"{format_time(t)} but the latest data is at time {format_time(newest)}",
                             stamps[0], newest)
        oldest = stamps[0]
        if t <= oldest:
            if t == oldest:
                return self.data[0], self.parents[0]
            return CacheMiss(BACKWARD, "Lookup would require extrapolation into the past.  Requested time "
                             f"{format_time(t)} but the earliest data is at time {format_time(oldest)}",
                             oldest, newest)
        i = bisect_right(stamps, t) - 1
        t0, t1 = stamps[i], stamps[i + 1]
        parents = self.parents
        parent = parents[i]
        if parents[i + 1] != parent:
            return self.data[i], parent  # never interpolate across a parent change
        if t0 == t1:
            return self.data[i + 1], parent
        return pose_interpolate(self.data[i], self.data[i + 1], (t - t0) / (t1 - t0)), parent

    def latest(self) -> tuple[int, int]:
        """(newest stamp, its parent id); (0, 0) when empty."""
        if not self.stamps:
            return 0, 0
        return self.stamps[-1], self.parents[-1]

    def oldest_stamp(self) -> int:
        """Oldest stamp (0 when empty)."""
        return self.stamps[0] if self.stamps else 0

    def __len__(self) -> int:
        return len(self.stamps)

    def clear(self) -> None:
        """Drop every sample."""
        self.stamps.clear()
        self.data.clear()
        self.parents.clear()
        self.version += 1


class StaticCache:
    """One sample, valid at every time."""

    __slots__ = ("parent", "pose", "version")

    def __init__(self, pose: Pose7, parent: int) -> None:
        self.pose = pose
        self.parent = parent
        self.version = 0

    def insert(self, stamp: int, pose: Pose7, parent: int) -> bool:
        """Overwrite the sample (never rejected)."""
        self.pose, self.parent = pose, parent
        self.version += 1
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
