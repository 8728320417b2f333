"""The bulk TFMessage decoder gives, bit for bit, what rosbags' deserializer gives, message by message."""

from __future__ import annotations

import random
import struct

import pytest
from recording.bagfiles import NS, TS1, TS2, Msg, build

from robotmodel.recording._open import ros1_typestore
from robotmodel.recording._tfarrays import TFArrayDecoder, ros1_reference

NAMES = ["a", "ab", "abc", "abcd", "base_link", "odom", "map", "camera_optical", "é", "x/y", "link_07", "link_42"]
SPECIAL = [0.0, -0.0, 1e308, -1e-308, 5e-324, float("nan"), float("inf"), 1.0]


def random_message(rng: random.Random, names: list[tuple[str, str]]) -> Msg:
    transforms = []
    for parent, child in names:
        sec = rng.randrange(0, 2**31)
        ns = sec * NS + rng.randrange(NS)
        pose = tuple(rng.choice(SPECIAL) if rng.random() < 0.1 else rng.uniform(-10, 10) for _ in range(7))
        transforms.append((parent, child, ns, pose))
    return Msg("/tf", 0, "tf", transforms)


def reference_values(msg: object) -> list[tuple[str, str, int, bytes]]:
    out = []
    for t in msg.transforms:  # type: ignore[attr-defined]
        s, tr, r = t.header.stamp, t.transform.translation, t.transform.rotation
        out.append((t.header.frame_id, t.child_frame_id, int(s.sec) * NS + int(s.nanosec),
                    struct.pack("<7d", tr.x, tr.y, tr.z, r.x, r.y, r.z, r.w)))
    return out


def decoded_values(decoder: TFArrayDecoder) -> tuple[dict[int, list[tuple[str, str, int, bytes]]], int]:
    blocks, slow = decoder.flush()
    out: dict[int, list[tuple[str, str, int, bytes]]] = {}
    in_blocks = 0
    for b in blocks:
        for row, order in enumerate(b.order.tolist()):
            out[order] = [(p, c, int(b.stamps[row, j]), b.poses[row, j].tobytes())
                          for j, (p, c) in enumerate(zip(b.parents, b.children, strict=True))]
            in_blocks += 1
    for order, records in slow:
        out[order] = [(r.parent, r.child, r.stamp_ns, struct.pack("<7d", *r.pose)) for r in records]
    return out, in_blocks


@pytest.mark.parametrize("ros1", [False, True], ids=["cdr", "ros1"])
def test_bulk_decoding_equals_rosbags_bit_for_bit(ros1):
    rng = random.Random(12)
    shapes = []
    for _ in range(6):
        width = rng.randrange(0, 6)
        shapes.append([(rng.choice(NAMES), rng.choice(NAMES)) for _ in range(width)])
    # Same length, other names: "ab"/"cd" share every offset but not their bytes.
    shapes += [[("ab", "x")], [("cd", "x")]]
    ts = TS1 if ros1 else TS2
    decoder = TFArrayDecoder(ros1, ros1_reference(ros1_typestore().deserialize_ros1) if ros1 else None)
    expected = {}
    for order in range(400):
        msg = build(ts, random_message(rng, rng.choice(shapes)), ros1)
        data = ts.serialize_ros1(msg, "tf2_msgs/msg/TFMessage") if ros1 else \
            ts.serialize_cdr(msg, "tf2_msgs/msg/TFMessage")
        decoder.add(order, bytes(data))
        expected[order] = reference_values(msg)
    got, in_blocks = decoded_values(decoder)
    assert got == expected
    assert in_blocks > 300  # the bulk path did the work


def test_a_damaged_message_is_left_out_and_counted():
    decoder = TFArrayDecoder()
    good = bytes(TS2.serialize_cdr(build(TS2, random_message(random.Random(1), [("a", "b")]), False),
                                   "tf2_msgs/msg/TFMessage"))
    for order in range(5):
        decoder.add(order, good)
    decoder.add(9, good[:-9])
    miscounted = bytearray(good)
    miscounted[4:8] = (10**6).to_bytes(4, "little")  # same length as the good ones: fails the template
    decoder.add(7, bytes(miscounted))
    blocks, slow = decoder.flush()
    orders = sorted([int(o) for b in blocks for o in b.order] + [o for o, _ in slow])
    assert orders == [0, 1, 2, 3, 4]
    assert decoder.undecodable == 2
    assert decoder.first_error is not None and decoder.first_error[0] == 7


def test_proven_layout_rejects_rows_whose_structure_differs():
    # Two messages of one length and layout, but other frame names: never read with the other's names.
    rng = random.Random(3)
    decoder = TFArrayDecoder()
    msgs = [random_message(rng, [("map", "odom")]), random_message(rng, [("abc", "xyz")])]
    for order in range(20):
        decoder.add(order, bytes(TS2.serialize_cdr(build(TS2, msgs[order % 2], False), "tf2_msgs/msg/TFMessage")))
    got, _ = decoded_values(decoder)
    assert {got[k][0][:2] for k in range(0, 20, 2)} == {("map", "odom")}
    assert {got[k][0][:2] for k in range(1, 20, 2)} == {("abc", "xyz")}


def test_sample_times_refuses_absurd_spans():
    from robotmodel.errors import RecordingError
    from robotmodel.recording import MAX_STEPS, sample_times

    assert list(sample_times(10, 40, 10)) == [10, 20, 30, 40]
    assert len(sample_times(0, (MAX_STEPS - 1) * 7, 7)) == MAX_STEPS
    with pytest.raises(RecordingError, match=r"run\.bag: the transforms span .* more than 100,000"):
        sample_times(0, MAX_STEPS * 7, 7, where="run.bag")
