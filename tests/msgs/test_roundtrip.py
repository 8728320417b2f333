"""Messages <-> rosbags' Jazzy types <-> CDR: lossless round trips, stamp limits, range errors."""

from __future__ import annotations

import enum
import math
import struct
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from msgstrategies import CLASSES, STORE, message_strategy
from rosbags.typesys import Stores, get_typestore

from robotmodel.errors import MessageError
from robotmodel.msgs import (
    Header,
    JointState,
    Odometry,
    TFMessage,
    TransformStamped,
    builtin_interfaces,
    deserialize,
    from_rosbags,
    make_transform,
    rosgraph_msgs,
    serialize,
    to_rosbags,
    type_hash,
)
from robotmodel.msgs._convert import _struct_converter
from robotmodel.time import Time

MSGTYPES = [c.__msgtype__ for c in CLASSES]
INT32 = (-(2**31), 2**31 - 1)
UINT32_MAX = 2**32 - 1


@pytest.mark.parametrize("msgtype", MSGTYPES)
@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_random_messages_round_trip_through_rosbags_and_cdr(msgtype: str, data: st.DataObject) -> None:
    msg = data.draw(message_strategy(msgtype))
    obj = to_rosbags(msg)
    assert type(obj) is STORE.types[msgtype]
    raw = bytes(STORE.serialize_cdr(obj, msgtype))
    checked = _struct_converter(STORE, msgtype)(msg)  # the slow, field-by-field checked path
    assert bytes(STORE.serialize_cdr(checked, msgtype)) == raw
    assert from_rosbags(STORE.deserialize_cdr(raw, msgtype)) == msg
    assert serialize(msg) == raw  # TFMessage takes the hand-written codec: same bytes
    assert deserialize(raw, msgtype) == msg
    assert deserialize(raw, type(msg)) == msg


@pytest.mark.parametrize("sec", [INT32[0], -1, 0, INT32[1]])
@pytest.mark.parametrize("nanosec", [0, 999_999_999, UINT32_MAX])
def test_stamps_at_int32_uint32_limits_round_trip_exactly(sec: int, nanosec: int) -> None:
    stamp = builtin_interfaces.Time(sec=sec, nanosec=nanosec)
    t = make_transform("map", "base", (1.0, 2.0, 3.0))
    t.header.stamp = stamp
    messages: list[Any] = [
        TFMessage([t]), t, JointState(header=Header(stamp=stamp)), rosgraph_msgs.Clock(clock=stamp), stamp,
        builtin_interfaces.Duration(sec=sec, nanosec=nanosec),
    ]
    for msg in messages:
        raw = serialize(msg)
        back = deserialize(raw, type(msg))
        assert back == msg
        rb = STORE.deserialize_cdr(raw, msg.__msgtype__)  # rosbags reads the same numbers from our bytes
        rb_stamp = rb if msg is stamp or type(msg) is builtin_interfaces.Duration else None
        if type(msg) is TFMessage:
            rb_stamp = rb.transforms[0].header.stamp
        elif type(msg) is rosgraph_msgs.Clock:
            rb_stamp = rb.clock
        elif rb_stamp is None:
            rb_stamp = rb.header.stamp
        assert (rb_stamp.sec, rb_stamp.nanosec) == (sec, nanosec)


def _tf_with_stamp(sec: Any, nanosec: Any) -> TFMessage:
    t = make_transform("map", "base")
    t.header.stamp.sec, t.header.stamp.nanosec = sec, nanosec
    return TFMessage([make_transform("a", "b"), t])


