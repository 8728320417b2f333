"""rclpy.utilities: the default context and the calls on it, where rclpy keeps them."""

from __future__ import annotations

from robotmodel.rcl import remove_ros_args
from robotmodel.rclpy.context import Context, get_default_context

__all__ = ["get_default_context", "ok", "remove_ros_args", "shutdown", "try_shutdown"]


def ok(*, context: Context | None = None) -> bool:
    """Whether the context (default: the default one) is initialized and not shut down."""
    return (context or get_default_context()).ok()


def shutdown(*, context: Context | None = None) -> None:
    """Shut the context down (RuntimeError if it is not initialized)."""
    (context or get_default_context()).shutdown()


def try_shutdown(*, context: Context | None = None) -> None:
    """Shut the context down if it is initialized."""
    (context or get_default_context()).try_shutdown()
