"""ROS 1 messages (md5sums checked against Debian's real ROS 1) and the connection header codec."""

from __future__ import annotations

import struct
import subprocess

import pytest
from ros1helpers import SYSTEM_PYTHON

from robotmodel.errors import MessageError, Ros1Error
from robotmodel.ros1 import decode_header, deserialize, encode_header, message_type, serialize, typestore, wire_name

# (module, class) of Debian's generated message classes; the md5sums are read from them.
TYPES = [("std_msgs.msg", "String"), ("std_msgs.msg", "Header"), ("geometry_msgs.msg", "TransformStamped"),
         ("tf2_msgs.msg", "TFMessage"), ("sensor_msgs.msg", "JointState"), ("rosgraph_msgs.msg", "Log"),
         ("rosgraph_msgs.msg", "Clock")]


def _debian(module: str, name: str) -> tuple[str, str, str] | None:
    code = f"from {module} import {name} as T; print(T._type); print(T._md5sum); print(repr(T._full_text))"
    done = subprocess.run([SYSTEM_PYTHON, "-c", code], capture_output=True, text=True, check=False)
    if done.returncode != 0:
        return None
    kind, md5, text = done.stdout.splitlines()
    return kind, md5, text


@pytest.mark.parametrize(("module", "name"), TYPES, ids=[f"{m.split('.')[0]}/{n}" for m, n in TYPES])
def test_md5sum_equals_debians(module: str, name: str) -> None:
    real = _debian(module, name)
    if real is None:
        pytest.skip(f"Debian's ROS 1 {module}.{name} is absent under {SYSTEM_PYTHON}")
    kind, md5, _ = real
    ours = message_type(kind)
    assert (ours.name, ours.md5sum) == (kind, md5)
    assert message_type(kind.replace("/", "/msg/")) == ours


def test_tfmessage_is_registered_with_its_real_md5() -> None:
    # the md5sum Noetic's tf2_msgs/TFMessage carries (also checked against Debian above)
    assert message_type("tf2_msgs/TFMessage").md5sum == "94810edda583a504dfda3829e70d7eec"
    assert "MSG: geometry_msgs/TransformStamped" in message_type("tf2_msgs/TFMessage").definition


def test_serialize_round_trip_and_bytes() -> None:
    string = typestore().types["std_msgs/msg/String"]
    data = serialize(string(data="héllo"), "std_msgs/String")
    assert data == struct.pack("<I", 6) + "héllo".encode()
    assert deserialize(data, "std_msgs/msg/String").data == "héllo"


def test_bad_bytes_and_unknown_types_are_one_error() -> None:
    with pytest.raises(MessageError, match="cannot decode std_msgs/String"):
        deserialize(b"\x05\x00", "std_msgs/String")
    with pytest.raises(Ros1Error, match="unknown ROS 1 message type 'foo_msgs/Bar'"):
        message_type("foo_msgs/Bar")
    with pytest.raises(Ros1Error, match="not a ROS message type name"):
        wire_name("String")


def test_header_round_trip_matches_the_wire_layout() -> None:
    fields = {"callerid": "/talker", "topic": "/chatter", "md5sum": "*", "latching": "1", "message_definition": "a=b"}
    raw = encode_header(fields)
    (total,) = struct.unpack_from("<I", raw)
    assert total == len(raw) - 4
    (first,) = struct.unpack_from("<I", raw, 4)
    assert raw[8 : 8 + first] == b"callerid=/talker"
    assert decode_header(raw[4:]) == fields  # '=' inside a value survives: split at the first only


@pytest.mark.parametrize(("body", "text"), [
    (b"", "without fields"),
    (struct.pack("<I", 7) + b"noequal", "not key=value"),
    (struct.pack("<I", 50) + b"topic=/x", "runs past"),
    (b"\x01\x00", "truncated"),
    (struct.pack("<I", 2) + b"\xff=", "not UTF-8"),
])
def test_bad_headers_are_one_error(body: bytes, text: str) -> None:
    with pytest.raises(Ros1Error, match=text):
        decode_header(body)
