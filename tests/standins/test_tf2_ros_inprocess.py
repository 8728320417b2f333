"""robotmodel.tf2_ros on the in-process wire: tf2_ros's layout, its exceptions after a timeout, both node styles."""

from __future__ import annotations

import threading
import time

import pytest

from robotmodel import errors, rospy, tf2_ros
from robotmodel.bus import Node
from robotmodel.msgs.geometry_msgs import TransformStamped
from robotmodel.tf2_ros.buffer import Buffer
from robotmodel.tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from robotmodel.tf2_ros.transform_broadcaster import TransformBroadcaster
from robotmodel.tf2_ros.transform_listener import TransformListener
from robotmodel.time import Duration, Time


def transform(parent: str, child: str, x: float, secs: int = 0, nsecs: int = 0) -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = parent, child
    t.header.stamp.sec, t.header.stamp.nanosec = secs, nsecs
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


def test_layout_and_distinct_exceptions() -> None:
    assert tf2_ros.Buffer is Buffer
    assert tf2_ros.TransformListener is TransformListener
    assert tf2_ros.TransformBroadcaster is TransformBroadcaster
    assert tf2_ros.StaticTransformBroadcaster is StaticTransformBroadcaster
    three = (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException)
    assert len(set(three)) == 3
    for cls in (*three, tf2_ros.InvalidArgumentException, tf2_ros.TimeoutException):
        assert issubclass(cls, tf2_ros.TransformException)
        assert getattr(errors, cls.__name__) is cls
    for a in three:
        assert not any(issubclass(a, b) for b in three if b is not a)


def failing(buffer: Buffer, *args: object) -> tuple[type[BaseException], float]:
    t0 = time.monotonic()
    with pytest.raises(tf2_ros.TransformException) as caught:
        buffer.lookup_transform(*args)  # type: ignore[arg-type]
    return caught.type, time.monotonic() - t0


@pytest.mark.parametrize("timeout", [rospy.Duration(0.3), Duration(seconds=0.3)], ids=["rospy", "rclpy"])
def test_after_the_timeout_the_lookups_own_error_not_timeout(timeout: object) -> None:
    buffer = Buffer(cache_time=rospy.Duration(100))
    buffer.set_transform(transform("world", "a", 1.0, 10), "test")
    buffer.set_transform(transform("world", "a", 1.0, 11), "test")
    buffer.set_transform(transform("island", "b", 1.0, 10), "test")
    kind, waited = failing(buffer, "world", "nowhere", rospy.Time(0), timeout)
    assert kind is tf2_ros.LookupException and waited >= 0.29
    kind, waited = failing(buffer, "world", "b", rospy.Time(0), timeout)
    assert kind is tf2_ros.ConnectivityException and waited >= 0.29
    kind, waited = failing(buffer, "world", "a", rospy.Time(20), timeout)
    assert kind is tf2_ros.ExtrapolationException and waited >= 0.29
    with pytest.raises(tf2_ros.ExtrapolationException):
        buffer.lookup_transform_full("a", rospy.Time(20), "a", rospy.Time(10), "world", timeout)
    assert not buffer.can_transform("world", "b", rospy.Time(0), timeout)
    got = buffer.lookup_transform("world", "a", rospy.Time(10, 500_000_000), timeout)
    assert (got.header.stamp.sec, got.header.stamp.nanosec) == (10, 500_000_000)


@pytest.mark.parametrize("style", ["rclpy", "rospy-times"])
def test_listener_and_broadcaster_on_a_given_node(style: str) -> None:
    with Node("tf2_ros_test", backend="inprocess", domain_id=61) as node:
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer, node)
        broadcaster = tf2_ros.TransformBroadcaster(node)
        static = tf2_ros.StaticTransformBroadcaster(node)
        latest, wait = (Time(), Duration(seconds=5)) if style == "rclpy" else (rospy.Time(0), rospy.Duration(5))
        got: list[TransformStamped] = []
        waiter = threading.Thread(target=lambda: got.append(buffer.lookup_transform("world", "tool", latest, wait)))
        waiter.start()  # waiting before anything was sent: woken by the arrival
        static.sendTransform(transform("world", "base", 1.0))
        broadcaster.sendTransform(transform("base", "tool", 0.25, 5))
        waiter.join(10)
        assert got and got[0].transform.translation.x == pytest.approx(1.25)
        assert listener.node is node
        listener.close()
        broadcaster.close()
        static.close()
