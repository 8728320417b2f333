"""ROS 1 codecs of robotmodel's (ROS 2-shaped) classes: the bytes Noetic's own serializers give, and back."""

from __future__ import annotations

import subprocess

import pytest
from ros1helpers import MISSING, SYSTEM_PYTHON

from robotmodel.bus import TFRecords, codec_for
from robotmodel.errors import MessageError
from robotmodel.msgs import Header, JointState, TFMessage, make_transform, stamp
from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.ros1 import message_type, typestore


def tf_message() -> TFMessage:
    a = make_transform("world", "base", (1.0, -2.5, 3.25), (0.0, 0.0, 0.6, 0.8))
    a.header.stamp = Time(sec=1_700_000_000, nanosec=123_456_789)
    b = make_transform("base", "ünïcode_tool", (0.1, 0.2, 0.3))
    return TFMessage(transforms=[a, b])


def noetic_tf_bytes() -> bytes:
    """The same TFMessage built from Noetic's own classes and serialized by rosbags' ROS 1 serializer."""
    store = typestore()
    t = store.types
    def ts(frame: str, child: str, sec: int, nsec: int, xyz: tuple[float, ...], q: tuple[float, ...]) -> object:
        header = t["std_msgs/msg/Header"](seq=0, stamp=t["builtin_interfaces/msg/Time"](sec=sec, nanosec=nsec),
                                          frame_id=frame)
        tr = t["geometry_msgs/msg/Transform"](translation=t["geometry_msgs/msg/Vector3"](x=xyz[0], y=xyz[1], z=xyz[2]),
                                              rotation=t["geometry_msgs/msg/Quaternion"](x=q[0], y=q[1], z=q[2], w=q[3]))
        return t["geometry_msgs/msg/TransformStamped"](header=header, child_frame_id=child, transform=tr)

    msg = t["tf2_msgs/msg/TFMessage"](transforms=[
        ts("world", "base", 1_700_000_000, 123_456_789, (1.0, -2.5, 3.25), (0.0, 0.0, 0.6, 0.8)),
        ts("base", "ünïcode_tool", 0, 0, (0.1, 0.2, 0.3), (0.0, 0.0, 0.0, 1.0))])
    return bytes(store.serialize_ros1(msg, "tf2_msgs/msg/TFMessage"))


@pytest.mark.parametrize("cls", [TFMessage, "tf2_msgs/msg/TFMessage"], ids=["hand", "generic"])
def test_tfmessage_bytes_equal_noetics(cls: object) -> None:
    codec = codec_for(cls, "ros1")
    msg = tf_message() if cls is TFMessage else codec_for("tf2_msgs/msg/TFMessage").decode(
        codec_for(TFMessage).encode(tf_message()))
    assert codec.encode(msg) == noetic_tf_bytes()
    assert codec.message_type().md5sum == "94810edda583a504dfda3829e70d7eec"
    assert codec.message_type().definition == message_type("tf2_msgs/TFMessage").definition


def test_tfmessage_and_records_decode_noetics_bytes() -> None:
    data = noetic_tf_bytes()
    assert codec_for(TFMessage, "ros1").decode(data) == tf_message()
    records = codec_for(TFRecords, "ros1").decode(data)
    assert [(r.parent, r.child, r.stamp_ns) for r in records] == [
        ("world", "base", 1_700_000_000_123_456_789), ("base", "ünïcode_tool", 0)]
    assert records[0].pose == (1.0, -2.5, 3.25, 0.0, 0.0, 0.6, 0.8)
    assert codec_for(TFRecords, "ros1").encode(records) == data


def test_joint_state_header_gets_rosones_seq_and_time() -> None:
    js = JointState(header=Header(stamp=stamp(1_700_000_000_000_000_042), frame_id="base"), name=["a", "b"],
                    position=[0.5, -1.0], velocity=[], effort=[2.0, 3.0])
    codec = codec_for(JointState, "ros1")
    data = codec.encode(js)
    noetic = typestore().deserialize_ros1(data, "sensor_msgs/msg/JointState")
    assert (noetic.header.seq, noetic.header.stamp.sec, noetic.header.stamp.nanosec) == (0, 1_700_000_000, 42)
    assert (list(noetic.name), list(noetic.position), list(noetic.effort)) == (["a", "b"], [0.5, -1.0], [2.0, 3.0])
    assert codec.decode(data) == js


@pytest.mark.parametrize("cls", [TFMessage, TFRecords, JointState], ids=["tf", "records", "joint_state"])
def test_damaged_bytes_are_one_message_error(cls: object) -> None:
    data = codec_for(cls, "ros1").encode(tf_message() if cls is TFMessage else [] if cls is TFRecords
                                         else JointState(name=["a"], position=[1.0]))
    damaged = [data[:-1], data + b"\x01\x02\x03\x04\x05"]
    if cls is not JointState:  # a TFMessage starts with its count (a JointState with its header's seq)
        damaged.append(b"\xff\xff\xff\xff" + data[4:])
    for bad in damaged:
        with pytest.raises(MessageError):
            codec_for(cls, "ros1").decode(bad)


def test_genpy_reads_what_we_write() -> None:
    if MISSING:
        pytest.skip(MISSING)
    data = codec_for(TFMessage, "ros1").encode(tf_message())
    code = ("import sys; from tf2_msgs.msg import TFMessage as T; m = T().deserialize(bytes.fromhex(sys.argv[1])); "
            "print([(t.header.frame_id, t.child_frame_id, t.header.stamp.secs, t.header.stamp.nsecs, "
            "t.transform.rotation.z) for t in m.transforms])")
    out = subprocess.run([SYSTEM_PYTHON, "-c", code, data.hex()], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[('world', 'base', 1700000000, 123456789, 0.6), ('base', 'ünïcode_tool', 0, 0, 0.0)]"
