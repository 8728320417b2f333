"""Time and Duration as rclpy has them, kept as integer nanoseconds.

:class:`Time` doubles as the ``builtin_interfaces/Time`` message (``sec``/``nanosec``
fields), so ``t.header.stamp.sec = 5`` and ``Time(seconds=1.5)`` both work. ``Time()``
is 0, which tf2 reads as "the latest available".
"""

from __future__ import annotations

from typing import Any

__all__ = ["Duration", "Time", "to_nanoseconds"]

_NS = 1_000_000_000


class Time:
    """A point in time: ``Time(seconds=1.5)``, ``Time(nanoseconds=...)`` or ``Time(sec=, nanosec=)``."""

    __slots__ = ("_ns",)

    def __init__(self, seconds: float = 0, nanoseconds: int = 0, *, sec: int | None = None,
                 nanosec: int | None = None) -> None:
        total = round(seconds * _NS) + int(nanoseconds)
        if sec is not None or nanosec is not None:
            total += int(sec or 0) * _NS + int(nanosec or 0)
        if total < 0:
            raise ValueError("time must not be negative")
        self._ns = total

    @property
    def nanoseconds(self) -> int:
        """Nanoseconds since the epoch."""
        return self._ns

    @property
    def sec(self) -> int:
        """Whole seconds (``builtin_interfaces/Time.sec``)."""
        return self._ns // _NS

    @sec.setter
    def sec(self, value: int) -> None:
        self._ns = int(value) * _NS + self._ns % _NS

    @property
    def nanosec(self) -> int:
        """Nanoseconds within the second (``builtin_interfaces/Time.nanosec``)."""
        return self._ns % _NS

    @nanosec.setter
    def nanosec(self, value: int) -> None:
        self._ns = (self._ns // _NS) * _NS + int(value)

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """(sec, nanosec), as rclpy's Time."""
        return self.sec, self.nanosec

    def to_msg(self) -> Time:
        """A copy usable as a stamp message (the same class here)."""
        return Time(nanoseconds=self._ns)

    def __float__(self) -> float:
        return self._ns / _NS

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Time):
            return self._ns == other._ns
        return NotImplemented

    def __lt__(self, other: Time) -> bool:
        return self._ns < other._ns

    def __le__(self, other: Time) -> bool:
        return self._ns <= other._ns

    def __hash__(self) -> int:
        return hash(self._ns)

    def __add__(self, other: Duration) -> Time:
        return Time(nanoseconds=self._ns + other.nanoseconds)

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Time):
            return Duration(nanoseconds=self._ns - other._ns)
        return Time(nanoseconds=self._ns - other.nanoseconds)

    def __repr__(self) -> str:
        return f"Time(sec={self.sec}, nanosec={self.nanosec})"


class Duration:
    """A span of time: ``Duration(seconds=0.5)`` (may be negative)."""

    __slots__ = ("_ns",)

    def __init__(self, seconds: float = 0, nanoseconds: int = 0, *, sec: int | None = None,
                 nanosec: int | None = None) -> None:
        self._ns = round(seconds * _NS) + int(nanoseconds) + int(sec or 0) * _NS + int(nanosec or 0)

    @property
    def nanoseconds(self) -> int:
        """Length in nanoseconds."""
        return self._ns

    @property
    def sec(self) -> int:
        """Whole seconds (``builtin_interfaces/Duration.sec``)."""
        return self._ns // _NS

    @property
    def nanosec(self) -> int:
        """Nanoseconds within the second."""
        return self._ns % _NS

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._ns == other._ns
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._ns)

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._ns})"


def to_nanoseconds(value: Any) -> int:
    """Integer nanoseconds of a Time/Duration, an rclpy-like object or a stamp message."""
    if isinstance(value, Time | Duration):
        return value._ns
    if hasattr(value, "nanoseconds"):
        return int(value.nanoseconds)
    if hasattr(value, "sec") and hasattr(value, "nanosec"):
        return int(value.sec) * _NS + int(value.nanosec)
    raise TypeError("time must have sec and nanosec, or nanoseconds.")
