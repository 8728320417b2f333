"""Frame-graph queries besides the lookup walk: frame reports, latest common time, what a waiting lookup reads."""

from __future__ import annotations

import threading
from collections.abc import Iterable

from robotmodel.errors import ConnectivityException, LookupException
from robotmodel.tf._cache import CacheMiss, StaticCache, TimeCache, format_time
from robotmodel.tf._names import yaml_key, yaml_quoted

__all__ = ["MAX_GRAPH_DEPTH", "FrameGraph"]

_NO_AUTHORITY = "no recorded authority"

#: tf2's bound on any walk up the tree; beyond it the tree must contain a loop.
MAX_GRAPH_DEPTH = 1000


class FrameGraph:
    """The frame registry's read-only views (the state itself belongs to BufferCore)."""

    _names: list[str]
    _ids: dict[str, int]
    _caches: list[TimeCache | StaticCache | None]
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
        """tf2's allFramesAsYAML (the text view_frames parses); YAML that reads back whatever the names hold."""
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
                who = _NO_AUTHORITY if cache.authority is None else cache.authority
                # Names are anyone's choice on the bus: quoted and escaped where tf2's bare
                # text would not read back as the same string (control characters, quotes, 'true').
                out.append(f"{yaml_key(self._names[fid])}: \n  parent: {yaml_quoted(self._names[parent])}\n"
                           f"  broadcaster: {yaml_quoted(who)}\n"
                           f"  rate: {rate:.3f}\n  most_recent_transform: {format_time(newest)}\n"
                           f"  oldest_transform: {format_time(oldest)}\n")
                if current_time_ns:
                    out.append(f"  transform_delay: {(current_time_ns - newest) / 1e9:.3f}\n")
                out.append(f"  buffer_length: {(newest - oldest) / 1e9:.3f}\n")
            return "".join(out)

    def _loop_error(self, target: str, source: str) -> LookupException:
        return LookupException("The tf tree is invalid because it contains a loop.\n"
                               + self._frames_as_string() + "\n", target_frame=target, source_frame=source)

    def _connectivity(self, target: str, source: str) -> ConnectivityException:
        return ConnectivityException(
            f"Could not find a connection between '{target}' and '{source}' because they are not part of "
            "the same tree.Tf has two or more unconnected trees.", target_frame=target, source_frame=source)

    def _latest_common_time(self, target_id: int, source_id: int, target: str, source: str) -> int:
        caches = self._caches
        if source_id == target_id:
            cache = caches[source_id]
            return cache.latest()[0] if cache is not None else 0
        chain: list[tuple[int, int]] = []  # (stamp, parent) walking up from source
        frame = source_id
        common = 2**63
        depth = 0
        while frame:
            cache = caches[frame]
            if cache is None or len(cache) == 0:
                break
            stamp, parent = cache.latest()
            if parent == 0:
                break
            if stamp:
                common = min(common, stamp)
            chain.append((stamp, parent))
            if parent == target_id:
                return 0 if common == 2**63 else common
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop_error(target, source)
        parents = [p for _, p in chain]
        frame = target_id
        common_t = 2**63
        depth = 0
        ancestor = 0
        while frame:
            cache = caches[frame]
            if cache is None or len(cache) == 0:
                break
            stamp, parent = cache.latest()
            if parent == 0:
                break
            if stamp:
                common_t = min(common_t, stamp)
            if parent in parents:
                ancestor = parent
                break
            frame = parent
            if frame == source_id:
                return 0 if common_t == 2**63 else common_t
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop_error(target, source)
        if not ancestor:
            raise self._connectivity(target, source)
        for stamp, parent in chain:
            if stamp:
                common_t = min(common_t, stamp)
            if parent == ancestor:
                break
        return 0 if common_t == 2**63 else common_t
