"""Bytes that are not a message: a MessageError, never another exception; the fast TF path agrees with rosbags."""

from __future__ import annotations

import contextlib
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from msgstrategies import STORE, message_strategy
from rosbags.serde import SerdeError

from robotmodel.errors import MessageError
from robotmodel.msgs import JointState, TFMessage, deserialize, from_rosbags, make_transform, serialize
from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.msgs.geometry_msgs import Transform, TransformStamped
from robotmodel.msgs.std_msgs import Header

TF = "tf2_msgs/msg/TFMessage"


def _samples() -> list[Any]:
    return [
        TFMessage([make_transform("map", "odom", (1.0, 2.0, 3.0)), make_transform("odom", "base_link")]),
        JointState(name=["j1", "j2"], position=[0.1, 0.2], velocity=[], effort=[3.0]),
    ]


@pytest.mark.parametrize("msg", _samples(), ids=lambda m: type(m).__name__)
def test_every_truncation_is_a_message_error(msg: Any) -> None:
    raw = serialize(msg)
    for n in range(len(raw)):
        with pytest.raises(MessageError, match=f"{msg.__msgtype__}|invalid"):
            deserialize(raw[:n], type(msg))


def _rosbags_decode(raw: bytes) -> Any:
    try:
        return from_rosbags(STORE.deserialize_cdr(raw, TF))
    except (SerdeError, UnicodeDecodeError):
        return None


@settings(max_examples=300, deadline=None)
@given(msg=message_strategy(TF), edits=st.lists(st.tuples(st.integers(0, 10**6), st.integers(0, 255)), max_size=3))
def test_fast_tf_decoder_agrees_with_rosbags_on_damaged_bytes(msg: TFMessage, edits: list[tuple[int, int]]) -> None:
    raw = bytearray(serialize(msg))
    for at, value in edits:
        if at % len(raw) >= 4:  # keep the little-endian header: the fast path's domain
            raw[at % len(raw)] = value
    data = bytes(raw)
    expected = _rosbags_decode(data)
    if expected is None:
        with pytest.raises(MessageError):
            deserialize(data, TFMessage)
    else:
        assert repr(deserialize(data, TFMessage)) == repr(expected)  # repr: NaN equals NaN


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=200))
def test_random_bytes_never_escape_as_other_errors(tail: bytes) -> None:
    for msgtype in (TFMessage, JointState):
        for data in (b"\x00\x01\x00\x00" + tail, tail):
            with contextlib.suppress(MessageError):
                deserialize(data, msgtype)


def test_fast_tf_decoder_refuses_bytes_past_the_message_as_rosbags_does() -> None:
    # Found by the property test above: a count zeroed by damage left 132 bytes unread,
    # which rosbags refuses ("size mismatch") and the fast path accepted as an empty message.
    raw = bytearray(serialize(TFMessage([TransformStamped(Header(Time(1, 2), "a"), "b", Transform())])))
    raw[4:8] = bytes(4)
    assert _rosbags_decode(bytes(raw)) is None
    with pytest.raises(MessageError, match="after the message's end"):
        deserialize(bytes(raw), TFMessage)
    for pad in range(4):  # alignment padding after the last field is no damage
        assert deserialize(bytes(serialize(TFMessage([]))) + bytes(pad), TFMessage) == TFMessage([])
