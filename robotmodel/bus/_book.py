"""Bookkeeping every wire's session shares: the nodes it made, and handles that run a function on close."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Generic, TypeVar

from robotmodel.bus._backend import Handle
from robotmodel.errors import BusError

__all__ = ["NodeBook", "OnClose"]

N = TypeVar("N")


class OnClose(Handle):
    """A handle whose ``close`` calls ``fn`` once (later calls do nothing)."""

    def __init__(self, fn: Callable[[], None]) -> None:
        self._fn: Callable[[], None] | None = fn

    def close(self) -> None:
        """Call ``fn`` the first time."""
        fn, self._fn = self._fn, None
        if fn is not None:
            fn()


class NodeBook(Generic[N]):
    """The open nodes of one session, so that closing the session closes them (last made, first closed).

    ``wire`` names the session in the error a closed session gives (``the DDS session is closed``).
    """

    def __init__(self, wire: str) -> None:
        self._wire = wire
        self._lock = threading.Lock()
        self._nodes: list[N] = []
        self.closed = False

    def add(self, make: Callable[[], N]) -> N:
        """Make a node with ``make`` and keep it; :class:`BusError` once the session is closed.

        ``make`` runs outside the book's lock: announcing a node may take a wire's graph lock,
        whose thread may in turn be waiting on the session.
        """
        with self._lock:
            if self.closed:
                raise BusError(f"the {self._wire} session is closed")
        node = make()
        with self._lock:
            self._nodes.append(node)
        return node

    def forget(self, node: N) -> None:
        """Drop a node that closed itself."""
        with self._lock:
            if node in self._nodes:
                self._nodes.remove(node)

    def close(self) -> list[N] | None:
        """Mark the session closed; its nodes to close, newest first (None when it already was closed)."""
        with self._lock:
            if self.closed:
                return None
            self.closed = True
            nodes, self._nodes = self._nodes, []
        return nodes[::-1]
