"""Time and Duration as rclpy has them, as immutable integer nanoseconds.

A :class:`Time` is a point since the epoch in [0, 2**63) ns; a :class:`Duration` a
signed span in [-2**63, 2**63) ns. Both are immutable and hashable; the mutable stamp
fields of messages are :mod:`robotmodel.msgs.builtin_interfaces`, reached with
``to_msg()``/``from_msg()``. As in rclpy, ``seconds`` is truncated (not rounded) to
nanoseconds, and ``Time() == Time(nanoseconds=0)`` is what tf2 reads as "latest".
"""

from __future__ import annotations

import math
from datetime import datetime
from decimal import Decimal, InvalidOperation
from typing import Any, NoReturn, overload

from robotmodel.msgs import builtin_interfaces

__all__ = ["Duration", "Time", "parse_seconds", "to_nanoseconds"]

_NS = 1_000_000_000
_INT64_MAX = 2**63 - 1


class Time:
    """A point in time: ``Time(seconds=1.5)`` or ``Time(nanoseconds=...)``, never negative."""

    __slots__ = ("_ns",)
    _ns: int

    def __init__(self, *, seconds: float = 0, nanoseconds: float = 0) -> None:
        if seconds < 0:
            raise ValueError("Seconds value must not be negative")
        if nanoseconds < 0:
            raise ValueError("Nanoseconds value must not be negative")
        total = int(seconds * _NS) + int(nanoseconds)
        if total > _INT64_MAX:
            raise OverflowError("Total nanoseconds value is too large to store in C time point.")
        object.__setattr__(self, "_ns", total)

    def __setattr__(self, name: str, value: Any) -> NoReturn:
        raise AttributeError(f"Time is immutable; cannot set '{name}'")

    def __delattr__(self, name: str) -> NoReturn:
        raise AttributeError(f"Time is immutable; cannot delete '{name}'")

    def __reduce__(self) -> tuple[Any, ...]:
        return (_time_from_ns, (self._ns,))

    @property
    def nanoseconds(self) -> int:
        """Nanoseconds since the epoch."""
        return self._ns

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """(whole seconds, nanoseconds within the second), as rclpy's Time."""
        return divmod(self._ns, _NS)

    def to_msg(self) -> builtin_interfaces.Time:
        """A new ``builtin_interfaces/Time`` message holding this time."""
        sec, nanosec = divmod(self._ns, _NS)
        return builtin_interfaces.Time(sec=sec, nanosec=nanosec)

    def to_datetime(self) -> datetime:
        """The naive local ``datetime`` of this time, as rclpy's (microsecond resolution)."""
        return datetime.fromtimestamp(self._ns / _NS)

    @classmethod
    def from_msg(cls, msg: Any) -> Time:
        """The Time of a ``builtin_interfaces/Time`` message (ours, rosbags' or rclpy's)."""
        if not _is_msg(msg, "builtin_interfaces/msg/Time"):
            raise TypeError("Must pass a builtin_interfaces.msg.Time object")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self._ns})"

    def __hash__(self) -> int:
        return hash((Time, self._ns))

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Time):
            return self._ns == other._ns
        return NotImplemented

    def __lt__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._ns < other._ns
        return NotImplemented

    def __le__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._ns <= other._ns
        return NotImplemented

    def __gt__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._ns > other._ns
        return NotImplemented

    def __ge__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._ns >= other._ns
        return NotImplemented

    def __add__(self, other: Duration) -> Time:
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._ns + other._ns)
            except OverflowError as exc:
                raise OverflowError("Addition leads to overflow in C storage.") from exc
        return NotImplemented

    __radd__ = __add__

    @overload
    def __sub__(self, other: Time) -> Duration: ...

    @overload
    def __sub__(self, other: Duration) -> Time: ...

    def __sub__(self, other: Time | Duration) -> Time | Duration:
        if isinstance(other, Time):
            return Duration(nanoseconds=self._ns - other._ns)
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._ns - other._ns)
            except ValueError as exc:
                raise ValueError("Subtraction leads to negative time.") from exc
            except OverflowError as exc:
                raise OverflowError("Subtraction leads to overflow in C storage.") from exc
        return NotImplemented


