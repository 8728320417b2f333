"""builtin_interfaces messages: the stamp and span fields of every other message.

These are plain mutable messages, as rclpy's are (``stamp.sec = 5`` works). The
immutable values to compute with are :class:`robotmodel.time.Time` and
:class:`robotmodel.time.Duration`, which convert with ``to_msg()``/``from_msg()``.

For code ported from rospy, where a stamp is genpy's Time, they also answer genpy's
``secs``/``nsecs`` (read and set), ``to_sec()``, ``to_nsec()`` and ``is_zero()``, so that
``msg.header.stamp.to_sec()`` works unchanged.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from robotmodel.msgs._base import RosMessage

__all__ = ["Duration", "Time"]


class _Genpy:
    """genpy's names on a (sec, nanosec) message, for code written against rospy."""

    __slots__ = ()
    sec: int
    nanosec: int

    @property
    def secs(self) -> int:
        """``sec`` under genpy's name."""
        return self.sec

    @secs.setter
    def secs(self, value: int) -> None:
        self.sec = value  # type: ignore[misc]  # the subclass's slot

    @property
    def nsecs(self) -> int:
        """``nanosec`` under genpy's name."""
        return self.nanosec

    @nsecs.setter
    def nsecs(self, value: int) -> None:
        self.nanosec = value  # type: ignore[misc]  # the subclass's slot

    def to_nsec(self) -> int:
        """All of it in integer nanoseconds."""
        return self.sec * 1_000_000_000 + self.nanosec

    def to_sec(self) -> float:
        """All of it in float seconds."""
        return self.to_nsec() / 1e9

    def is_zero(self) -> bool:
        """Whether both fields are zero."""
        return self.sec == 0 and self.nanosec == 0


@dataclass(slots=True, repr=False)
class Time(_Genpy, RosMessage):
    """builtin_interfaces/msg/Time: ``sec`` (int32) and ``nanosec`` (uint32) since the epoch."""

    __msgtype__: ClassVar[str] = "builtin_interfaces/msg/Time"

    sec: int = 0
    nanosec: int = 0


@dataclass(slots=True, repr=False)
class Duration(_Genpy, RosMessage):
    """builtin_interfaces/msg/Duration: ``sec`` (int32) and ``nanosec`` (uint32, always added)."""

    __msgtype__: ClassVar[str] = "builtin_interfaces/msg/Duration"

    sec: int = 0
    nanosec: int = 0
