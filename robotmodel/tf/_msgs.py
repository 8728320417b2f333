"""ROS 2 message classes with the same attribute paths and defaults as geometry_msgs/std_msgs.

They are plain mutable dataclasses, constructible empty and filled field by field
(``t = TransformStamped(); t.header.frame_id = 'base_link'``) or by keywords, so code
written against rclpy carries over with only its imports changed.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from robotmodel.tf._time import Time

__all__ = [
    "Header",
    "Point",
    "PointStamped",
    "Pose",
    "PoseStamped",
    "Quaternion",
    "Transform",
    "TransformStamped",
    "Vector3",
    "Vector3Stamped",
    "make_transform",
]


@dataclass
class Header:
    """std_msgs/Header."""

    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass
class Vector3:
    """geometry_msgs/Vector3."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


@dataclass
class Point:
    """geometry_msgs/Point."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


@dataclass
class Quaternion:
    """geometry_msgs/Quaternion; defaults to the identity (w = 1), as in ROS 2."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    w: float = 1.0


@dataclass
class Transform:
    """geometry_msgs/Transform."""

    translation: Vector3 = field(default_factory=Vector3)
    rotation: Quaternion = field(default_factory=Quaternion)


@dataclass
class TransformStamped:
    """geometry_msgs/TransformStamped: the pose of ``child_frame_id`` in ``header.frame_id``."""

    header: Header = field(default_factory=Header)
    child_frame_id: str = ""
    transform: Transform = field(default_factory=Transform)


@dataclass
class Pose:
    """geometry_msgs/Pose."""

    position: Point = field(default_factory=Point)
    orientation: Quaternion = field(default_factory=Quaternion)


@dataclass
class PointStamped:
    """geometry_msgs/PointStamped."""

    header: Header = field(default_factory=Header)
    point: Point = field(default_factory=Point)


@dataclass
class PoseStamped:
    """geometry_msgs/PoseStamped."""

    header: Header = field(default_factory=Header)
    pose: Pose = field(default_factory=Pose)


@dataclass
class Vector3Stamped:
    """geometry_msgs/Vector3Stamped."""

    header: Header = field(default_factory=Header)
    vector: Vector3 = field(default_factory=Vector3)


def make_transform(parent: str, child: str, translation: Iterable[float] = (0.0, 0.0, 0.0),
                   rotation: Iterable[float] = (0.0, 0.0, 0.0, 1.0), stamp_ns: int = 0) -> TransformStamped:
    """A filled TransformStamped: ``child``'s pose in ``parent``, rotation as (x, y, z, w)."""
    tx, ty, tz = (float(v) for v in translation)
    qx, qy, qz, qw = (float(v) for v in rotation)
    return TransformStamped(
        header=Header(stamp=Time(nanoseconds=stamp_ns), frame_id=parent),
        child_frame_id=child,
        transform=Transform(Vector3(tx, ty, tz), Quaternion(qx, qy, qz, qw)),
    )
