"""Regression tests: duplicated oldest stamp in vectorized lookups, invalid stamps, extrapolation direction."""

from __future__ import annotations

import math

import numpy as np
import pytest
from tfhelpers import SEC, make

from robotmodel.errors import ExtrapolationDirection, TransformException
from robotmodel.msgs import builtin_interfaces
from robotmodel.tf import Buffer, ExtrapolationException, InvalidArgumentException, Time


def test_vectorized_lookup_takes_the_older_sample_at_a_duplicated_oldest_stamp() -> None:
    buf = Buffer()
    buf.set_transform(make("a", "b", (1, 0, 0), sec=1), "me")
    buf.set_transform(make("a", "b", (2, 0, 0), sec=1), "me")  # same stamp, other data: both kept (tf2)
    buf.set_transform(make("a", "b", (5, 0, 0), sec=2), "me")
    # tf2 returns the earliest-inserted sample at the oldest stamp, the newest-inserted elsewhere.
    assert buf.lookup_transform("a", "b", Time(seconds=1)).transform.translation.x == 1.0
    assert buf.lookup_transform("a", "b", Time(seconds=1.5)).transform.translation.x == 3.5
    translations, _ = buf.lookup_transforms("a", "b", [SEC, SEC + SEC // 2, 2 * SEC])
    np.testing.assert_array_equal(translations[:, 0], [1.0, 3.5, 5.0])


def test_vectorized_equals_scalar_with_duplicated_stamps_everywhere() -> None:
    buf = Buffer()
    for s in (1, 1, 2, 3, 3, 3, 4, 4):
        buf.set_transform(make("a", "b", (s + len(buf.frames()) * 0.0 + np.random.default_rng(s).random(), 0, 0),
                               yaw=s * 0.1, sec=s), "me")
    buf.set_transform(make("a", "b", (9, 0, 0), sec=3), "me")
    stamps = [SEC, 2 * SEC, 3 * SEC, 4 * SEC, int(2.5 * SEC), int(3.5 * SEC)]
    translations, quats = buf.lookup_transforms("a", "b", stamps)
    for k, s in enumerate(stamps):
        single = buf.lookup_transform("a", "b", Time(nanoseconds=s)).transform
        assert translations[k, 0] == pytest.approx(single.translation.x, abs=1e-12)
        assert quats[k, 2] == pytest.approx(single.rotation.z, abs=1e-12)


def _msg_with_stamp(sec: int, nanosec: int = 0):
    msg = make("a", "b", sec=1)
    msg.header.stamp.sec = sec
    msg.header.stamp.nanosec = nanosec
    return msg


@pytest.mark.parametrize(("sec", "nanosec"), [(-5, 0), (0, -1), (2**34, 0), (9_223_372_036, 854_775_808)],
                         ids=["negative-sec", "negative-nanosec", "sec-2^34", "exactly-2^63"])
def test_invalid_stamps_rejected_on_insert(sec: int, nanosec: int) -> None:
    buf = Buffer()
    with pytest.raises(InvalidArgumentException, match='child_frame_id "b"'):
        buf.set_transform(_msg_with_stamp(sec, nanosec), "me")
    with pytest.raises(InvalidArgumentException):
        buf.insert("a", "b", sec * SEC + nanosec, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), "me")
    assert buf.frames() == {}
    # Nothing half-stored: the buffer still answers, with tf2 exceptions and bools only.
    assert buf.can_transform("a", "b", Time()) is False
    buf.set_transform(make("a", "b", sec=1), "me")
    assert buf.lookup_transform("a", "b", Time()).header.stamp.sec == 1


def test_largest_valid_stamp_is_kept_and_reported_exactly() -> None:
    buf = Buffer()
    top = 2**63 - 1
    buf.insert("a", "b", top, (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), "me")
    got = buf.lookup_transform("a", "b", Time())
    assert got.header.stamp.sec * SEC + got.header.stamp.nanosec == top


@pytest.mark.parametrize("when", [builtin_interfaces.Time(sec=-5), builtin_interfaces.Time(sec=2**34),
                                  builtin_interfaces.Time(nanosec=-3), "soon", None, math.nan],
                         ids=["negative", "beyond-2^63", "negative-nanosec", "string", "none", "nan"])
def test_invalid_lookup_times_are_tf2_exceptions_and_can_transform_is_a_bool(when) -> None:
    buf = Buffer()
    buf.set_transform(make("a", "b", sec=1), "me")
    with pytest.raises(TransformException):
        buf.lookup_transform("a", "b", when)
    with pytest.raises(TransformException):
        buf.lookup_transform_full("a", when, "b", Time(), "a")
    assert buf.can_transform("a", "b", when) is False
    ok, why = buf.can_transform("a", "b", when, return_debug_tuple=True)
    assert ok is False and why
    assert buf.can_transform_full("a", when, "b", Time(), "a") is False
    if isinstance(when, str | float):  # not a duration at all (a negative timeout just does not wait)
        with pytest.raises(TransformException):
            buf.lookup_transform("a", "b", Time(), timeout=when)


@pytest.mark.parametrize("stamps", [[-1], [2**63], [math.nan], ["x"]], ids=["negative", "2^63", "nan", "text"])
def test_invalid_vectorized_stamps_are_invalid_argument(stamps) -> None:
    buf = Buffer()
    buf.set_transform(make("a", "b", sec=1), "me")
    with pytest.raises(InvalidArgumentException):
        buf.lookup_transforms("a", "b", stamps)


def test_extrapolation_exception_says_its_direction() -> None:
    buf = Buffer()
    buf.set_transform(make("a", "b", sec=10), "me")
    with pytest.raises(ExtrapolationException, match=r"but only time 10\.000000") as info:
        buf.lookup_transform("a", "b", Time(seconds=11))
    assert info.value.direction is ExtrapolationDirection.NO_DATA
    buf.set_transform(make("a", "b", sec=11), "me")
    with pytest.raises(ExtrapolationException, match="into the future") as info:
        buf.lookup_transform("a", "b", Time(seconds=12))
    assert info.value.direction is ExtrapolationDirection.FORWARD
    with pytest.raises(ExtrapolationException, match="into the past") as info:
        buf.lookup_transform("a", "b", Time(seconds=9))
    assert info.value.direction is ExtrapolationDirection.BACKWARD
    with pytest.raises(ExtrapolationException, match="into the future") as info:
        buf.lookup_transforms("a", "b", [10 * SEC, 12 * SEC])
    assert info.value.direction is ExtrapolationDirection.FORWARD
    buf.clear()
    with pytest.raises(ExtrapolationException, match=r"but only time 0\.000000") as info:
        buf.lookup_transform("a", "b", Time(seconds=11))
    assert info.value.direction is ExtrapolationDirection.NO_DATA


def test_malformed_inputs_are_tf2_exceptions() -> None:
    buf = Buffer()
    with pytest.raises(InvalidArgumentException, match="not a TransformStamped"):
        buf.set_transform(object(), "me")
    with pytest.raises(InvalidArgumentException, match="frame ids must be strings"):
        buf.insert(None, "b", SEC, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), "me")
    with pytest.raises(InvalidArgumentException, match="frame_id is a string"):
        buf.lookup_transform(3, "b", Time())
    assert buf.can_transform(None, "b", Time()) is False
    buf.set_transform(make("a", "b", sec=1), "me")
    with pytest.raises(InvalidArgumentException, match="Type str is not loaded or supported"):
        buf.transform("not a stamped message", "a")