@pytest.mark.parametrize(("msg", "text"), [
    (_tf_with_stamp(2**31, 0), r"^tf2_msgs/msg/TFMessage\.transforms\[1\]\.header\.stamp\.sec: 2147483648 is out of "
                               r"range for int32 \[-2147483648, 2147483647\]$"),
    (_tf_with_stamp(-(2**31) - 1, 0), r"transforms\[1\]\.header\.stamp\.sec: -2147483649 is out of range for int32"),
    (_tf_with_stamp(0, -1), r"transforms\[1\]\.header\.stamp\.nanosec: -1 is out of range for uint32 \[0, 4294967295\]"),
    (_tf_with_stamp(0, 2**32), r"transforms\[1\]\.header\.stamp\.nanosec: 4294967296 is out of range for uint32"),
    (_tf_with_stamp(1.5, 0), r"transforms\[1\]\.header\.stamp\.sec: 1\.5 is not an integer \(int32\)"),
    (builtin_interfaces.Time(sec=2**31), r"^builtin_interfaces/msg/Time\.sec: 2147483648 is out of range for int32"),
    (JointState(position=[1.0, "x"]), r"^sensor_msgs/msg/JointState\.position\[1\]: 'x' is not a number \(float64\)$"),
    (JointState(position=["1.5"]), r"JointState\.position\[0\]: '1\.5' is not a number"),
    (JointState(name=["a", 3]), r"JointState\.name\[1\]: 3 is not a str$"),
    (JointState(name="abc"), r"JointState\.name: 'abc' is not a sequence of string$"),
    (JointState(position=5), r"JointState\.position: 5 is not a sequence of float64$"),
    (JointState(effort=(float(x) for x in "12")), r"JointState\.effort: <generator .*> is not a sequence of float64$"),
    (TFMessage(transforms=iter([TransformStamped()])), r"transforms: <list_iterator .*> is not a sequence of geometry_"),
    (Odometry(child_frame_id=None), r"^nav_msgs/msg/Odometry\.child_frame_id: None is not a str$"),
    (TFMessage([TransformStamped(), "x"]), r"transforms\[1\]: a str is not a geometry_msgs/msg/TransformStamped"),
    (TFMessage([TransformStamped(child_frame_id=b"x")]), r"transforms\[0\]\.child_frame_id: b'x' is not a str"),
    (TransformStamped(Header(stamp=Time(seconds=1))),  # type: ignore[arg-type]
     r"TransformStamped\.header\.stamp: a Time is not a builtin_interfaces/msg/Time \(no field 'sec'\)"),
], ids=lambda v: "" if isinstance(v, str) else type(v).__name__)
def test_out_of_range_values_are_rejected_naming_the_field(msg: Any, text: str) -> None:
    with pytest.raises(MessageError, match=text):
        serialize(msg)
    with pytest.raises(MessageError, match=text):
        to_rosbags(msg)


def test_covariance_needs_36_values() -> None:
    odom = Odometry()
    odom.pose.covariance = [0.0] * 35
    with pytest.raises(MessageError, match=r"Odometry\.pose\.covariance: 35 elements where float64\[36\] is expected"):
        serialize(odom)


def test_sequences_accept_numpy_and_tuples() -> None:
    np = pytest.importorskip("numpy")
    assert deserialize(serialize(TFMessage((TransformStamped(),))), TFMessage) == TFMessage([TransformStamped()])
    js = JointState(name=("a", "b"), position=np.array([1.0, 2.0]), velocity=np.array([1, 2]), effort=(0.5, 1))
    back = deserialize(serialize(js), JointState)
    assert back == JointState(name=["a", "b"], position=[1.0, 2.0], velocity=[1.0, 2.0], effort=[0.5, 1.0])
    assert all(type(v) is float for v in back.position + back.effort)


def test_str_subclasses_give_their_characters() -> None:
    class Frame(str, enum.Enum):  # noqa: UP042 - a str mixin, whose str() is "Frame.MAP"
        MAP = "map"

    t = make_transform(Frame.MAP, "base")  # type: ignore[arg-type]
    assert deserialize(serialize(TFMessage([t])), TFMessage).transforms[0].header.frame_id == "map"
    assert deserialize(serialize(t), TransformStamped).header.frame_id == "map"


def test_non_finite_floats_survive() -> None:
    t = make_transform("a", "b", (math.nan, math.inf, -math.inf))
    for msg in (t, TFMessage([t])):
        back = deserialize(serialize(msg), type(msg))
        tr = (back if type(back) is TransformStamped else back.transforms[0]).transform.translation
        assert math.isnan(tr.x) and tr.y == math.inf and tr.z == -math.inf


