"""TFTemplate writes the same bytes as rosbags' CDR of the same TFMessage."""

from __future__ import annotations

import random

import numpy as np
import pytest

from robotmodel.msgs import TFMessage, make_transform, serialize
from robotmodel.publishers._tf_cdr import TFTemplate


def frame(rng: random.Random) -> str:
    return "".join(rng.choice("ab/_é1") for _ in range(rng.randint(0, 11)))


@pytest.mark.parametrize("seed", range(200))
def test_same_bytes_as_rosbags(seed):
    rng = random.Random(seed)
    n = rng.choice([0, 1, 2, 5, 44])
    parents = [frame(rng) for _ in range(n)]
    children = [frame(rng) for _ in range(n)]
    translations = np.array([[rng.uniform(-5, 5) for _ in range(3)] for _ in range(n)]).reshape(n, 3)
    rotations = np.array([[rng.uniform(-1, 1) for _ in range(4)] for _ in range(n)]).reshape(n, 4)
    stamp_ns = rng.choice([0, 1, 2**31 * 10**9 - 1, rng.randint(0, 2**31 * 10**9 - 1)])
    template = TFTemplate(parents, children)
    expected = serialize(TFMessage([make_transform(p, c, t, r, stamp_ns) for p, c, t, r in
                                    zip(parents, children, translations, rotations, strict=True)]))
    assert template.encode(stamp_ns, translations, rotations) == expected
    # The template is reused: a second message with other values is right too.
    other = stamp_ns - 7 if stamp_ns >= 7 else stamp_ns + 7
    assert template.encode(other, translations * 2, rotations) == serialize(TFMessage(
        [make_transform(p, c, t, r, other) for p, c, t, r in
         zip(parents, children, translations * 2, rotations, strict=True)]))
