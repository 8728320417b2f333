"""Time and Duration: rclpy's constructors, texts and arithmetic; immutable and hashable."""

from __future__ import annotations

import pickle
import re
from datetime import datetime

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from rosbags.typesys import Stores, get_typestore

from robotmodel.msgs import builtin_interfaces
from robotmodel.time import Duration, Time, to_nanoseconds

SEC = 1_000_000_000
INT64_MAX = 2**63 - 1

times_ns = st.integers(0, INT64_MAX)
durations_ns = st.integers(-(2**63), INT64_MAX)


def test_construction_matches_rclpy() -> None:
    assert Time().nanoseconds == 0
    assert Time(seconds=1.5).nanoseconds == 1_500_000_000
    assert Time(seconds=2, nanoseconds=5).nanoseconds == 2 * SEC + 5
    assert Time(seconds=1.5).seconds_nanoseconds() == (1, 500_000_000)
    # rclpy truncates seconds * 1e9 (1.005 * 1e9 == 1004999999.9999999 in binary floating point).
    assert Time(seconds=1.005).nanoseconds == 1_004_999_999
    assert Duration(seconds=-0.5).nanoseconds == -500_000_000
    assert Duration(seconds=1, nanoseconds=-1).nanoseconds == SEC - 1


def test_keyword_only_as_rclpy() -> None:
    with pytest.raises(TypeError):
        Time(1)  # type: ignore[misc]
    with pytest.raises(TypeError):
        Duration(1)  # type: ignore[misc]


@pytest.mark.parametrize(("kwargs", "error", "text"), [
    ({"seconds": -1}, ValueError, "Seconds value must not be negative"),
    ({"nanoseconds": -1}, ValueError, "Nanoseconds value must not be negative"),
    ({"nanoseconds": 2**63}, OverflowError, "Total nanoseconds value is too large to store in C time point."),
    ({"seconds": 9_300_000_000}, OverflowError, "too large"),
])
def test_time_rejects_what_rclpy_rejects(kwargs: dict[str, int], error: type[Exception], text: str) -> None:
    with pytest.raises(error, match=text):
        Time(**kwargs)


def test_duration_range_is_int64() -> None:
    assert Duration(nanoseconds=-(2**63)).nanoseconds == -(2**63)
    assert Duration(nanoseconds=INT64_MAX).nanoseconds == INT64_MAX
    for bad in (2**63, -(2**63) - 1):
        with pytest.raises(OverflowError, match="too large to store in C duration"):
            Duration(nanoseconds=bad)


def test_immutable_and_hashable() -> None:
    t = Time(seconds=3)
    with pytest.raises(AttributeError, match="immutable"):
        t._ns = 5  # type: ignore[misc]
    with pytest.raises(AttributeError):
        t.nanoseconds = 5  # type: ignore[misc]
    with pytest.raises(AttributeError, match="immutable"):
        Duration(seconds=1).sec = 2  # type: ignore[attr-defined]
    assert t.nanoseconds == 3 * SEC
    seen = {Time(seconds=3): "a", Duration(seconds=3): "b"}
    assert seen[Time(nanoseconds=3 * SEC)] == "a" and seen[Duration(nanoseconds=3 * SEC)] == "b"
    assert len({Time(seconds=1), Time(nanoseconds=SEC), Time(seconds=2)}) == 2
    assert pickle.loads(pickle.dumps(t)) == t
    assert pickle.loads(pickle.dumps(Duration(nanoseconds=-7))) == Duration(nanoseconds=-7)


def test_arithmetic() -> None:
    t = Time(seconds=10)
    d = Duration(seconds=2.5)
    assert t + d == Time(seconds=12.5) == d + t
    assert t - d == Time(seconds=7.5)
    assert t - Time(seconds=12) == Duration(seconds=-2)
    assert d + d == Duration(seconds=5) and d - d == Duration()
    assert d * 2 == Duration(seconds=5) == 2 * d
    assert d * 0.5 == Duration(seconds=1.25)
    assert -d == Duration(seconds=-2.5)
    with pytest.raises(ValueError, match=re.escape("Subtraction leads to negative time.")):
        t - Duration(seconds=11)
    with pytest.raises(ValueError, match="Nanoseconds value must not be negative"):
        t + Duration(seconds=-11)
    with pytest.raises(OverflowError, match=re.escape("Addition leads to overflow in C storage.")):
        Time(nanoseconds=INT64_MAX) + Duration(nanoseconds=1)
    with pytest.raises(ValueError, match="nan"):
        d * float("nan")
    with pytest.raises(TypeError):
        t + t  # type: ignore[operator]
    with pytest.raises(TypeError):
        t + 1  # type: ignore[operator]


def test_ordering_within_a_kind_only() -> None:
    assert Time(seconds=1) < Time(seconds=2) <= Time(seconds=2) < Time(seconds=3) > Time() >= Time()
    assert Duration(seconds=-1) < Duration() <= Duration() < Duration(nanoseconds=1)
    assert sorted([Time(seconds=3), Time(), Time(seconds=1)]) == [Time(), Time(seconds=1), Time(seconds=3)]
    assert Time(seconds=1) != Duration(seconds=1)
    assert Time(seconds=1) != 1_000_000_000
    with pytest.raises(TypeError):
        _ = Time() < Duration()  # type: ignore[operator]
    with pytest.raises(TypeError):
        _ = Time() < 5  # type: ignore[operator]


