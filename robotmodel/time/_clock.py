"""Clocks: where "now" comes from. System time, time set by hand, and recording playback.

Every clock answers ``now() -> Time`` (the :class:`Clock` protocol) and can sleep until
a time of its own (``sleep_until``), so code written against one runs on any of them: a
tool on the wall clock, a test on a :class:`SimClock` it advances itself, a replay on a
:class:`PlaybackClock` running a recording's time at some rate.
"""

from __future__ import annotations

import threading
import time as _walltime
from typing import Protocol, runtime_checkable

from robotmodel.time._time import Duration, Time

__all__ = ["Clock", "PlaybackClock", "Rate", "SimClock", "SystemClock"]

_NS = 1_000_000_000


@runtime_checkable
class Clock(Protocol):
    """Anything that tells the time: ``now() -> Time``, and sleeps until a time of its own."""

    def now(self) -> Time:
        """The current time of this clock."""
        ...

    def sleep_until(self, until: Time, timeout: Duration | None = None) -> bool:
        """Block until ``now() >= until``; False if ``timeout`` (wall time) expired first."""
        ...


class SystemClock:
    """The wall clock (``time.time_ns``), as rclpy's SYSTEM_TIME clock."""

    def now(self) -> Time:
        """The current system time."""
        return Time(nanoseconds=_walltime.time_ns())

    def sleep_until(self, until: Time, timeout: Duration | None = None) -> bool:
        """Sleep until the system time reaches ``until``; False if ``timeout`` expired first."""
        deadline = None if timeout is None else _walltime.monotonic_ns() + timeout.nanoseconds
        while True:
            left = until.nanoseconds - _walltime.time_ns()
            if left <= 0:
                return True
            if deadline is not None:
                budget = deadline - _walltime.monotonic_ns()
                if budget <= 0:
                    return False
                left = min(left, budget)
            _walltime.sleep(left / _NS)

    def sleep_for(self, duration: Duration) -> bool:
        """Sleep for ``duration`` of this clock's time."""
        return self.sleep_until(self.now() + duration)


class SimClock:
    """A clock that moves only when told: ``set(t)`` (e.g. from ``/clock``) or ``advance(d)``.

    Thread-safe; ``sleep_until`` wakes when another thread moves the clock far enough.
    Time may be set backwards (a looping replay), as ROS time may jump.
    """

    def __init__(self, start: Time | None = None) -> None:
        self._ns = start.nanoseconds if start is not None else 0
        self._cond = threading.Condition()

    def now(self) -> Time:
        """The time last set."""
        return Time(nanoseconds=self._ns)

    def set(self, time: Time) -> None:
        """Jump to ``time`` and wake the sleepers it concerns."""
        with self._cond:
            self._ns = time.nanoseconds
            self._cond.notify_all()

    def advance(self, duration: Duration) -> Time:
        """Move forward by ``duration`` (backward if negative); returns the new time."""
        with self._cond:
            new = Time(nanoseconds=self._ns + duration.nanoseconds)
            self._ns = new.nanoseconds
            self._cond.notify_all()
        return new

    def sleep_until(self, until: Time, timeout: Duration | None = None) -> bool:
        """Block until the clock is set to ``until`` or later; False if ``timeout`` (wall) expired."""
        target = until.nanoseconds
        with self._cond:
            return self._cond.wait_for(lambda: self._ns >= target,
                                       None if timeout is None else timeout.nanoseconds / _NS)

    def sleep_for(self, duration: Duration) -> bool:
        """Block until this clock has moved ``duration`` past now."""
        return self.sleep_until(self.now() + duration)


class PlaybackClock:
    """A recording's time, running from ``start`` at ``rate`` times the wall clock's speed.

    ``now()`` is ``start + rate * (wall time since started)``; ``pause()``, ``resume()``,
    ``seek(t)`` and ``set_rate(r)`` keep the time continuous. Wall time is monotonic, so
    the playback never jumps when the system clock is adjusted.
    """

    def __init__(self, start: Time, rate: float = 1.0, *, paused: bool = False) -> None:
        if not rate > 0:
            raise ValueError(f"playback rate must be positive, got {rate}")
        self._lock = threading.Lock()
        self._base_ns = start.nanoseconds
        self._wall0 = _walltime.monotonic_ns()
        self._rate = float(rate)
        self._paused = paused

    def _now_ns(self) -> int:
        if self._paused:
            return self._base_ns
        return self._base_ns + int((_walltime.monotonic_ns() - self._wall0) * self._rate)

    def _rebase(self, base_ns: int) -> None:
        self._base_ns = base_ns
        self._wall0 = _walltime.monotonic_ns()

    @property
    def rate(self) -> float:
        """Recording seconds per wall second."""
        return self._rate

    @property
    def paused(self) -> bool:
        """Whether the playback is paused."""
        return self._paused

    def now(self) -> Time:
        """The recording time now."""
        with self._lock:
            return Time(nanoseconds=max(0, self._now_ns()))

    def pause(self) -> None:
        """Stop the time where it is."""
        with self._lock:
            self._rebase(self._now_ns())
            self._paused = True

    def resume(self) -> None:
        """Run again from where it was paused."""
        with self._lock:
            self._rebase(self._now_ns())
            self._paused = False

    def seek(self, time: Time) -> None:
        """Jump to ``time`` (running or paused as before)."""
        with self._lock:
            self._rebase(time.nanoseconds)

    def set_rate(self, rate: float) -> None:
        """Change the speed from now on."""
        if not rate > 0:
            raise ValueError(f"playback rate must be positive, got {rate}")
        with self._lock:
            self._rebase(self._now_ns())
            self._rate = float(rate)

    def sleep_until(self, until: Time, timeout: Duration | None = None) -> bool:
        """Sleep until the recording time reaches ``until``; False if ``timeout`` (wall) expired.

        While paused this sleeps in short steps, so a ``resume()`` or ``seek()`` is noticed.
        """
        deadline = None if timeout is None else _walltime.monotonic_ns() + timeout.nanoseconds
        while True:
            with self._lock:
                left = until.nanoseconds - self._now_ns()
                wall = 10_000_000 if self._paused else int(left / self._rate) + 1
            if left <= 0:
                return True
            if deadline is not None:
                budget = deadline - _walltime.monotonic_ns()
                if budget <= 0:
                    return False
                wall = min(wall, budget)
            _walltime.sleep(min(wall, 100_000_000) / _NS)


class Rate:
    """Loop at a fixed frequency on any clock: ``rate = Rate(10.0, clock); rate.sleep()``.

    Wake-ups fall on the multiples of the period after the Rate's creation, as rclpy's
    timer-based Rate; a loop that fell more than one period behind restarts from now
    instead of bursting.
    """

    def __init__(self, hz: float, clock: Clock | None = None) -> None:
        if not hz > 0:
            raise ValueError(f"rate must be positive, got {hz} Hz")
        self._period = Duration(nanoseconds=round(_NS / hz))
        self._clock: Clock = clock if clock is not None else SystemClock()
        self._last = self._clock.now()

    @property
    def period(self) -> Duration:
        """Time between two wake-ups."""
        return self._period

    def sleep(self) -> None:
        """Sleep until the next period boundary."""
        now = self._clock.now()
        if now - self._last > self._period + self._period:
            self._last = now
        self._last = self._last + self._period
        self._clock.sleep_until(self._last)
