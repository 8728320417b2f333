"""rclpy.task: Future, the result of an asynchronous call (a service call's response)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

__all__ = ["Future"]


class Future:
    """A result to come: ``done()``, ``result()``, ``add_done_callback``, as rclpy's."""

    def __init__(self) -> None:
        self._cond = threading.Condition()
        self._done = False
        self._cancelled = False
        self._result: Any = None
        self._exception: BaseException | None = None
        self._callbacks: list[Callable[[Future], None]] = []
        #: Set by an executor: done callbacks are scheduled on it (rclpy runs them in the executor).
        self._executor: Any = None

    def done(self) -> bool:
        """Whether a result, an exception or a cancel has come."""
        with self._cond:
            return self._done

    def cancelled(self) -> bool:
        """Whether :meth:`cancel` ended it."""
        return self._cancelled

    def cancel(self) -> None:
        """Give up on the result."""
        self._finish(cancelled=True)

    def result(self) -> Any:
        """The result (None before it comes); raises the exception it was given."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        """The exception it was given, if any."""
        return self._exception

    def set_result(self, result: Any) -> None:
        """Complete it with ``result``."""
        self._finish(result=result)

    def set_exception(self, exception: BaseException) -> None:
        """Complete it with an exception."""
        self._finish(exception=exception)

    def _finish(self, result: Any = None, exception: BaseException | None = None, cancelled: bool = False) -> None:
        with self._cond:
            if self._done:
                return
            self._result, self._exception, self._cancelled = result, exception, cancelled
            self._done = True
            callbacks, self._callbacks = self._callbacks, []
            self._cond.notify_all()
        executor = self._executor
        for callback in callbacks:
            if executor is not None:
                executor._schedule_callback(lambda cb=callback: cb(self))
            else:
                callback(self)
        if executor is not None:
            executor._wake()

    def add_done_callback(self, callback: Callable[[Future], None]) -> None:
        """Call ``callback(future)`` once it is done (at once if it already is)."""
        with self._cond:
            if not self._done:
                self._callbacks.append(callback)
                return
        callback(self)

    def wait(self, timeout: float | None = None) -> bool:
        """Block until done (robotmodel's); False at the timeout."""
        with self._cond:
            return self._cond.wait_for(lambda: self._done, timeout)