def test_to_datetime_as_rclpy() -> None:
    assert Time(seconds=1_700_000_000.25).to_datetime() == datetime.fromtimestamp(1_700_000_000.25)


def test_repr_and_str_as_rclpy() -> None:
    assert repr(Duration(seconds=1)) == "Duration(nanoseconds=1000000000)"
    assert str(Duration(nanoseconds=5)) == "5 nanoseconds"
    assert repr(Time(nanoseconds=7)) == "Time(nanoseconds=7)"


@settings(deadline=None)  # a loaded machine must not fail a correct test
@given(times_ns)
def test_time_message_round_trip(ns: int) -> None:
    t = Time(nanoseconds=ns)
    msg = t.to_msg()
    assert isinstance(msg, builtin_interfaces.Time)
    assert (msg.sec, msg.nanosec) == (ns // SEC, ns % SEC)
    assert Time.from_msg(msg) == t
    assert to_nanoseconds(msg) == ns == to_nanoseconds(t)


@settings(deadline=None)
@given(durations_ns)
def test_duration_message_round_trip(ns: int) -> None:
    d = Duration(nanoseconds=ns)
    msg = d.to_msg()
    assert isinstance(msg, builtin_interfaces.Duration)
    assert 0 <= msg.nanosec < SEC and msg.sec * SEC + msg.nanosec == ns  # rclpy's divmod split
    assert Duration.from_msg(msg) == d
    assert to_nanoseconds(msg) == ns == to_nanoseconds(d)


def test_negative_duration_message_as_rclpy() -> None:
    msg = Duration(nanoseconds=-1).to_msg()
    assert (msg.sec, msg.nanosec) == (-1, 999_999_999)


def test_to_msg_gives_a_new_mutable_message() -> None:
    t = Time(seconds=1)
    msg = t.to_msg()
    msg.sec = 5
    assert t == Time(seconds=1) and t.to_msg().sec == 1


def test_from_msg_takes_other_libraries_messages() -> None:
    store = get_typestore(Stores.ROS2_JAZZY)
    rb = store.types["builtin_interfaces/msg/Time"](sec=4, nanosec=7)
    assert Time.from_msg(rb) == Time(seconds=4, nanoseconds=7)
    with pytest.raises(TypeError, match=re.escape("Must pass a builtin_interfaces.msg.Time object")):
        Time.from_msg(Time(seconds=1))
    with pytest.raises(TypeError, match=re.escape("Must pass a builtin_interfaces.msg.Duration object")):
        Duration.from_msg(3)
    with pytest.raises(TypeError, match=re.escape("Must pass a builtin_interfaces.msg.Duration object")):
        Duration.from_msg(builtin_interfaces.Time(sec=1))
    with pytest.raises(TypeError, match=re.escape("Must pass a builtin_interfaces.msg.Time object")):
        Time.from_msg(store.types["builtin_interfaces/msg/Duration"](sec=1, nanosec=0))

    class RclpyStamp:  # rclpy's messages carry no type name: the fields stand for it
        sec, nanosec = 2, 3

    assert Time.from_msg(RclpyStamp()) == Time(seconds=2, nanoseconds=3)
    with pytest.raises(ValueError, match="Seconds value must not be negative"):
        Time.from_msg(builtin_interfaces.Time(sec=-1))


def test_to_nanoseconds_takes_every_time_form() -> None:
    class RclpyLike:
        nanoseconds = 42

    assert to_nanoseconds(RclpyLike()) == 42
    assert to_nanoseconds(builtin_interfaces.Duration(sec=-2, nanosec=5)) == -2 * SEC + 5
    with pytest.raises(TypeError, match="a time must have sec and nanosec, or nanoseconds; got float"):
        to_nanoseconds(1.5)


def test_parse_seconds_is_exact_and_bounded_to_tf2s_range() -> None:
    from robotmodel.time import parse_seconds

    assert parse_seconds("1700000000.123456789") == 1_700_000_000_123_456_789
    assert parse_seconds(" 1e3 ") == 1000 * 10**9
    assert parse_seconds("0.0000000019") == 1  # truncated toward zero, as rclpy's Time(seconds=...)
    assert parse_seconds("9223372036.854775807") == 2**63 - 1
    assert parse_seconds("-9223372036.854775808", signed=True) == -(2**63)
    for text, signed in (("9223372036.854775808", False), ("1e300", False), ("1e300", True), ("-1", False),
                         ("1e999999999", False), ("-9223372036.854775809", True)):
        with pytest.raises(ValueError, match="out of range"):
            parse_seconds(text, signed=signed)
    for text in ("soon", "nan", "inf", ""):
        with pytest.raises(ValueError, match="number of seconds"):
            parse_seconds(text)