def test_transform_stamped_bytes_derived_by_hand() -> None:
    # CDR little endian: 4-byte encapsulation header 00 01 00 00; then, aligned relative to the
    # body: int32 sec, uint32 nanosec, string = uint32 length counting a NUL + bytes + NUL,
    # padding to 4 before the next string, padding to 8 before the float64s.
    t = make_transform("map", "base_link", (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0), 5 * 10**9 + 7)
    body = struct.pack("<iI", 5, 7) + struct.pack("<I", 4) + b"map\x00"  # body offset 16
    body += struct.pack("<I", 10) + b"base_link\x00"  # offset 30
    body += b"\x00\x00"  # to 32
    body += struct.pack("<7d", 1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0)
    assert serialize(t) == b"\x00\x01\x00\x00" + body
    # In a TFMessage the uint32 count comes first, which moves the strings by 4 bytes.
    body = struct.pack("<I", 1) + struct.pack("<iI", 5, 7) + struct.pack("<I", 4) + b"map\x00"  # offset 20
    body += struct.pack("<I", 10) + b"base_link\x00" + b"\x00\x00" + b"\x00\x00\x00\x00"  # 34 -> 40
    body += struct.pack("<7d", 1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0)
    assert serialize(TFMessage([t])) == b"\x00\x01\x00\x00" + body


def test_big_endian_payloads_decode() -> None:
    msg = TFMessage([make_transform("odom", "base", (1.0, -2.0, 0.5), stamp_ns=3 * 10**9 + 1)])
    raw = bytes(STORE.serialize_cdr(to_rosbags(msg), msg.__msgtype__, little_endian=False))
    assert raw[:2] == b"\x00\x00"
    assert deserialize(raw, TFMessage) == msg


def test_type_hashes_match_published_values() -> None:
    # Values published by rmw_zenoh's design document and ROS 2 Jazzy's generated interfaces.
    assert type_hash(TFMessage) == "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087"
    assert type_hash("std_msgs/msg/String") == (
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18")
    assert type_hash(TransformStamped) == (
        "RIHS01_0a241f87d04668d94099cbb5ba11691d5ad32c2f29682e4eb5653424bd275206")
    with pytest.raises(MessageError, match="no robotmodel message class for 'sensor_msgs/msg/Image'"):
        type_hash("sensor_msgs/msg/Image")


def test_from_rosbags_drops_ros1_only_fields() -> None:
    noetic = get_typestore(Stores.ROS1_NOETIC)
    types = noetic.types
    header = types["std_msgs/msg/Header"](seq=9, stamp=types["builtin_interfaces/msg/Time"](sec=1, nanosec=2),
                                           frame_id="map")
    assert from_rosbags(header) == Header(builtin_interfaces.Time(1, 2), "map")


def test_other_typestores() -> None:
    humble = get_typestore(Stores.ROS2_HUMBLE)
    msg = TFMessage([make_transform("a", "b", (1.0, 0.0, 0.0), stamp_ns=10)])
    assert type(to_rosbags(msg, humble)) is humble.types["tf2_msgs/msg/TFMessage"]
    assert serialize(msg, humble) == serialize(msg)
    assert deserialize(serialize(msg), TFMessage, humble) == msg


def test_unknown_types_are_message_errors() -> None:
    with pytest.raises(MessageError, match="no robotmodel message class for 'sensor_msgs/msg/Image'"):
        deserialize(b"\x00\x01\x00\x00", "sensor_msgs/msg/Image")
    with pytest.raises(MessageError, match="no robotmodel message class for 'sensor_msgs/msg/Image'"):
        from_rosbags(STORE.types["sensor_msgs/msg/Image"](
            header=to_rosbags(Header()), height=0, width=0, encoding="", is_bigendian=0, step=0, data=[]))
    with pytest.raises(MessageError, match="no robotmodel message class for 'int'"):
        from_rosbags(3)
