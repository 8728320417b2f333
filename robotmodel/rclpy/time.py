"""rclpy.time: a point in time of one clock type, in integer nanoseconds."""

from __future__ import annotations

from typing import Any

from robotmodel.msgs.builtin_interfaces import Time as TimeMsg
from robotmodel.rclpy.clock_type import ClockType
from robotmodel.rclpy.duration import Duration

__all__ = ["Time"]


class Time:
    """``Time(seconds=..., nanoseconds=..., clock_type=ClockType.SYSTEM_TIME)``, as rclpy's."""

    def __init__(self, *, seconds: float = 0, nanoseconds: int = 0,
                 clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        total = int(seconds * 1_000_000_000) + int(nanoseconds)
        if total < 0:
            raise ValueError("Total nanoseconds value is too low to store")
        self._ns = total
        self._clock_type = ClockType(clock_type)

    @property
    def nanoseconds(self) -> int:
        """Nanoseconds since the clock's epoch."""
        return self._ns

    @property
    def clock_type(self) -> ClockType:
        """The clock this time is of."""
        return self._clock_type

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """(seconds, nanoseconds within the second)."""
        sec, nsec = divmod(self._ns, 1_000_000_000)
        return sec, nsec

    def to_msg(self) -> TimeMsg:
        """builtin_interfaces/Time."""
        sec, nsec = self.seconds_nanoseconds()
        return TimeMsg(sec=sec, nanosec=nsec)

    @classmethod
    def from_msg(cls, msg: Any, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        """From a builtin_interfaces/Time (a ROS time by default, as rclpy)."""
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)

    def _check(self, other: Time) -> None:
        if self._clock_type != other._clock_type:
            raise TypeError("Can't compare times with different clock types")

    def __add__(self, other: Duration) -> Time:
        if not isinstance(other, Duration):
            return NotImplemented
        return Time(nanoseconds=self._ns + other.nanoseconds, clock_type=self._clock_type)

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Time):
            if self._clock_type != other._clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self._ns - other._ns)
        if isinstance(other, Duration):
            return Time(nanoseconds=self._ns - other.nanoseconds, clock_type=self._clock_type)
        return NotImplemented

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        self._check(other)
        return self._ns == other._ns

    def __hash__(self) -> int:
        return hash((self._ns, self._clock_type))

    def __lt__(self, other: Time) -> bool:
        self._check(other)
        return self._ns < other._ns

    def __le__(self, other: Time) -> bool:
        self._check(other)
        return self._ns <= other._ns

    def __gt__(self, other: Time) -> bool:
        self._check(other)
        return self._ns > other._ns

    def __ge__(self, other: Time) -> bool:
        self._check(other)
        return self._ns >= other._ns

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self._ns}, clock_type={self._clock_type.name})"
