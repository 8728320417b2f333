"""rospy's Time and Duration: seconds and nanoseconds (``secs``/``nsecs``), genpy's arithmetic; the ROS clock.

Both also carry ``sec``/``nanosec`` and ``nanoseconds``, so they go into robotmodel's
messages (``t.header.stamp = rospy.Time.now()``) and its tf2 buffer as they are; the other
way, a received stamp message takes part in their arithmetic and comparisons
(``rospy.Time.now() - msg.header.stamp``).

The ROS clock is the wall clock unless the node follows ``/clock`` (``/use_sim_time`` true
at init_node, as rospy): then :func:`get_rostime` is the last ``/clock`` received, zero
before the first, and :data:`clock_cond` is notified on each.
"""

from __future__ import annotations

import math
import threading
import time as _systime
from typing import Any, Self

__all__ = ["Duration", "Time", "clock_cond", "get_rostime", "get_time", "is_wallclock", "set_rostime",
           "use_sim_time"]

_NS = 1_000_000_000


def _split(secs: float | int, nsecs: int) -> int:
    if isinstance(secs, float):
        if not math.isfinite(secs):
            raise ValueError(f"time values must be finite: {secs}")
        whole = math.floor(secs)
        return int(whole) * _NS + round((secs - whole) * _NS) + int(nsecs)
    return int(secs) * _NS + int(nsecs)


class _TVal:
    """What Time and Duration share: one integer of nanoseconds."""

    __slots__ = ("_ns",)

    def __init__(self, secs: float | int = 0, nsecs: int = 0) -> None:
        self._ns = _split(secs, nsecs)

    @classmethod
    def from_sec(cls, float_secs: float) -> Self:
        """From (float) seconds."""
        return cls(float(float_secs))

    @classmethod
    def from_seconds(cls, float_secs: float) -> Self:
        """The older spelling of :meth:`from_sec`."""
        return cls.from_sec(float_secs)

    @classmethod
    def _of(cls, ns: int) -> Self:
        out = cls.__new__(cls)
        out._ns = int(ns)
        return out

    @property
    def secs(self) -> int:
        """Whole seconds (floor, so that ``nsecs`` is in [0, 1e9))."""
        return self._ns // _NS

    @property
    def nsecs(self) -> int:
        """Nanoseconds past ``secs``."""
        return self._ns % _NS

    # The ROS 2 names, so these values fit robotmodel's stamp fields and buffer.
    sec = secs
    nanosec = nsecs

    @property
    def nanoseconds(self) -> int:
        """All of it in integer nanoseconds."""
        return self._ns

    def to_sec(self) -> float:
        """Float seconds."""
        return self._ns / _NS

    def to_nsec(self) -> int:
        """Integer nanoseconds."""
        return self._ns

    def is_zero(self) -> bool:
        """Whether this is zero."""
        return self._ns == 0

    def __bool__(self) -> bool:
        return self._ns != 0

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._ns))

    def __str__(self) -> str:
        return str(self._ns)

    def __repr__(self) -> str:
        return f"rospy.{type(self).__name__}[{self._ns}]"

    def _cmp(self, other: Any) -> int:
        other = _coerce(other)
        if type(other) is not type(self):
            raise TypeError(f"cannot compare {type(self).__name__} to {type(other).__name__}")
        return int(other._ns)

    def __eq__(self, other: object) -> bool:
        other = _coerce(other)
        return type(other) is type(self) and other._ns == self._ns

    def __lt__(self, other: Any) -> bool:
        return self._ns < self._cmp(other)

    def __le__(self, other: Any) -> bool:
        return self._ns <= self._cmp(other)

    def __gt__(self, other: Any) -> bool:
        return self._ns > self._cmp(other)

    def __ge__(self, other: Any) -> bool:
        return self._ns >= self._cmp(other)


class Duration(_TVal):
    """A signed span: ``Duration(secs, nsecs)`` or ``Duration(1.5)``; ``Duration.from_sec(0.1)``."""

    __slots__ = ()

    def __neg__(self) -> Duration:
        return Duration._of(-self._ns)

    def __abs__(self) -> Duration:
        return Duration._of(abs(self._ns))

    def __add__(self, other: Any) -> Any:
        other = _coerce(other)
        if isinstance(other, Time):
            return Time._of(self._ns + other._ns)
        if isinstance(other, Duration):
            return Duration._of(self._ns + other._ns)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Duration:
        other = _coerce(other)
        if isinstance(other, Duration):
            return Duration._of(self._ns - other._ns)
        return NotImplemented

    def __mul__(self, factor: float) -> Duration:
        if isinstance(factor, (int, float)) and not isinstance(factor, bool):
            return Duration._of(round(self._ns * factor))
        return NotImplemented

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return self._ns / other._ns
        if isinstance(other, (int, float)):
            return Duration._of(round(self._ns / other))
        return NotImplemented

    def __floordiv__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return self._ns // other._ns
        if isinstance(other, int):
            return Duration._of(self._ns // other)
        return NotImplemented


class Time(_TVal):
    """A point in time, never negative: ``Time(secs, nsecs)``, ``Time.now()``; ``Time(0)`` means latest to tf."""

    __slots__ = ()

    def __init__(self, secs: float | int = 0, nsecs: int = 0) -> None:
        super().__init__(secs, nsecs)
        if self._ns < 0:
            raise TypeError("time values must be positive")

    @classmethod
    def now(cls) -> Time:
        """The current ROS time (``/clock``'s under ``/use_sim_time``, else the wall clock)."""
        return get_rostime()

    def __add__(self, other: Any) -> Time:
        other = _coerce(other)
        if isinstance(other, Duration):
            return Time._of(self._ns + other._ns)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        other = _coerce(other)
        if isinstance(other, Time):
            return Duration._of(self._ns - other._ns)
        if isinstance(other, Duration):
            return Time._of(self._ns - other._ns)
        return NotImplemented


def _coerce(value: Any) -> Any:
    """A stamp or span message (a received ``header.stamp``) as the Time or Duration it is; else as it is."""
    kind = getattr(value, "__msgtype__", None)
    if kind == "builtin_interfaces/msg/Time":
        return Time._of(value.sec * _NS + value.nanosec)
    if kind == "builtin_interfaces/msg/Duration":
        return Duration._of(value.sec * _NS + value.nanosec)
    return value


#: Notified whenever ``/clock`` sets the ROS time (what a sleep in simulated time waits on).
clock_cond = threading.Condition()
_sim: list[int] = []  # empty: the wall clock; else [the last /clock in nanoseconds]


def use_sim_time() -> None:
    """Follow ``/clock`` from now on (the time is zero until the first one arrives)."""
    with clock_cond:
        if not _sim:
            _sim.append(0)


def set_rostime(nanoseconds: int) -> None:
    """Set the simulated time (what each ``/clock`` message does)."""
    with clock_cond:
        if _sim:
            _sim[0] = int(nanoseconds)
            clock_cond.notify_all()


def is_wallclock() -> bool:
    """Whether the ROS time is the wall clock (no ``/use_sim_time``)."""
    return not _sim


def get_rostime() -> Time:
    """The current ROS time as a Time."""
    sim = _sim
    return Time._of(sim[0] if sim else _systime.time_ns())


def get_time() -> float:
    """The current ROS time in float seconds."""
    return get_rostime().nanoseconds / _NS
