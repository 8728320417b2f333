"""A TF buffer that follows ROS time: cleared when ``/clock`` jumps back, as tf2_ros's buffers are.

ROS 2's ``tf2_ros::Buffer`` (and rclpy's since Jazzy), given the node's clock, registers a
jump callback and clears itself on any backward jump; ROS 1's TransformListener does the
same when it sees ``ros::Time::now()`` go back. Without it a looping replay's transforms
would land behind the recording's end already in the buffer, and a lookup of the latest
would show the end for ever.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robotmodel.rcl import ros_log

if TYPE_CHECKING:
    from robotmodel.time import Time

__all__ = ["clear_on_jump_back"]


def clear_on_jump_back(buffer: Any, clock: Any, logger: str, *, ros1: bool = False) -> None:
    """Clear ``buffer`` (its dynamic transforms) whenever ``clock``, a sim-time clock, goes back; logs tf2_ros's line.

    A system clock never jumps for this: nothing is registered then. ``ros1`` picks ROS 1's
    wording (with the jump's size) over ROS 2's.
    """
    from robotmodel.bus import TopicClock

    if not isinstance(clock, TopicClock):
        return

    def cleared(before: Time, after: Time) -> None:
        if ros1:
            text = f"Detected jump back in time of {(before - after).nanoseconds / 1e9:f}s. Clearing TF buffer."
        else:
            text = "Detected jump back in time. Clearing TF buffer."
        ros_log("WARN", logger, text)
        buffer.clear()

    clock.on_jump_back(cleared)
