"""rclpy.callback_groups: which callbacks an executor may run at the same time.

A MutuallyExclusiveCallbackGroup runs one of its callbacks at a time; a
ReentrantCallbackGroup lets its callbacks run at once (on a MultiThreadedExecutor). A
node's default group is mutually exclusive, as in rclpy.
"""

from __future__ import annotations

import threading

__all__ = ["CallbackGroup", "MutuallyExclusiveCallbackGroup", "ReentrantCallbackGroup"]


class CallbackGroup:
    """The base: decides whether one more of its callbacks may start now."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._running = 0

    def can_execute(self) -> bool:
        """Whether a callback of this group may start now."""
        return True

    def beginning_execution(self) -> bool:
        """Claim a run; False when the group does not allow one now."""
        with self._lock:
            if not self._can_start():
                return False
            self._running += 1
            return True

    def ending_execution(self) -> None:
        """Release a run claimed by :meth:`beginning_execution`."""
        with self._lock:
            self._running -= 1

    def _can_start(self) -> bool:
        return True


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """One callback of the group at a time."""

    def can_execute(self) -> bool:
        """Whether none of its callbacks runs now."""
        with self._lock:
            return self._running == 0

    def _can_start(self) -> bool:
        return self._running == 0


class ReentrantCallbackGroup(CallbackGroup):
    """Any number of its callbacks at once."""
