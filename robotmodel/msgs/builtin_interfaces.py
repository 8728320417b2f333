"""builtin_interfaces messages: the stamp and span fields of every other message.

These are plain mutable messages, as rclpy's are (``stamp.sec = 5`` works). The
immutable values to compute with are :class:`robotmodel.time.Time` and
:class:`robotmodel.time.Duration`, which convert with ``to_msg()``/``from_msg()``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from robotmodel.msgs._base import RosMessage

__all__ = ["Duration", "Time"]


@dataclass(slots=True, repr=False)
class Time(RosMessage):
    """builtin_interfaces/msg/Time: ``sec`` (int32) and ``nanosec`` (uint32) since the epoch."""

    __msgtype__: ClassVar[str] = "builtin_interfaces/msg/Time"

    sec: int = 0
    nanosec: int = 0


@dataclass(slots=True, repr=False)
class Duration(RosMessage):
    """builtin_interfaces/msg/Duration: ``sec`` (int32) and ``nanosec`` (uint32, always added)."""

    __msgtype__: ClassVar[str] = "builtin_interfaces/msg/Duration"

    sec: int = 0
    nanosec: int = 0
