"""The tf Buffer takes every time form rclpy code hands it: messages, Time, rclpy-like objects."""

from __future__ import annotations

import pytest
from rosbags.typesys import Stores, get_typestore

from robotmodel import tf
from robotmodel.msgs import builtin_interfaces, make_transform
from robotmodel.time import Duration, Time

SEC = 1_000_000_000


class RclpyLikeTime:
    """What rclpy's Time looks like to duck typing: only ``.nanoseconds``."""

    def __init__(self, ns: int) -> None:
        self.nanoseconds = ns


def test_tf_exports_the_immutable_time() -> None:
    assert tf.Time is Time and tf.Duration is Duration
    stamp = tf.TransformStamped().header.stamp
    assert isinstance(stamp, builtin_interfaces.Time)
    stamp.sec = 5  # messages stay mutable
    assert tf.TransformStamped().header.stamp.sec == 0  # and do not share a default


@pytest.mark.parametrize("make_stamp", [
    lambda ns: builtin_interfaces.Time(sec=ns // SEC, nanosec=ns % SEC),
    lambda ns: Time(nanoseconds=ns),
    RclpyLikeTime,
    lambda ns: get_typestore(Stores.ROS2_JAZZY).types["builtin_interfaces/msg/Time"](sec=ns // SEC, nanosec=ns % SEC),
], ids=["message", "Time", "rclpy-like", "rosbags"])
def test_buffer_accepts_every_stamp_form(make_stamp: object) -> None:
    buf = tf.Buffer()
    for k, x in ((1, 1.0), (2, 2.0)):
        t = make_transform("map", "robot", (x, 0.0, 0.0))
        t.header.stamp = make_stamp(k * SEC)  # type: ignore[operator]
        assert buf.set_transform(t, "test")
    query = make_stamp(3 * SEC // 2)  # type: ignore[operator]
    got = buf.lookup_transform("map", "robot", query, timeout=Duration(seconds=1))
    assert got.transform.translation.x == pytest.approx(1.5)
    assert got.header.stamp == builtin_interfaces.Time(sec=1, nanosec=500_000_000)
    assert buf.can_transform("map", "robot", query, timeout=RclpyLikeTime(0))
    assert buf.get_latest_common_time("map", "robot") == Time(seconds=2)


def test_transform_keeps_the_stamp_as_a_message() -> None:
    buf = tf.Buffer()
    buf.set_transform_static(make_transform("map", "base", (1.0, 0.0, 0.0)), "test")
    point = tf.PointStamped(header=tf.Header(stamp=Time(seconds=4).to_msg(), frame_id="base"))
    out = buf.transform(point, "map")
    assert out.point.x == pytest.approx(1.0)
    assert out.header.stamp == builtin_interfaces.Time(sec=4) and out.header.frame_id == "map"
