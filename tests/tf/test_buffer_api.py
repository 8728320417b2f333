"""tf2_ros-style API: messages, waiting with timeouts, threads, transform(), vectorized lookups, seeds."""

from __future__ import annotations

import itertools
import math
import threading
import time

import numpy as np
import pytest
from tfhelpers import SEC, make, matrix, msg_matrix

from robotmodel.tf import (
    Buffer,
    Duration,
    ExtrapolationException,
    Header,
    PointStamped,
    PoseStamped,
    Time,
    TimeoutException,
    TransformStamped,
    Vector3Stamped,
)


def test_messages_have_ros2_paths_and_defaults() -> None:
    t = TransformStamped()
    assert (t.header.stamp.sec, t.header.stamp.nanosec, t.header.frame_id, t.child_frame_id) == (0, 0, "", "")
    assert (t.transform.rotation.x, t.transform.rotation.w) == (0.0, 1.0)
    t.header.stamp.sec = 3
    t.header.stamp.nanosec = 500
    assert Time.from_msg(t.header.stamp).nanoseconds == 3 * SEC + 500
    assert Time(seconds=1.5).seconds_nanoseconds() == (1, 500_000_000)
    assert Time(seconds=2, nanoseconds=5).nanoseconds == 2 * SEC + 5
    assert Duration(seconds=0.25).nanoseconds == SEC // 4
    assert PoseStamped().pose.orientation.w == 1.0


def test_lookup_message_equals_the_constructed_one_field_by_field() -> None:
    # lookup_transform builds its message without the dataclass constructors (for speed): every
    # field of every nested message must still be set, a field added later included.
    import dataclasses

    from robotmodel.msgs import Quaternion, Transform, Vector3
    from robotmodel.msgs.builtin_interfaces import Time as StampMsg

    (x, y, z), (qx, qy, qz, qw) = (0.5, 0.0, 0.0), (0.0, 0.0, math.sin(0.2), math.cos(0.2))
    sent = make("map", "tool", (x, y, z), quat=(qx, qy, qz, qw))
    sent.header.stamp = StampMsg(sec=2, nanosec=7)
    buf = Buffer()
    buf.set_transform(sent, "a")
    got = buf.lookup_transform("map", "tool", Time(nanoseconds=2 * SEC + 7))
    want = TransformStamped(header=Header(stamp=StampMsg(sec=2, nanosec=7), frame_id="map"), child_frame_id="tool",
                            transform=Transform(translation=Vector3(x=x, y=y, z=z),
                                                rotation=Quaternion(x=qx, y=qy, z=qz, w=qw)))

    def same(a: object, b: object) -> None:
        assert type(a) is type(b)
        if not dataclasses.is_dataclass(a):
            assert a == pytest.approx(b, abs=1e-15)
            return
        for f in dataclasses.fields(a):
            same(getattr(a, f.name), getattr(b, f.name))  # AttributeError if one was never set

    same(got, want)


def test_lookup_waits_for_data_from_another_thread() -> None:
    buf = Buffer()

    def later() -> None:
        time.sleep(0.2)
        buf.set_transform(make("map", "robot", (1, 2, 3), sec=1), "writer")

    threading.Thread(target=later).start()
    got = buf.lookup_transform("map", "robot", Time(), timeout=Duration(seconds=5))
    assert (got.transform.translation.x, got.transform.translation.z) == (1.0, 3.0)


def test_timeout_raises_timeout_exception_with_reason() -> None:
    buf = Buffer()
    buf.set_transform(make("map", "robot", sec=1), "writer")
    with pytest.raises(TimeoutException, match=r"extrapolation at time 2\.000000, but only time 1\.000000") as info:
        buf.lookup_transform("map", "robot", Time(seconds=2), timeout=Duration(seconds=0.2))
    assert info.value.latest_ns == SEC
    assert buf.can_transform("map", "robot", Time(seconds=2), timeout=Duration(seconds=0.05)) is False


