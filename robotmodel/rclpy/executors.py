"""rclpy.executors: who runs a node's callbacks, and when.

Callbacks never run on the bus's threads: messages, requests, responses and timers queue
in their node, and an executor runs them while it spins. A SingleThreadedExecutor (what
``rclpy.spin`` uses) runs one callback at a time in the spinning thread, so callbacks never
overlap; a MultiThreadedExecutor runs them on a pool of threads, as far as their callback
groups allow (a MutuallyExclusiveCallbackGroup one at a time, a ReentrantCallbackGroup at
once). Waits are bounded (0.1 s), so a signal handled on the main thread is never held
back by a spinning executor.

When the context shuts down (``rclpy.shutdown()``, SIGINT, SIGTERM), ``spin`` raises
:class:`ExternalShutdownException`, as rclpy's does.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from robotmodel.rclpy.context import Context, get_default_context
from robotmodel.rclpy.task import Future

if TYPE_CHECKING:
    from robotmodel.rclpy.node import Node

__all__ = ["ConditionReachedException", "Executor", "ExternalShutdownException", "MultiThreadedExecutor",
           "ShutdownException", "SingleThreadedExecutor", "TimeoutException"]

_SLICE_S = 0.1


class ExternalShutdownException(Exception):
    """The context was shut down while the executor spun (rclpy's)."""


class ShutdownException(Exception):
    """The executor was shut down."""


class TimeoutException(Exception):
    """Nothing became ready in time."""


class ConditionReachedException(Exception):
    """What the executor waited for happened."""


class Executor:
    """The base of executors: nodes, a wake-up condition, and taking ready work fairly."""

    def __init__(self, *, context: Context | None = None) -> None:
        self._context = context or get_default_context()
        self._nodes: list[Node] = []
        self._cond = threading.Condition()
        self._scheduled: deque[Callable[[], None]] = deque()
        self._is_shutdown = False
        self._turn = 0
        self._context._add_executor(self)

    @property
    def context(self) -> Context:
        """The context it spins in."""
        return self._context

    def add_node(self, node: Node) -> bool:
        """Spin ``node`` too; False if it already does."""
        with self._cond:
            if node in self._nodes:
                return False
            self._nodes.append(node)
        node._executors.add(self)
        node.executor = self
        self._wake()
        return True

    def remove_node(self, node: Node) -> None:
        """Stop spinning ``node``."""
        with self._cond:
            if node in self._nodes:
                self._nodes.remove(node)
        node._executors.discard(self)

    def get_nodes(self) -> list[Node]:
        """The nodes it spins."""
        with self._cond:
            return list(self._nodes)

    def create_task(self, callback: Callable[..., Any], *args: Any) -> Future:
        """Run ``callback(*args)`` in the executor; the Future gets its result."""
        future = Future()

        def run() -> None:
            try:
                future.set_result(callback(*args))
            except Exception as exc:
                future.set_exception(exc)

        self._schedule_callback(run)
        return future

    def _schedule_callback(self, job: Callable[[], None]) -> None:
        with self._cond:
            self._scheduled.append(job)
            self._cond.notify_all()

    def _wake(self) -> None:
        with self._cond:
            self._cond.notify_all()

    def _check(self) -> None:
        if self._is_shutdown:
            raise ShutdownException()
        if not self._context.ok():
            raise ExternalShutdownException()

    def _claim(self) -> Callable[[], None] | None:
        """A ready job whose callback group lets it start now, claimed (called with the lock held)."""
        if self._scheduled:
            return self._scheduled.popleft()
        waitables = [w for node in self._nodes for w in node._waitables()]
        n = len(waitables)
        # Round-robin from where the last take stopped: no waitable starves the others.
        for i in range(n):
            w = waitables[(self._turn + i) % n]
            if not w.ready() or not w.callback_group.beginning_execution():
                continue
            job = w.take()
            if job is None:
                w.callback_group.ending_execution()
                continue
            self._turn = (self._turn + i + 1) % max(n, 1)
            group = w.callback_group

            def run(job: Callable[[], None] = job, group: Any = group) -> None:
                try:
                    job()
                finally:
                    group.ending_execution()
                    self._wake()

            return run
        return None

    def _wait_time(self, deadline: float | None) -> float:
        wait = _SLICE_S
        for node in self._nodes:
            for w in node._waitables():
                due = w.due_in()
                if due is not None:
                    wait = min(wait, due)
        if deadline is not None:
            wait = min(wait, max(0.0, deadline - time.monotonic()))
        return wait

    def _next_job(self, timeout_sec: float | None) -> Callable[[], None] | None:
        deadline = None if timeout_sec is None or timeout_sec < 0 else time.monotonic() + timeout_sec
        with self._cond:
            while True:
                self._check()
                job = self._claim()
                if job is not None:
                    return job
                if deadline is not None and time.monotonic() >= deadline:
                    return None
                self._cond.wait(self._wait_time(deadline))

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Run at most one callback, waiting up to ``timeout_sec`` (None: for ever) for one."""
        try:
            job = self._next_job(timeout_sec)
        except ShutdownException:
            return
        if job is not None:
            job()

    def spin(self) -> None:
        """Run callbacks until the executor or the context shuts down."""
        while self._context.ok() and not self._is_shutdown:
            self.spin_once()
        self._check()

    def spin_until_future_complete(self, future: Future, timeout_sec: float | None = None) -> None:
        """Run callbacks until ``future`` is done or ``timeout_sec`` passes."""
        future._executor = self
        future.add_done_callback(lambda _f: self._wake())
        end = None if timeout_sec is None or timeout_sec < 0 else time.monotonic() + timeout_sec
        while not future.done() and self._context.ok() and not self._is_shutdown:
            left = None if end is None else end - time.monotonic()
            if left is not None and left <= 0:
                return
            self._spin_once_until(future, left)
        if not future.done():
            self._check()

    def _spin_once_until(self, future: Future, timeout_sec: float | None) -> None:
        self.spin_once(_SLICE_S if timeout_sec is None else min(timeout_sec, _SLICE_S))

    def spin_once_until_future_complete(self, future: Future, timeout_sec: float | None = None) -> None:
        """One callback at most, or until ``future`` is done."""
        if not future.done():
            self.spin_once(timeout_sec)

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop spinning (the nodes stay open); True once done."""
        del timeout_sec
        with self._cond:
            self._is_shutdown = True
            self._cond.notify_all()
            nodes, self._nodes = list(self._nodes), []
        for node in nodes:
            node._executors.discard(self)
        self._context._remove_executor(self)
        return True


class SingleThreadedExecutor(Executor):
    """Runs every callback in the thread that spins, one at a time (rclpy's default)."""


class MultiThreadedExecutor(Executor):
    """Runs callbacks on ``num_threads`` threads, as far as their callback groups allow."""

    def __init__(self, num_threads: int | None = None, *, context: Context | None = None) -> None:
        super().__init__(context=context)
        import os

        self._num_threads = num_threads or max(os.cpu_count() or 2, 2)
        self._pool: list[threading.Thread] = []
        self._errors: list[BaseException] = []

    def _worker(self) -> None:
        while self._context.ok() and not self._is_shutdown:
            try:
                job = self._next_job(_SLICE_S)
            except (ShutdownException, ExternalShutdownException):
                return
            if job is not None:
                try:
                    job()
                except BaseException as exc:  # the spinning thread re-raises it, as rclpy's does
                    with self._cond:
                        self._errors.append(exc)
                        self._cond.notify_all()

    def _start_pool(self) -> None:
        with self._cond:
            self._pool = [t for t in self._pool if t.is_alive()]
            missing = self._num_threads - len(self._pool)
            for _ in range(max(missing, 0)):
                # Daemons: an uncaught exception or a signal in the main thread must end the process.
                thread = threading.Thread(target=self._worker, name="rclpy-executor", daemon=True)
                thread.start()
                self._pool.append(thread)

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Let the pool work for up to ``timeout_sec`` (None: one slice); re-raise a callback's error."""
        self._start_pool()
        end = time.monotonic() + (_SLICE_S if timeout_sec is None else max(timeout_sec, 0.0))
        with self._cond:
            while not self._errors and time.monotonic() < end and self._context.ok() and not self._is_shutdown:
                self._cond.wait(min(_SLICE_S, max(0.0, end - time.monotonic())))
            if self._errors:
                raise self._errors.pop(0)

    def _spin_once_until(self, future: Future, timeout_sec: float | None) -> None:
        self._start_pool()
        end = time.monotonic() + (_SLICE_S if timeout_sec is None else min(timeout_sec, _SLICE_S))
        with self._cond:
            while not future.done() and not self._errors and time.monotonic() < end and self._context.ok():
                self._cond.wait(max(0.0, end - time.monotonic()))
            if self._errors:
                raise self._errors.pop(0)

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop the pool, waiting up to ``timeout_sec`` for running callbacks."""
        super().shutdown()
        end = time.monotonic() + (timeout_sec if timeout_sec is not None else 5.0)
        for thread in self._pool:
            if thread is not threading.current_thread():
                thread.join(max(0.0, end - time.monotonic()))
        return not any(t.is_alive() for t in self._pool)
