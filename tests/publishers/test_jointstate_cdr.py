"""The fast JointState decoder reads exactly what rosbags' deserializer reads, and refuses what it cannot."""

from __future__ import annotations

import math
import random
import struct

import pytest

from robotmodel.msgs import Header, JointState, deserialize, serialize, stamp
from robotmodel.publishers._jointstate_cdr import CannotDecode, JointStateDecoder, decode_joint_state


def random_state(rng: random.Random) -> JointState:
    n = rng.choice([0, 1, 2, 3, 7, 44])
    names = ["".join(rng.choice("abc_/é9") for _ in range(rng.randint(0, 12))) for _ in range(n)]

    def values() -> list[float]:
        if rng.random() < 0.3:
            return []
        pool = [0.0, -0.0, 1e-300, math.inf, -math.inf, 1.5, -2.25]
        return [rng.choice(pool) if rng.random() < 0.2 else rng.uniform(-10, 10) for _ in range(n)]

    frame = "".join(rng.choice("xyz_") for _ in range(rng.randint(0, 5)))
    ns = rng.choice([0, 1, 2**31 * 10**9 - 1, rng.randint(0, 2**31 * 10**9 - 1)])
    return JointState(Header(stamp(ns), frame), names, values(), values(), values())


@pytest.mark.parametrize("seed", range(300))
def test_same_message_as_rosbags(seed):
    rng = random.Random(seed)
    msg = random_state(rng)
    data = serialize(msg)
    fast = decode_joint_state(data)
    assert fast == deserialize(data, JointState) == msg


def test_one_decoder_over_a_stream_with_changing_names():
    rng = random.Random(5)
    decoder = JointStateDecoder()
    base = random_state(rng)
    for i in range(200):
        # Mostly the same names (the cached path), sometimes others, one, or none.
        msg = random_state(rng) if i % 7 == 0 else JointState(
            Header(stamp(i), base.header.frame_id), list(base.name), [float(i)] * len(base.name))
        data = serialize(msg)
        assert decoder.decode(data) == deserialize(data, JointState) == msg


def test_nan_round_trips():
    data = serialize(JointState(name=["a"], position=[math.nan]))
    assert math.isnan(decode_joint_state(data).position[0])


@pytest.mark.parametrize("cut", [3, 5, 9, 13, 20, 30, 41])
def test_truncated_bytes_are_refused(cut):
    data = serialize(JointState(Header(stamp(5), "f"), ["joint_a", "b"], [1.0, 2.0], [], [3.0, 4.0]))
    with pytest.raises(CannotDecode):
        decode_joint_state(data[:cut])


def test_big_endian_and_lying_counts_are_refused():
    data = bytearray(serialize(JointState(name=["a"], position=[1.0])))
    with pytest.raises(CannotDecode):
        decode_joint_state(b"\x00\x00" + bytes(data[2:]))
    # The name count says a billion.
    body = 4 + 8 + 4 + 1 + 3
    data[body:body + 4] = struct.pack("<I", 10**9)
    with pytest.raises(CannotDecode):
        decode_joint_state(bytes(data))