def test_many_writers_and_readers() -> None:
    buf = Buffer()
    errors: list[BaseException] = []
    buf.set_transform_static(make("base", "cam", (0.1, 0, 0.2)), "static")

    def writer(k: int) -> None:
        for i in range(300):
            buf.set_transform(make("odom", f"base{k}" if k else "base", (i, 0, 0), sec=1 + i * 0.01), f"w{k}")

    def reader() -> None:
        try:
            for _ in range(300):
                if buf.can_transform("odom", "cam", Time()):
                    got = buf.lookup_transform("odom", "cam", Time())
                    assert got.transform.translation.z == pytest.approx(0.2)
        except BaseException as exc:  # surfaced below
            errors.append(exc)

    threads = [threading.Thread(target=writer, args=(k,)) for k in range(3)] + [
        threading.Thread(target=reader) for _ in range(3)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert errors == []
    got = buf.lookup_transform("odom", "cam", Time())
    assert got.transform.translation.x == pytest.approx(299.1)


def test_transform_stamped_objects() -> None:
    buf = Buffer()
    buf.set_transform(make("map", "base", (1, 2, 0), math.pi / 2, sec=5), "me")
    stamp = Time(seconds=5)
    point = buf.transform(PointStamped(header=Header(stamp=stamp, frame_id="base")), "map")
    assert point.header.frame_id == "map"
    np.testing.assert_allclose([point.point.x, point.point.y, point.point.z], [1, 2, 0], atol=1e-12)
    vec = Vector3Stamped(header=Header(stamp=stamp, frame_id="base"))
    vec.vector.x = 1.0
    out = buf.transform(vec, "map")
    np.testing.assert_allclose([out.vector.x, out.vector.y], [0, 1], atol=1e-12)  # rotated, not translated
    pose = PoseStamped(header=Header(stamp=stamp, frame_id="base"))
    pose.pose.position.x = 1.0
    res = buf.transform(pose, "map")
    expected = matrix((1, 2, 0), math.pi / 2) @ matrix((1, 0, 0), 0.0)
    np.testing.assert_allclose([res.pose.position.x, res.pose.position.y], expected[:2, 3], atol=1e-12)
    assert res.pose.orientation.z == pytest.approx(math.sin(math.pi / 4))


def _moving_buffer() -> Buffer:
    buf = Buffer()
    rng = np.random.default_rng(4)
    chain = ["map", "odom", "base", "arm", "wrist", "tool"]
    for s in range(1, 21):
        for parent, child in itertools.pairwise(chain):
            buf.set_transform(make(parent, child, tuple(rng.uniform(-1, 1, 3)), rng.uniform(-3, 3), sec=s * 0.5), "me")
    buf.set_transform_static(make("tool", "cam", (0.1, 0, 0.2)), "me")
    return buf


def test_vectorized_lookups_equal_single_lookups() -> None:
    buf = _moving_buffer()
    stamps = np.concatenate([np.random.default_rng(1).integers(SEC // 2, 10 * SEC, 200), [0, SEC // 2, 10 * SEC]])
    translations, quats = buf.lookup_transforms("cam", "map", stamps)
    for k, s in enumerate(stamps):
        single = buf.lookup_transform("cam", "map", Time(nanoseconds=int(s)))
        tr, q = single.transform.translation, single.transform.rotation
        np.testing.assert_allclose(translations[k], [tr.x, tr.y, tr.z], atol=1e-12)
        np.testing.assert_allclose(quats[k], [q.x, q.y, q.z, q.w], atol=1e-12)


def test_vectorized_lookups_raise_like_single_ones() -> None:
    buf = _moving_buffer()
    with pytest.raises(ExtrapolationException, match="into the future"):
        buf.lookup_transforms("cam", "map", [SEC, 11 * SEC])


def test_vectorized_lookups_across_parent_change() -> None:
    buf = Buffer()
    buf.set_transform_static(make("world", "a", (10, 0, 0)), "me")
    buf.set_transform_static(make("world", "b", (0, 10, 0)), "me")
    buf.set_transform(make("a", "obj", (1, 0, 0), sec=1), "me")
    buf.set_transform(make("a", "obj", (1, 0, 0), sec=2), "me")
    buf.set_transform(make("b", "obj", (2, 0, 0), sec=3), "me")
    buf.set_transform(make("b", "obj", (2, 0, 0), sec=4), "me")
    translations, _ = buf.lookup_transforms("world", "obj", [int(1.5 * SEC), int(3.5 * SEC)])
    np.testing.assert_allclose(translations, [[11, 0, 0], [2, 10, 0]])


def test_seed_broadcaster_and_listener() -> None:
    # The tf2 tutorials' tree: map -> odom -> base_link -> {laser_link, camera_link}.
    buf = Buffer()
    buf.set_transform_static(make("base_link", "camera_link", (0.1, 0.0, 0.2)), "static_transform_publisher")
    buf.set_transform_static(make("base_link", "laser_link", (0.0, 0.0, 0.3)), "static_transform_publisher")
    buf.set_transform_static(make("map", "odom", (0.0, 0.0, 0.0)), "map_server")
    for i in range(11):
        t = i * 0.1
        buf.set_transform(make("odom", "base_link", (t, 0.0, 0.0), yaw=t, sec=100 + t), "odometry")
    cam = buf.lookup_transform("map", "camera_link", Time(seconds=100.5))
    expected = matrix((0.5, 0, 0), 0.5) @ matrix((0.1, 0, 0.2), 0.0)
    np.testing.assert_allclose(msg_matrix(cam), expected, atol=1e-9)
    laser_in_cam = buf.lookup_transform("camera_link", "laser_link", Time())
    np.testing.assert_allclose(msg_matrix(laser_in_cam)[:3, 3], [-0.1, 0.0, 0.1], atol=1e-12)
