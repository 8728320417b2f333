"""turtlesim messages: Pose, what a turtle of ROS's turtlesim publishes on ``/turtleN/pose``.

rosbags' type stores do not ship turtlesim; its definition (:data:`POSE_DEFINITION`, the same
in ROS 1 and ROS 2) is registered in robotmodel's ROS 2 store (:func:`robotmodel.msgs.typestore`)
and in the ROS 1 store (:func:`robotmodel.ros1.typestore`), so the type hash and md5sum are ROS's.
A turtle's velocity commands are ``geometry_msgs/Twist`` (:class:`robotmodel.msgs.Twist`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from robotmodel.msgs._base import RosMessage

__all__ = ["Pose"]

#: turtlesim's msg/Pose.msg.
POSE_DEFINITION = """float32 x
float32 y
float32 theta

float32 linear_velocity
float32 angular_velocity
"""


@dataclass(slots=True, repr=False)
class Pose(RosMessage):
    """turtlesim/msg/Pose: where a turtle is (metres, radians) and how fast it moves."""

    __msgtype__: ClassVar[str] = "turtlesim/msg/Pose"

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0
    linear_velocity: float = 0.0
    angular_velocity: float = 0.0
