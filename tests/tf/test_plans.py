"""The reused chain walks (BufferCore._plan/_chain) give what tf2's full walk gives, whatever the tree does.

The reference is the walk every lookup took before walks were reused: ``_latest_common_time``
for time 0, ``_walk`` and ``quat_canonical``, called directly. Random sequences of inserts
(re-parenting, loops, static/dynamic switches, out-of-order and repeated stamps), bulk inserts
and clears, with every pair of frames looked up after each step, at sample times, between
them, outside the data and at time 0: the same pose to the bit, or the same error and text.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from robotmodel.errors import TransformException
from robotmodel.spatial import quat_canonical
from robotmodel.tf import Buffer, Duration

FRAMES = ["a", "b", "c", "d", "e"]
SEC = 1_000_000_000


def reference(buf: Buffer, target: str, source: str, t: int) -> object:
    """The lookup as the full walk does it: (pose, stamp) or (exception class, text)."""
    try:
        with buf._lock:
            tid = buf._validate(target, "lookupTransform argument target_frame")
            sid = buf._validate(source, "lookupTransform argument source_frame")
            if t == 0:
                t = buf._latest_common_time(tid, sid, target, source)
            pose = buf._walk(t, tid, sid, target, source)
            return (*pose[:3], *quat_canonical(pose[3:])), t
    except TransformException as exc:
        return type(exc), str(exc)


def ours(buf: Buffer, target: str, source: str, t: int) -> object:
    try:
        pose, stamp = buf.lookup_ns(target, source, t)
        return tuple(pose), stamp
    except TransformException as exc:
        return type(exc), str(exc)


def pose_of(k: int) -> tuple[float, ...]:
    angle = 0.7 * k
    axis = (math.sin(k), math.cos(2 * k), 0.5)
    n = math.sqrt(sum(v * v for v in axis))
    s = math.sin(angle / 2) / n
    sign = -1.0 if k % 3 == 0 else 1.0  # both signs, and w of either size
    return (0.1 * k, -0.2 * k, 0.05 * k * k, sign * axis[0] * s, sign * axis[1] * s, sign * axis[2] * s,
            sign * math.cos(angle / 2))


op = st.one_of(
    st.tuples(st.just("insert"), st.sampled_from(FRAMES), st.sampled_from(FRAMES), st.integers(1, 12),
              st.integers(0, 20)),
    st.tuples(st.just("static"), st.sampled_from(FRAMES), st.sampled_from(FRAMES), st.integers(0, 20)),
    st.tuples(st.just("many"), st.sampled_from(FRAMES), st.sampled_from(FRAMES), st.integers(1, 6)),
    st.tuples(st.just("clear")),
)


@settings(max_examples=60, deadline=None)
@given(st.lists(op, min_size=1, max_size=15), st.booleans())
def test_reused_walks_match_the_full_walk(ops: list[tuple], unbounded: bool) -> None:
    buf = Buffer(unbounded=True) if unbounded else Buffer(cache_time=Duration(seconds=5))
    times = [0, SEC // 2, 3 * SEC // 2, 2 * SEC, 4 * SEC + 7, 13 * SEC]
    for step in ops:
        if step[0] == "insert":
            _, parent, child, sec, k = step
            buf.insert(parent, child, sec * SEC // 2, pose_of(k), "test")
        elif step[0] == "static":
            _, parent, child, k = step
            buf.insert(parent, child, 0, pose_of(k), "test", is_static=True)
        elif step[0] == "many":
            _, parent, child, n = step
            stamps = np.arange(1, n + 1, dtype=np.int64) * SEC
            if parent != child:
                buf.insert_many(parent, child, stamps, np.array([pose_of(k) for k in range(n)]), "test")
        else:
            buf.clear()
        for target in FRAMES:
            for source in FRAMES:
                if target == source or target not in buf._ids or source not in buf._ids:
                    continue
                for t in times:
                    # Twice: the first lookup may build the walk, the second reuses it.
                    assert ours(buf, target, source, t) == reference(buf, target, source, t)
                    assert ours(buf, target, source, t) == reference(buf, target, source, t)


def test_a_chain_published_together_reuses_one_walk() -> None:
    buf = Buffer()
    chain = ["map", "odom", "base", "arm", "tool"]
    for k in range(50):
        for parent, child in itertools.pairwise(chain):
            buf.insert(parent, child, (k + 1) * SEC // 100, pose_of(k + len(child)), "test")
    t = 20 * SEC // 100 + 3
    assert ours(buf, "map", "tool", t) == reference(buf, "map", "tool", t)
    plan = buf._plans["map", "tool"]
    assert plan[0] == buf._topology and len(plan[2]) == 4
    assert ours(buf, "tool", "odom", 0) == reference(buf, "tool", "odom", 0)
    # Re-parenting a link changes the walk: the kept one is no longer used.
    buf.insert("odom", "arm", 51 * SEC // 100, pose_of(3), "test")
    assert buf._plans["map", "tool"][0] != buf._topology
    for when in (0, t, 51 * SEC // 100):
        assert ours(buf, "map", "tool", when) == reference(buf, "map", "tool", when)