class Duration:
    """A span of time: ``Duration(seconds=0.5)``, ``Duration(nanoseconds=-3)``; may be negative."""

    __slots__ = ("_ns",)
    _ns: int

    def __init__(self, *, seconds: float = 0, nanoseconds: float = 0) -> None:
        total = int(seconds * _NS) + int(nanoseconds)
        if not -_INT64_MAX - 1 <= total <= _INT64_MAX:
            raise OverflowError("Total nanoseconds value is too large to store in C duration.")
        object.__setattr__(self, "_ns", total)

    def __setattr__(self, name: str, value: Any) -> NoReturn:
        raise AttributeError(f"Duration is immutable; cannot set '{name}'")

    def __delattr__(self, name: str) -> NoReturn:
        raise AttributeError(f"Duration is immutable; cannot delete '{name}'")

    def __reduce__(self) -> tuple[Any, ...]:
        return (_duration_from_ns, (self._ns,))

    @property
    def nanoseconds(self) -> int:
        """Length in nanoseconds."""
        return self._ns

    def to_msg(self) -> builtin_interfaces.Duration:
        """A new ``builtin_interfaces/Duration`` message (``nanosec`` always in [0, 1e9), as rclpy)."""
        sec, nanosec = divmod(self._ns, _NS)
        return builtin_interfaces.Duration(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: Any) -> Duration:
        """The Duration of a ``builtin_interfaces/Duration`` message (ours, rosbags' or rclpy's)."""
        if not _is_msg(msg, "builtin_interfaces/msg/Duration"):
            raise TypeError("Must pass a builtin_interfaces.msg.Duration object")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._ns})"

    def __str__(self) -> str:
        return f"{self._ns} nanoseconds"

    def __hash__(self) -> int:
        return hash((Duration, self._ns))

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._ns == other._ns
        return NotImplemented

    def __lt__(self, other: Duration) -> bool:
        if isinstance(other, Duration):
            return self._ns < other._ns
        return NotImplemented

    def __le__(self, other: Duration) -> bool:
        if isinstance(other, Duration):
            return self._ns <= other._ns
        return NotImplemented

    def __gt__(self, other: Duration) -> bool:
        if isinstance(other, Duration):
            return self._ns > other._ns
        return NotImplemented

    def __ge__(self, other: Duration) -> bool:
        if isinstance(other, Duration):
            return self._ns >= other._ns
        return NotImplemented

    def __add__(self, other: Duration) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._ns + other._ns)
        return NotImplemented

    def __sub__(self, other: Duration) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._ns - other._ns)
        return NotImplemented

    def __mul__(self, other: float) -> Duration:
        if isinstance(other, bool) or not isinstance(other, int | float):
            return NotImplemented
        if isinstance(other, float) and math.isnan(other):
            raise ValueError("Can't multiply duration with nan")
        return Duration(nanoseconds=self._ns * other if isinstance(other, int) else int(self._ns * other))

    __rmul__ = __mul__

    def __neg__(self) -> Duration:
        return Duration(nanoseconds=-self._ns)


def _is_msg(msg: Any, msgtype: str) -> bool:
    # Ours and rosbags' name their type; rclpy's do not, so a sec/nanosec pair stands for it.
    named = getattr(type(msg), "__msgtype__", None)
    if named is not None:
        return bool(named == msgtype)
    return not isinstance(msg, Time | Duration) and hasattr(msg, "sec") and hasattr(msg, "nanosec")


def _time_from_ns(ns: int) -> Time:
    return Time(nanoseconds=ns)


def _duration_from_ns(ns: int) -> Duration:
    return Duration(nanoseconds=ns)


def to_nanoseconds(value: Any) -> int:
    """Integer nanoseconds of a time value.

    Takes a Time or Duration, a stamp message (``sec``/``nanosec``: ours, rosbags' or
    rclpy's) or anything with ``.nanoseconds`` (rclpy's Time and Duration).
    """
    kind = type(value)
    if kind is builtin_interfaces.Time or kind is builtin_interfaces.Duration:
        return int(value.sec) * _NS + int(value.nanosec)
    if kind is Time or kind is Duration:
        return int(value._ns)
    if hasattr(value, "nanoseconds"):
        return int(value.nanoseconds)
    if hasattr(value, "sec") and hasattr(value, "nanosec"):
        return int(value.sec) * _NS + int(value.nanosec)
    raise TypeError(f"a time must have sec and nanosec, or nanoseconds; got {kind.__name__}")


def parse_seconds(text: str, *, signed: bool = False) -> int:
    """Seconds written in decimal (``12.5``, ``1700000000.123456789``, ``1e3``) as integer nanoseconds, exactly.

    Truncated toward zero to whole nanoseconds, as rclpy's ``Time(seconds=...)``. Raises
    ValueError for text that is not a finite number, and for a value outside a Time's
    range [0, 2**63) ns (a Duration's [-2**63, 2**63) with ``signed=True``), so that the
    result always fits tf2's int64 time.
    """
    try:
        value = Decimal(text.strip())
    except InvalidOperation:
        raise ValueError(f"'{text}' is not a number of seconds") from None
    if not value.is_finite():
        raise ValueError(f"'{text}' is not a finite number of seconds")
    lowest = -_INT64_MAX - 1 if signed else 0
    # Compared as decimals first: int() of '1e300000000' seconds would take forever.
    if not Decimal(lowest) / _NS <= value < Decimal(_INT64_MAX + 1) / _NS:
        kind = "a duration" if signed else "a time"
        raise ValueError(f"'{text}' seconds is out of range for {kind}: it must be within "
                         f"[{Decimal(lowest) / _NS}, {Decimal(_INT64_MAX) / _NS}]")
    return int(value * _NS)
