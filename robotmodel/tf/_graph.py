"""Frame-graph queries other than lookups: tf2's frame reports, and what a waiting lookup depends on."""

from __future__ import annotations

import threading
from collections.abc import Iterable

from robotmodel.tf._cache import CacheMiss, StaticCache, TimeCache, format_time

__all__ = ["MAX_GRAPH_DEPTH", "FrameGraph"]

#: tf2's bound on any walk up the tree; beyond it the tree must contain a loop.
MAX_GRAPH_DEPTH = 1000


class FrameGraph:
    """The frame registry's read-only views (the state itself belongs to BufferCore)."""

    _names: list[str]
    _ids: dict[str, int]
    _caches: list[TimeCache | StaticCache | None]
    _authority: dict[int, str]
    _lock: threading.RLock

    def _dependencies(self, requests: Iterable[tuple[str, int]]) -> set[str]:
        """Frames whose data a lookup of these (frame, time) ends reads: their chains up to the roots.

        Both the newest parents (time 0, the latest common time) and the parents at the
        requested time are followed, so any insert that could change the answer touches one.
        """
        names: set[str] = set()
        for frame, time_ns in requests:
            names.add(frame)
            fid = self._ids.get(frame)
            todo = [fid] if fid else []
            seen: set[int] = set()
            while todo and len(seen) <= MAX_GRAPH_DEPTH:
                fid = todo.pop()
                if fid in seen or not fid:
                    continue
                seen.add(fid)
                names.add(self._names[fid])
                cache = self._caches[fid]
                if cache is None or not len(cache):
                    continue
                todo.append(cache.latest()[1])
                if time_ns:
                    got = cache.sample(time_ns)
                    if not isinstance(got, CacheMiss):
                        todo.append(got[1])
        return names

    def frames(self) -> dict[str, str]:
        """Every frame that has data, mapped to its current (newest) parent."""
        with self._lock:
            out = {}
            for fid, cache in enumerate(self._caches):
                if cache is not None and len(cache):
                    out[self._names[fid]] = self._names[cache.latest()[1]]
            return out

    def all_frame_names(self) -> list[str]:
        """All known frame names in order of first appearance (roots included)."""
        with self._lock:
            return self._names[1:]

    def _frames_as_string(self) -> str:
        lines = []
        for fid, cache in enumerate(self._caches):
            if cache is None:
                continue
            parent = self._names[cache.latest()[1]] if len(cache) else "NO_PARENT"
            lines.append(f"Frame {self._names[fid]} exists with parent {parent}.\n")
        return "".join(lines)

    def all_frames_as_string(self) -> str:
        """tf2's allFramesAsString: one line per frame with data."""
        with self._lock:
            return self._frames_as_string()

    def all_frames_as_yaml(self, current_time_ns: int = 0) -> str:
        """tf2's allFramesAsYAML (the text view_frames parses)."""
        with self._lock:
            if len(self._names) == 1:
                return "[]"
            out = []
            for fid, cache in enumerate(self._caches):
                if cache is None or not len(cache):
                    continue
                newest, parent = cache.latest()
                oldest = cache.oldest_stamp()
                span = max(newest - oldest, 100_000)
                rate = len(cache) * 1e9 / span
                out.append(f"{self._names[fid]}: \n  parent: '{self._names[parent]}'\n"
                           f"  broadcaster: '{self._authority.get(fid, 'no recorded authority')}'\n"
                           f"  rate: {rate:.3f}\n  most_recent_transform: {format_time(newest)}\n"
                           f"  oldest_transform: {format_time(oldest)}\n")
                if current_time_ns:
                    out.append(f"  transform_delay: {(current_time_ns - newest) / 1e9:.3f}\n")
                out.append(f"  buffer_length: {(newest - oldest) / 1e9:.3f}\n")
            return "".join(out)
