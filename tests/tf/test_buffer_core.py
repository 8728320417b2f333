"""tf2's BufferCore behaviour, from tf2's own test scenarios (buffer_core_test, simple_tf2_core, cache tests)."""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from tfhelpers import SEC, make, matrix, msg_matrix

from robotmodel.errors import RobotModelError
from robotmodel.tf import (
    Buffer,
    ConnectivityException,
    Duration,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    Time,
    TransformException,
)


@pytest.fixture
def buf() -> Buffer:
    return Buffer()


def test_exceptions_sit_under_the_single_root() -> None:
    for exc in (LookupException, ConnectivityException, ExtrapolationException, InvalidArgumentException):
        assert issubclass(exc, TransformException) and issubclass(exc, RobotModelError)


@pytest.mark.parametrize(
    ("msg", "text"),
    [
        (make("a", "a"), 'TF_SELF_TRANSFORM: Ignoring transform from authority "me" with frame_id and  child_frame_id "a" because they are the same'),
        (make("a", ""), 'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "me" because child_frame_id not set '),
        (make("", "b"), 'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "b"  from authority "me" because frame_id not set'),
        (make("a", "b", xyz=(math.nan, 0, 0)), 'TF_NAN_INPUT: Ignoring transform for child_frame_id "b" from authority "me" because of a nan value in the transform (nan 0.000000 0.000000) (0.000000 0.000000 0.000000 1.000000)'),
        (make("a", "b", quat=(0, 0, 0, 0)), 'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "b" from authority "me" because of an invalid quaternion in the transform (0.000000 0.000000 0.000000 0.000000)'),
    ],
    ids=["self", "no-child", "no-parent", "nan", "zero-quaternion"],
)
def test_invalid_inserts_are_logged_and_not_stored(buf: Buffer, msg, text: str, caplog) -> None:
    with caplog.at_level(logging.ERROR, logger="robotmodel.tf"):
        assert buf.set_transform(msg, "me") is False
    assert text in caplog.text
    assert buf.frames() == {}


def test_quaternion_normalized_and_slash_stripped_on_insert(buf: Buffer) -> None:
    buf.set_transform(make("/a", "/b", quat=(0, 0, 0, 2), sec=1), "me")
    assert buf.frames() == {"b": "a"}
    q = buf.lookup_transform("a", "b", Time()).transform.rotation
    assert (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 1.0)
    with pytest.raises(InvalidArgumentException, match=r"""Invalid argument "/a" passed to lookupTransform argument target_frame - in tf2 frame_ids cannot start with a '/'"""):
        buf.lookup_transform("/a", "b", Time())
    with pytest.raises(InvalidArgumentException, match='Invalid argument "" passed to lookupTransform argument source_frame - in tf2 frame_ids cannot be empty'):
        buf.lookup_transform("a", "", Time())


def test_unknown_frame_text(buf: Buffer) -> None:
    buf.set_transform(make("a", "b", sec=1), "me")
    with pytest.raises(LookupException) as info:
        buf.lookup_transform("a", "zz", Time())
    assert str(info.value) == '"zz" passed to lookupTransform argument source_frame does not exist. '


def test_identical_frames_shortcut_before_validation(buf: Buffer) -> None:
    out = buf.lookup_transform("nowhere", "nowhere", Time(seconds=3))
    assert out.header.stamp == Time(seconds=3).to_msg() and out.transform.rotation.w == 1.0


def test_chain_across_common_ancestor_matches_matrices(buf: Buffer) -> None:
    # a -> b -> c and a -> d -> e, all static: lookup(e, c) walks up to a and down.
    links = {("a", "b"): ((1, 0, 0), 0.3), ("b", "c"): ((0, 2, 0), -0.7),
             ("a", "d"): ((0, 0, 1), 1.1), ("d", "e"): ((3, 1, 0), 0.2)}
    for (parent, child), (xyz, yaw) in links.items():
        buf.set_transform_static(make(parent, child, xyz, yaw), "me")
    m = {k: matrix(*v) for k, v in links.items()}
    expected = np.linalg.inv(m["a", "d"] @ m["d", "e"]) @ (m["a", "b"] @ m["b", "c"])
    got = buf.lookup_transform("e", "c", Time())
    np.testing.assert_allclose(msg_matrix(got), expected, atol=1e-12)
    assert got.header.frame_id == "e" and got.child_frame_id == "c"
    assert got.header.stamp == Time().to_msg()  # static chain at time 0: stamp 0, as tf2


