"""A tf2-style transform buffer: ROS 2 message classes, Time/Duration, Buffer, tf2's exceptions.

Code written for tf2_ros carries over with only its imports changed::

    from robotmodel.tf import Buffer, TransformStamped, Time, Duration, LookupException

``Time`` and ``Duration`` are :mod:`robotmodel.time`'s immutable values; the messages
come from :mod:`robotmodel.msgs` (``TransformStamped().header.stamp`` is a mutable
``builtin_interfaces/Time`` message). Lookups take a Time, a stamp message, or any
object with ``.nanoseconds`` (rclpy's Time).
"""

from __future__ import annotations

from robotmodel.errors import (
    ConnectivityException,
    ExtrapolationDirection,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from robotmodel.msgs import (
    Header,
    Point,
    PointStamped,
    Pose,
    PoseStamped,
    Quaternion,
    Transform,
    TransformStamped,
    Vector3,
    Vector3Stamped,
    make_transform,
)
from robotmodel.tf._buffer import Buffer
from robotmodel.tf._core import MAX_GRAPH_DEPTH, BufferCore
from robotmodel.tf._view import view_frames_gv, write_view_frames
from robotmodel.time import Duration, Time

__all__ = [
    "MAX_GRAPH_DEPTH",
    "Buffer",
    "BufferCore",
    "ConnectivityException",
    "Duration",
    "ExtrapolationDirection",
    "ExtrapolationException",
    "Header",
    "InvalidArgumentException",
    "LookupException",
    "Point",
    "PointStamped",
    "Pose",
    "PoseStamped",
    "Quaternion",
    "Time",
    "TimeoutException",
    "Transform",
    "TransformException",
    "TransformStamped",
    "Vector3",
    "Vector3Stamped",
    "make_transform",
    "view_frames_gv",
    "write_view_frames",
]
