"""rclpy.clock_type: the kinds of clock."""

from __future__ import annotations

from enum import IntEnum

__all__ = ["ClockType"]


class ClockType(IntEnum):
    """rcl's clock types."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3
