"""TFRecord tuples: the same bytes as the TFMessage they stand for, read back exactly."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from msgstrategies import STORE, message_strategy

from robotmodel.errors import MessageError
from robotmodel.msgs import (
    TFMessage,
    TFRecord,
    decode_tf_records,
    encode_tf_records,
    make_transform,
    serialize,
    to_rosbags,
)

SEC = 1_000_000_000


def _records(msg: TFMessage) -> list[TFRecord]:
    out = []
    for t in msg.transforms:
        tr, q = t.transform.translation, t.transform.rotation
        out.append(TFRecord(t.header.frame_id, t.child_frame_id, t.header.stamp.sec * SEC + t.header.stamp.nanosec,
                            (tr.x, tr.y, tr.z, q.x, q.y, q.z, q.w)))
    return out


@settings(max_examples=150, deadline=None)
@given(message_strategy("tf2_msgs/msg/TFMessage"))
def test_records_match_messages(msg: TFMessage) -> None:
    raw = serialize(msg)
    records = _records(msg)
    assert decode_tf_records(raw) == records
    if all(t.header.stamp.nanosec < SEC for t in msg.transforms):  # else the stamp has no single ns form
        assert encode_tf_records(records) == raw == encode_tf_records(iter(records))


def test_records_feed_insert_and_read_big_endian() -> None:
    msg = TFMessage([make_transform("odom", "base", (1.0, 2.0, 3.0), (0.0, 0.0, 0.6, 0.8), 7 * SEC + 5)])
    (record,) = decode_tf_records(serialize(msg))
    assert record == TFRecord("odom", "base", 7 * SEC + 5, (1.0, 2.0, 3.0, 0.0, 0.0, 0.6, 0.8))
    assert (record.parent, record.child, record.stamp_ns, record.pose[6]) == ("odom", "base", 7 * SEC + 5, 0.8)
    big = bytes(STORE.serialize_cdr(to_rosbags(msg), msg.__msgtype__, little_endian=False))
    assert decode_tf_records(big) == [record]


def test_negative_stamps_split_as_messages_do() -> None:
    msg = TFMessage([make_transform("a", "b", stamp_ns=-1)])
    assert (msg.transforms[0].header.stamp.sec, msg.transforms[0].header.stamp.nanosec) == (-1, SEC - 1)
    assert encode_tf_records([TFRecord("a", "b", -1, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0))]) == serialize(msg)


@pytest.mark.parametrize(("record", "text"), [
    (TFRecord("a", "b", 2**31 * SEC, (0.0,) * 7), r"record 1 .*'i' format requires"),
    (TFRecord("a", "b", 0, (0.0,) * 6), r"record 1 .*pack expected 7 items"),  # type: ignore[arg-type]
    (TFRecord("a", None, 0, (0.0,) * 7), r"record 1 "),  # type: ignore[arg-type]
])
def test_bad_records_are_named(record: TFRecord, text: str) -> None:
    good = TFRecord("a", "b", 0, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0))
    with pytest.raises(MessageError, match=text):
        encode_tf_records([good, record])
