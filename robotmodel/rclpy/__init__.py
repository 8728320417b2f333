"""rclpy on robotmodel's bus: ``from robotmodel import rclpy`` in place of ``import rclpy``.

The module layout is rclpy's (:mod:`~robotmodel.rclpy.node`, :mod:`~robotmodel.rclpy.qos`,
:mod:`~robotmodel.rclpy.time`, :mod:`~robotmodel.rclpy.duration`, :mod:`~robotmodel.rclpy.clock`,
:mod:`~robotmodel.rclpy.executors`, :mod:`~robotmodel.rclpy.callback_groups`,
:mod:`~robotmodel.rclpy.parameter`, :mod:`~robotmodel.rclpy.exceptions`,
:mod:`~robotmodel.rclpy.logging`, :mod:`~robotmodel.rclpy.task`), and so are the semantics
a program sees: callbacks run only while an executor spins, never two at once under the
default executor; parameters are declared, typed and served to ``ros2 param`` and rclpy's
parameter clients; ``--ros-args`` are rcl's; log lines are rcutils' on stderr.

Signals: :func:`init` (from the main thread) makes SIGINT and SIGTERM shut the context
down; SIGINT then raises KeyboardInterrupt as Python's default handler does, and a
``spin`` in progress raises :class:`~robotmodel.rclpy.executors.ExternalShutdownException`,
so the usual ``except (KeyboardInterrupt, ExternalShutdownException)`` ends the program.

robotmodel's additions: :func:`init` takes ``backend=`` (the wire: ``"dds"``, ``"zenoh"``,
``"inprocess"``; default as :func:`robotmodel.bus.default_wire` decides) and ``connect=``.
Message classes come from :mod:`robotmodel.msgs` (``robotmodel.msgs.geometry_msgs.msg``,
``robotmodel.msgs.rcl_interfaces.msg``, ``robotmodel.msgs.example_interfaces.srv`` ...).
"""

from __future__ import annotations

import atexit
import signal
import threading
from collections.abc import Sequence
from typing import Any

from robotmodel.rclpy.context import Context, get_default_context
from robotmodel.rclpy.executors import Executor, SingleThreadedExecutor
from robotmodel.rclpy.node import Node
from robotmodel.rclpy.task import Future

__all__ = [
    "InitContextManager",
    "create_node",
    "get_default_context",
    "get_global_executor",
    "init",
    "ok",
    "shutdown",
    "spin",
    "spin_once",
    "spin_until_future_complete",
    "try_shutdown",
]

_executor: Executor | None = None
_executor_lock = threading.Lock()
_previous: dict[int, Any] = {}


class InitContextManager:
    """What :func:`init` returns: ``with rclpy.init():`` shuts the context down at the block's end.

    Newer rclpy's form (Kilted); Jazzy's init returns None, and code written for it ignores this.
    """

    def __init__(self, context: Context) -> None:
        self.context = context

    def __enter__(self) -> InitContextManager:
        return self

    def __exit__(self, *exc: object) -> None:
        self.context.try_shutdown()


def init(*, args: Sequence[str] | None = None, context: Context | None = None, domain_id: int | None = None,
         signal_handler_options: Any = None, backend: str | None = None,
         connect: Sequence[str] = ()) -> InitContextManager:
    """Start the context: read ``--ros-args`` from ``args`` (default ``sys.argv``), open the wire."""
    ctx = context or get_default_context()
    ctx.init(args, domain_id=domain_id, backend=backend, connect=connect)
    if signal_handler_options is not False and threading.current_thread() is threading.main_thread():
        for sig in (signal.SIGINT, signal.SIGTERM):
            current = signal.getsignal(sig)
            if current is not _on_signal:
                _previous[sig] = current
                signal.signal(sig, _on_signal)
    return InitContextManager(ctx)


def _on_signal(sig: int, frame: Any) -> None:
    # As rclpy's handler: every context shuts down (executors wake and stop), then the
    # handler that was there before runs (SIGINT's default raises KeyboardInterrupt).
    get_default_context().try_shutdown()
    previous = _previous.get(sig)
    if callable(previous):
        previous(sig, frame)


def ok(*, context: Context | None = None) -> bool:
    """Whether the context is initialized and not shut down."""
    return (context or get_default_context()).ok()


def shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut the context down (RuntimeError if it is not initialized)."""
    del uninstall_handlers
    global _executor
    (context or get_default_context()).shutdown()
    with _executor_lock:
        executor, _executor = _executor, None
    if executor is not None:
        executor.shutdown()


def try_shutdown(*, context: Context | None = None, uninstall_handlers: bool | None = None) -> None:
    """Shut the context down if it is initialized."""
    del uninstall_handlers
    (context or get_default_context()).try_shutdown()


def create_node(node_name: str, **kwargs: Any) -> Node:
    """``Node(node_name, **kwargs)``."""
    return Node(node_name, **kwargs)


def get_global_executor() -> Executor:
    """The process's SingleThreadedExecutor (what spin uses without one)."""
    global _executor
    with _executor_lock:
        if _executor is None or _executor._is_shutdown:
            _executor = SingleThreadedExecutor()
        return _executor


def spin(node: Node, executor: Executor | None = None) -> None:
    """Run ``node``'s callbacks until the context shuts down."""
    executor = executor or get_global_executor()
    try:
        executor.add_node(node)
        executor.spin()
    finally:
        executor.remove_node(node)


def spin_once(node: Node, *, executor: Executor | None = None, timeout_sec: float | None = None) -> None:
    """Run at most one of ``node``'s callbacks, waiting up to ``timeout_sec``."""
    executor = executor or get_global_executor()
    try:
        executor.add_node(node)
        executor.spin_once(timeout_sec)
    finally:
        executor.remove_node(node)


def spin_until_future_complete(node: Node, future: Future, executor: Executor | None = None,
                               timeout_sec: float | None = None) -> None:
    """Run ``node``'s callbacks until ``future`` is done (or ``timeout_sec`` passes)."""
    executor = executor or get_global_executor()
    try:
        executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        executor.remove_node(node)


atexit.register(lambda: get_default_context().try_shutdown())