def test_interpolation_lerp_and_slerp(buf: Buffer) -> None:
    buf.set_transform(make("a", "b", (0, 0, 0), 0.0, sec=1), "me")
    buf.set_transform(make("a", "b", (4, -2, 8), math.pi / 2, sec=2), "me")
    got = buf.lookup_transform("a", "b", Time(seconds=1.25))
    np.testing.assert_allclose(msg_matrix(got), matrix((1, -0.5, 2), math.pi / 8), atol=1e-12)


def test_extrapolation_both_ways_with_tf2_text(buf: Buffer) -> None:
    buf.set_transform(make("a", "b", sec=10), "me")
    buf.set_transform(make("a", "b", sec=11), "me")
    with pytest.raises(ExtrapolationException) as future:
        buf.lookup_transform("a", "b", Time(seconds=12))
    assert str(future.value) == ("Lookup would require extrapolation into the future.  Requested time 12.000000 but "
                                 "the latest data is at time 11.000000, when looking up transform from frame [b] to frame [a]")
    assert (future.value.time_ns, future.value.earliest_ns, future.value.latest_ns) == (12 * SEC, 10 * SEC, 11 * SEC)
    with pytest.raises(ExtrapolationException, match=r"into the past.  Requested time 9.500000 but the earliest data is at time 10.000000"):
        buf.lookup_transform("a", "b", Time(seconds=9.5))


def test_single_sample_only_at_its_stamp(buf: Buffer) -> None:
    buf.set_transform(make("a", "b", sec=5), "me")
    assert buf.can_transform("a", "b", Time(seconds=5))
    ok, why = buf.can_transform("a", "b", Time(seconds=6), return_debug_tuple=True)
    assert not ok and why.startswith("Lookup would require extrapolation at time 6.000000, but only time 5.000000 is in the buffer")


def test_time_zero_is_latest_common_time(buf: Buffer) -> None:
    for s in (1, 2, 3):
        buf.set_transform(make("map", "odom", (s, 0, 0), sec=s), "me")
    for s in (1, 2):
        buf.set_transform(make("odom", "base", (0, s, 0), sec=s), "me")
    buf.set_transform_static(make("base", "laser", (0, 0, 1)), "me")
    got = buf.lookup_transform("map", "laser", Time())
    assert got.header.stamp == Time(seconds=2).to_msg()  # newest common to both dynamic links
    np.testing.assert_allclose(msg_matrix(got)[:3, 3], [2, 2, 1])
    assert buf.get_latest_common_time("map", "laser") == Time(seconds=2)
    assert buf.lookup_transform("base", "laser", Time()).header.stamp == Time().to_msg()


def test_static_valid_at_all_times_mixed_with_dynamic(buf: Buffer) -> None:
    buf.set_transform_static(make("base", "cam", (0.1, 0, 0.2)), "me")
    buf.set_transform(make("odom", "base", (1, 0, 0), sec=100), "me")
    buf.set_transform(make("odom", "base", (2, 0, 0), sec=101), "me")
    for t in (0.0, 1.0, 1e6):
        assert buf.lookup_transform("base", "cam", Time(seconds=t)).transform.translation.x == pytest.approx(0.1)
    got = buf.lookup_transform("odom", "cam", Time(seconds=100.5))
    np.testing.assert_allclose(msg_matrix(got)[:3, 3], [1.6, 0, 0.2], atol=1e-12)


