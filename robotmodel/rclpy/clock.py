"""rclpy.clock: Clock, ROSClock (``/clock`` when use_sim_time is set) and ClockType.

A ROSClock reads the system clock until ROS time is made active (a node whose
``use_sim_time`` is true does so), then the last ``/clock`` time it was given; ``sleep_for``
and ``sleep_until`` follow that clock and return False when the context shuts down first.
"""

from __future__ import annotations

import threading
import time as _time
from typing import TYPE_CHECKING

from robotmodel.rclpy.clock_type import ClockType
from robotmodel.rclpy.duration import Duration
from robotmodel.rclpy.time import Time

if TYPE_CHECKING:
    from robotmodel.rclpy.context import Context

__all__ = ["Clock", "ClockType", "ROSClock"]


class Clock:
    """A clock of one type: ``Clock().now()`` is the system time."""

    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        self._clock_type = ClockType(clock_type)
        self._cond = threading.Condition()

    @property
    def clock_type(self) -> ClockType:
        """The clock's type."""
        return self._clock_type

    def _now_ns(self) -> int:
        if self._clock_type == ClockType.STEADY_TIME:
            return _time.monotonic_ns()
        return _time.time_ns()

    def now(self) -> Time:
        """The time now on this clock."""
        return Time(nanoseconds=self._now_ns(), clock_type=self._clock_type)

    def sleep_until(self, until: Time, context: Context | None = None) -> bool:
        """Sleep until this clock reads ``until``; False if the context shut down first."""
        from robotmodel.rclpy.context import get_default_context

        ctx = context or get_default_context()
        while self._now_ns() < until.nanoseconds:
            if not ctx.ok():
                return False
            with self._cond:
                # Bounded: ROS time may jump, and signals must reach the main thread.
                self._cond.wait(min(0.05, max(0.0, (until.nanoseconds - self._now_ns()) / 1e9)))
        return ctx.ok()

    def sleep_for(self, rel_time: Duration, context: Context | None = None) -> bool:
        """Sleep ``rel_time`` on this clock; False if the context shut down first."""
        return self.sleep_until(self.now() + rel_time, context)

    def _wake(self) -> None:
        with self._cond:
            self._cond.notify_all()


class ROSClock(Clock):
    """ROS time: the system time, or the ``/clock`` time once ROS time is active."""

    def __init__(self) -> None:
        super().__init__(clock_type=ClockType.ROS_TIME)
        self._active = False
        self._override_ns = 0

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the clock follows ``/clock`` (set by a node's use_sim_time)."""
        return self._active

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        self._active = enabled
        self._wake()

    def set_ros_time_override(self, when: Time | int) -> None:
        """The ROS time now (what a ``/clock`` message gives)."""
        self._override_ns = when if isinstance(when, int) else when.nanoseconds
        self._wake()

    def _now_ns(self) -> int:
        return self._override_ns if self._active else _time.time_ns()
