"""rclpy.context: the Context init() starts and shutdown() ends, holding the session on the bus.

A context is one session on one wire (:class:`robotmodel.bus.Context`), opened by
:meth:`Context.init` with the process's ``--ros-args`` (read as rcl reads them; nodes read
their remaps and parameters from them). Shutting it down closes every node made in it and
wakes every executor, whose ``spin`` then ends.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable, Sequence
from typing import Any

from robotmodel.bus import Context as BusContext
from robotmodel.rcl import RosArgs, apply_log_levels, take_ros_args
from robotmodel.rclpy.exceptions import NotInitializedException

__all__ = ["Context"]


class Context:
    """rclpy's Context: ``ok()`` between ``init()`` and ``shutdown()``."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self._ok = False
        self._bus: BusContext | None = None
        self.argv: list[str] = []
        self.ros_args = RosArgs()
        self._on_shutdown: list[Callable[[], None]] = []
        self._executors: list[Any] = []

    def init(self, args: Sequence[str] | None = None, *, domain_id: int | None = None,
             backend: str | None = None, connect: Sequence[str] = ()) -> None:
        """Start: read ``args`` (``sys.argv`` when None) and open the session (``backend``: the wire)."""
        with self._lock:
            if self._ok:
                raise RuntimeError("Context.init() must only be called once")
            words = list(sys.argv if args is None else args)
            self.argv = words
            self.ros_args, _rest = take_ros_args(words[1:] if words else [])
            apply_log_levels(self.ros_args)
            self._bus = BusContext(domain_id=domain_id, connect=connect, backend=backend)
            self._ok = True

    @property
    def bus(self) -> BusContext:
        """The session on the wire; NotInitializedException before init() or after shutdown()."""
        with self._lock:
            if not self._ok or self._bus is None:
                raise NotInitializedException()
            return self._bus

    def ok(self) -> bool:
        """Whether the context is initialized and not shut down."""
        with self._lock:
            return self._ok

    def on_shutdown(self, callback: Callable[[], None]) -> None:
        """Call ``callback()`` at shutdown."""
        with self._lock:
            self._on_shutdown.append(callback)

    def _add_executor(self, executor: Any) -> None:
        with self._lock:
            if executor not in self._executors:
                self._executors.append(executor)

    def _remove_executor(self, executor: Any) -> None:
        with self._lock:
            if executor in self._executors:
                self._executors.remove(executor)

    def shutdown(self) -> None:
        """End the context: nodes close, executors wake; RuntimeError when not initialized."""
        if not self.try_shutdown():
            raise RuntimeError("Context must be initialized before it can be shutdown")

    def try_shutdown(self) -> bool:
        """Shut down if initialized; False when it was not."""
        with self._lock:
            if not self._ok:
                return False
            self._ok = False
            callbacks, self._on_shutdown = self._on_shutdown, []
            executors = list(self._executors)
            bus, self._bus = self._bus, None
        for executor in executors:
            executor._wake()
        for callback in reversed(callbacks):
            try:
                callback()
            except Exception as exc:  # one failing hook must not keep the others from running
                print(f"rclpy: shutdown callback failed: {exc!r}", file=sys.stderr)
        if bus is not None:
            bus.close()
        return True

_default = Context()


def get_default_context() -> Context:
    """The process's default context."""
    return _default
