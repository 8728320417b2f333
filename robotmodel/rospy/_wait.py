"""rospy's Timer and wait_for_message.

:class:`Timer` calls ``callback(TimerEvent)`` every ``period`` of ROS time (``/clock``'s under
``/use_sim_time``) on a thread of its own (as rospy), until :meth:`Timer.shutdown` or the
node's shutdown; ``oneshot=True`` calls once.
:func:`wait_for_message` subscribes, waits for one message and unsubscribes.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any, NamedTuple

from robotmodel.errors import ROSException, ROSInterruptException
from robotmodel.rospy import _core, _time
from robotmodel.rospy._time import Duration, Time, get_rostime

__all__ = ["Timer", "TimerEvent", "wait_for_message"]


class TimerEvent(NamedTuple):
    """What a Timer callback is told (rospy's fields; ``last_*`` are None on the first call)."""

    last_expected: Time | None
    last_real: Time | None
    current_expected: Time
    current_real: Time
    last_duration: float | None


class Timer(threading.Thread):
    """``Timer(rospy.Duration(0.1), callback, oneshot=False)``: started at once, as rospy's."""

    def __init__(self, period: Duration, callback: Callable[[TimerEvent], Any], oneshot: bool = False,
                 reset: bool = False) -> None:
        super().__init__(name="rospy-timer", daemon=True)
        del reset
        self._period = period
        self._callback = callback
        self._oneshot = oneshot
        self._ended = threading.Event()
        self.start()

    def shutdown(self) -> None:
        """Stop calling the callback."""
        self._ended.set()

    def run(self) -> None:
        """Call the callback on the period's grid until stopped or shut down."""
        import time

        start = get_rostime()
        expected = start + self._period
        last_expected: Time | None = None
        last_real: Time | None = None
        last_duration: float | None = None
        while not self._ended.is_set() and not _core.is_shutdown():
            if not self._pause(expected - get_rostime()):
                return
            real = get_rostime()
            began = time.monotonic()
            self._callback(TimerEvent(last_expected, last_real, expected, real, last_duration))
            last_duration = time.monotonic() - began
            if self._oneshot:
                return
            last_expected, last_real = expected, real
            expected = expected + self._period

    def _pause(self, left: Duration) -> bool:
        """Wait ``left`` of ROS time; False when the timer or the node ended meanwhile."""
        if _time.is_wallclock():
            if left.nanoseconds > 0 and self._ended.wait(left.to_sec()):
                return False
        else:
            try:
                _core.sim_sleep(left.nanoseconds, self._ended)
            except ROSInterruptException:  # shutdown, or /clock went back: the timer ends, as rospy's
                return False
        return not (self._ended.is_set() or _core.is_shutdown())


def wait_for_message(topic: str, topic_type: type[Any], timeout: float | Duration | None = None) -> Any:
    """The next message on ``topic``; ROSException on timeout, ROSInterruptException at shutdown."""
    from robotmodel.rospy._topics import Subscriber

    got: list[Any] = []
    arrived = threading.Event()

    def take(msg: Any) -> None:
        if not got:
            got.append(msg)
            arrived.set()

    sub = Subscriber(topic, topic_type, take)
    try:
        seconds = None if timeout is None else (timeout.to_sec() if isinstance(timeout, Duration) else float(timeout))
        import time

        deadline = None if seconds is None else time.monotonic() + seconds
        while not arrived.wait(0.05):
            if _core.is_shutdown():
                raise ROSInterruptException("rospy shutdown")
            if deadline is not None and time.monotonic() > deadline:
                raise ROSException(f"timeout exceeded while waiting for message on topic {topic}")  # rospy: as given
        return got[0]
    finally:
        sub.unregister()
