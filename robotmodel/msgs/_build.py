"""Builders for messages that code fills often."""

from __future__ import annotations

from collections.abc import Iterable

from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.msgs.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
from robotmodel.msgs.std_msgs import Header

__all__ = ["make_transform", "stamp"]

_NS = 1_000_000_000


def stamp(nanoseconds: int) -> Time:
    """A builtin_interfaces Time message for integer nanoseconds since the epoch."""
    sec, nanosec = divmod(int(nanoseconds), _NS)
    return Time(sec=sec, nanosec=nanosec)


def make_transform(parent: str, child: str, translation: Iterable[float] = (0.0, 0.0, 0.0),
                   rotation: Iterable[float] = (0.0, 0.0, 0.0, 1.0), stamp_ns: int = 0) -> TransformStamped:
    """A filled TransformStamped: ``child``'s pose in ``parent``, rotation as (x, y, z, w)."""
    tx, ty, tz = (float(v) for v in translation)
    qx, qy, qz, qw = (float(v) for v in rotation)
    return TransformStamped(
        header=Header(stamp=stamp(stamp_ns), frame_id=parent),
        child_frame_id=child,
        transform=Transform(Vector3(tx, ty, tz), Quaternion(qx, qy, qz, qw)),
    )