def test_fixed_frame_lookup(buf: Buffer) -> None:
    # The robot drives along x in odom; where was the laser at t=1, seen from the base at t=3?
    for s in (1, 2, 3):
        buf.set_transform(make("odom", "base", (s, 0, 0), sec=s), "me")
    buf.set_transform_static(make("base", "laser", (0.5, 0, 0)), "me")
    got = buf.lookup_transform_full("base", Time(seconds=3), "laser", Time(seconds=1), "odom")
    np.testing.assert_allclose(msg_matrix(got)[:3, 3], [1.5 - 3, 0, 0], atol=1e-12)
    assert got.header.stamp == Time(seconds=3).to_msg()


def test_loop_is_a_lookup_exception(buf: Buffer) -> None:
    buf.set_transform_static(make("a", "b"), "me")
    buf.set_transform_static(make("b", "a"), "me")
    buf.set_transform_static(make("c", "d"), "me")
    with pytest.raises(LookupException, match=r"The tf tree is invalid because it contains a loop\.") as info:
        buf.lookup_transform("d", "a", Time())
    assert "Frame b exists with parent a." in str(info.value)


def test_not_connected(buf: Buffer) -> None:
    buf.set_transform_static(make("a", "b"), "me")
    buf.set_transform_static(make("c", "d"), "me")
    with pytest.raises(ConnectivityException) as info:
        buf.lookup_transform("b", "d", Time())
    assert str(info.value) == ("Could not find a connection between 'b' and 'd' because they are not part of the same "
                               "tree.Tf has two or more unconnected trees.")


def test_parent_change_over_time_is_never_interpolated(buf: Buffer) -> None:
    buf.set_transform_static(make("world", "a", (10, 0, 0)), "me")
    buf.set_transform_static(make("world", "b", (0, 10, 0)), "me")
    buf.set_transform(make("a", "obj", (1, 0, 0), sec=1), "me")
    buf.set_transform(make("b", "obj", (2, 0, 0), sec=3), "me")
    buf.set_transform(make("b", "obj", (2, 0, 0), sec=4), "me")
    np.testing.assert_allclose(msg_matrix(buf.lookup_transform("world", "obj", Time(seconds=2)))[:3, 3], [11, 0, 0])
    np.testing.assert_allclose(msg_matrix(buf.lookup_transform("world", "obj", Time(seconds=3.5)))[:3, 3], [2, 10, 0])


def test_cache_window_prunes_and_rejects_old_data(buf: Buffer, caplog) -> None:
    small = Buffer(cache_time=Duration(seconds=10))
    for s in range(31):
        small.set_transform(make("a", "b", sec=s + 1), "me")
    with pytest.raises(ExtrapolationException, match="into the past"):
        small.lookup_transform("a", "b", Time(seconds=5))
    assert small.can_transform("a", "b", Time(seconds=22))
    with caplog.at_level(logging.WARNING, logger="robotmodel.tf"):
        assert small.set_transform(make("a", "b", sec=3), "me") is False
    assert "TF_OLD_DATA ignoring data from the past for frame b at time 3.000000 according to authority me" in caplog.text


def test_clear_keeps_static(buf: Buffer) -> None:
    buf.set_transform_static(make("base", "cam", (0.1, 0, 0.2)), "me")
    buf.set_transform(make("odom", "base", sec=1), "me")
    buf.clear()
    assert buf.can_transform("base", "cam", Time())
    with pytest.raises(ConnectivityException):
        buf.lookup_transform("odom", "cam", Time())
    assert buf.all_frames_as_string() == "Frame cam exists with parent base.\nFrame base exists with parent NO_PARENT.\n"


def test_yaml_lists_frames_with_rates(buf: Buffer) -> None:
    import yaml

    buf.set_transform_static(make("base", "cam"), "static_pub")
    for s in range(5):
        buf.set_transform(make("odom", "base", sec=1 + s * 0.5), "odom_pub")
    data = yaml.safe_load(buf.all_frames_as_yaml())
    assert data["cam"] == {"parent": "base", "broadcaster": "static_pub", "rate": 10000.0,
                           "most_recent_transform": 0.0, "oldest_transform": 0.0, "buffer_length": 0.0}
    assert data["base"]["rate"] == pytest.approx(5 / 2.0) and data["base"]["buffer_length"] == 2.0
    assert Buffer().all_frames_as_yaml() == "[]"
