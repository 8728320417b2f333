"""geometry_msgs messages, with ROS 2's attribute paths and defaults.

Mutable and constructible empty, so code written for rclpy carries over with only its
imports changed: ``t = TransformStamped(); t.header.frame_id = 'base_link'``.
Covariances are 36 floats, row-major 6x6, zero by default.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from robotmodel.msgs._base import RosMessage
from robotmodel.msgs.std_msgs import Header

__all__ = [
    "Point",
    "PointStamped",
    "Pose",
    "PoseStamped",
    "PoseWithCovariance",
    "Quaternion",
    "Transform",
    "TransformStamped",
    "Twist",
    "TwistStamped",
    "TwistWithCovariance",
    "Vector3",
    "Vector3Stamped",
]


def _zeros36() -> list[float]:
    return [0.0] * 36


@dataclass(slots=True, repr=False)
class Vector3(RosMessage):
    """geometry_msgs/msg/Vector3: a free vector."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Vector3"

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


@dataclass(slots=True, repr=False)
class Point(RosMessage):
    """geometry_msgs/msg/Point: a position."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Point"

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


@dataclass(slots=True, repr=False)
class Quaternion(RosMessage):
    """geometry_msgs/msg/Quaternion (x, y, z, w); the identity (w = 1) by default, as in ROS 2."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Quaternion"

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    w: float = 1.0


@dataclass(slots=True, repr=False)
class Transform(RosMessage):
    """geometry_msgs/msg/Transform: a translation and a rotation."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Transform"

    translation: Vector3 = field(default_factory=Vector3)
    rotation: Quaternion = field(default_factory=Quaternion)


@dataclass(slots=True, repr=False)
class TransformStamped(RosMessage):
    """geometry_msgs/msg/TransformStamped: the pose of ``child_frame_id`` in ``header.frame_id``."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/TransformStamped"

    header: Header = field(default_factory=Header)
    child_frame_id: str = ""
    transform: Transform = field(default_factory=Transform)


@dataclass(slots=True, repr=False)
class Pose(RosMessage):
    """geometry_msgs/msg/Pose: a position and an orientation."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Pose"

    position: Point = field(default_factory=Point)
    orientation: Quaternion = field(default_factory=Quaternion)


@dataclass(slots=True, repr=False)
class PoseStamped(RosMessage):
    """geometry_msgs/msg/PoseStamped."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/PoseStamped"

    header: Header = field(default_factory=Header)
    pose: Pose = field(default_factory=Pose)


@dataclass(slots=True, repr=False)
class PointStamped(RosMessage):
    """geometry_msgs/msg/PointStamped."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/PointStamped"

    header: Header = field(default_factory=Header)
    point: Point = field(default_factory=Point)


@dataclass(slots=True, repr=False)
class Vector3Stamped(RosMessage):
    """geometry_msgs/msg/Vector3Stamped."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Vector3Stamped"

    header: Header = field(default_factory=Header)
    vector: Vector3 = field(default_factory=Vector3)


@dataclass(slots=True, repr=False)
class PoseWithCovariance(RosMessage):
    """geometry_msgs/msg/PoseWithCovariance: covariance over (x, y, z, rot X, rot Y, rot Z)."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/PoseWithCovariance"

    pose: Pose = field(default_factory=Pose)
    covariance: list[float] = field(default_factory=_zeros36)


@dataclass(slots=True, repr=False)
class Twist(RosMessage):
    """geometry_msgs/msg/Twist: linear and angular velocity."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/Twist"

    linear: Vector3 = field(default_factory=Vector3)
    angular: Vector3 = field(default_factory=Vector3)


@dataclass(slots=True, repr=False)
class TwistStamped(RosMessage):
    """geometry_msgs/msg/TwistStamped."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/TwistStamped"

    header: Header = field(default_factory=Header)
    twist: Twist = field(default_factory=Twist)


@dataclass(slots=True, repr=False)
class TwistWithCovariance(RosMessage):
    """geometry_msgs/msg/TwistWithCovariance: covariance over (x, y, z, rot X, rot Y, rot Z)."""

    __msgtype__: ClassVar[str] = "geometry_msgs/msg/TwistWithCovariance"

    twist: Twist = field(default_factory=Twist)
    covariance: list[float] = field(default_factory=_zeros36)
