"""Time as rclpy has it, kept as integer nanoseconds, and clocks to read it from.

:class:`Time` and :class:`Duration` are immutable, hashable values with rclpy's
constructors and arithmetic (``Time(seconds=1.5) + Duration(seconds=0.5)``); the
mutable stamp messages are in :mod:`robotmodel.msgs.builtin_interfaces`
(``Time.to_msg()``, ``Time.from_msg(stamp)``). A :class:`Clock` gives ``now()``: the
:class:`SystemClock`, a :class:`SimClock` moved by hand (tests, ``/clock``), or a
:class:`PlaybackClock` running a recording's time at a rate.
"""

from __future__ import annotations

from robotmodel.time._clock import Clock, PlaybackClock, Rate, SimClock, SystemClock
from robotmodel.time._time import Duration, Time, parse_seconds, to_nanoseconds

__all__ = [
    "Clock",
    "Duration",
    "PlaybackClock",
    "Rate",
    "SimClock",
    "SystemClock",
    "Time",
    "parse_seconds",
    "to_nanoseconds",
]
