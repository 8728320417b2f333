"""Which node published a sample: the GID the wire gives with it, matched against the bus's graph.

A publisher's announcement in the graph and its first samples travel separately, so a sample can
arrive before the graph knows its publisher. Looking names up is cheap once known (a dict),
throttled while unknown (the graph is scanned at most every 0.2 s per GID), and a caller
that cannot simply wait for the next sample (a latched static transform is sent once) can
ask to be called back when the name turns up.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotmodel.bus import Entity, Graph

__all__ = ["PublisherNames"]

_RETRY_S = 0.2
# How long a callback waits for its publisher to appear before it is dropped.
_PATIENCE_S = 10.0


class PublisherNames:
    """GID -> the publishing node's fully qualified name, from one bus graph."""

    def __init__(self, graph: Graph) -> None:
        self._graph = graph
        self._names: dict[bytes, str] = {}
        self._misses: dict[bytes, float] = {}
        self._lock = threading.Lock()
        self._waiting: dict[bytes, list[tuple[float, Callable[[str], None]]]] = {}
        self._thread: threading.Thread | None = None
        self._closed = False

    def name(self, gid: bytes) -> str | None:
        """The node behind ``gid``, or None while the graph does not show it."""
        name = self._names.get(gid)
        if name is not None:
            return name
        now = time.monotonic()
        if now - self._misses.get(gid, -1e9) < _RETRY_S:
            return None
        found = self._scan(gid)
        if found is None:
            # Scanning the graph for every sample of an unknown publisher would cost a lot
            # at high rates; look again a little later instead.
            self._misses[gid] = now
        return found

    def _scan(self, gid: bytes) -> str | None:
        from robotmodel.bus import EntityKind

        for entity in self._graph.entities():
            if entity.kind is EntityKind.PUBLISHER and entity.gid == gid:
                return self._learn(entity)
        return None

    def _learn(self, entity: Entity) -> str:
        name = self._names[entity.gid] = entity.node_fqn
        self._misses.pop(entity.gid, None)
        return name

    def when_known(self, gid: bytes, callback: Callable[[str], None]) -> None:
        """Call ``callback(name)`` on a background thread once ``gid``'s publisher shows up.

        Given up silently after 10 s (the publisher may have gone already).
        """
        with self._lock:
            if self._closed:
                return
            self._waiting.setdefault(gid, []).append((time.monotonic() + _PATIENCE_S, callback))
            if self._thread is None:
                self._thread = threading.Thread(target=self._watch, name="tf_ros-publisher-names", daemon=True)
                self._thread.start()

    def _watch(self) -> None:
        from robotmodel.bus import EntityKind

        def known(entities: list[Entity]) -> bool:
            wanted = self._waiting.keys()
            return any(e.kind is EntityKind.PUBLISHER and e.gid in wanted for e in entities)

        while True:
            # Wakes as soon as a token arrives (the graph notifies), or every 0.1 s to expire
            # callbacks and notice close().
            self._graph.wait_for(known, 0.1)
            ready: list[tuple[str, Callable[[str], None]]] = []
            with self._lock:
                if self._closed:
                    self._thread = None
                    return
                now = time.monotonic()
                for gid in list(self._waiting):
                    name = self._scan(gid)
                    callbacks = self._waiting[gid]
                    if name is not None:
                        ready.extend((name, cb) for _, cb in callbacks)
                        del self._waiting[gid]
                    else:
                        alive = [(t, cb) for t, cb in callbacks if t > now]
                        if alive:
                            self._waiting[gid] = alive
                        else:
                            del self._waiting[gid]
                if not self._waiting and not ready:
                    self._thread = None
                    return
            for name, cb in ready:
                cb(name)

    def close(self) -> None:
        """Drop pending callbacks and let the background thread end."""
        with self._lock:
            self._closed = True
            self._waiting.clear()
