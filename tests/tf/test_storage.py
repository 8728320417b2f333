"""The array-backed cache against a transcription of tf2's list algorithm, and the raw insert API."""

from __future__ import annotations

import logging
import math
import random
import threading
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from tfhelpers import SEC, make

from robotmodel.errors import InvalidArgumentException
from robotmodel.spatial import pose_interpolate
from robotmodel.tf import Buffer, Duration, Time
from robotmodel.tf._cache import CacheMiss

POOL = [(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), (2.0, 1.0, 0.0, 0.0, 0.0, math.sin(0.3), math.cos(0.3)),
        (0.0, -1.0, 3.0, 0.0, math.sin(0.2), 0.0, math.cos(0.2))]


class Tf2List:
    """tf2's TimeCache as the notes describe it: a list newest first, pruned before each insert."""

    def __init__(self, window: int | None) -> None:
        self.window = window
        self.items: list[tuple[int, tuple, str]] = []

    def insert(self, stamp: int, value: tuple, parent: str) -> bool:
        latest = self.items[0][0] if self.items else 0
        if self.window is not None:
            while self.items and self.items[-1][0] + self.window < latest:
                self.items.pop()
            if self.items and stamp < latest - self.window:
                return False
        k = 0
        while k < len(self.items) and self.items[k][0] > stamp:
            k += 1
        j = k
        while j < len(self.items) and self.items[j][0] == stamp:
            if self.items[j][1] == value and self.items[j][2] == parent:
                return True
            j += 1
        self.items.insert(k, (stamp, value, parent))
        return True

    def sample(self, t: int):
        items = self.items
        if not items:
            return None
        if t == 0:
            return items[0][1], items[0][2]
        if len(items) == 1:
            return (items[0][1], items[0][2]) if items[0][0] == t else None
        if t == items[0][0]:
            return items[0][1], items[0][2]
        if t == items[-1][0]:
            return items[-1][1], items[-1][2]
        if t > items[0][0] or t < items[-1][0]:
            return None
        k = next(i for i, it in enumerate(items) if it[0] <= t)
        one, two = items[k], items[k - 1]
        if one[2] != two[2]:
            return one[1], one[2]
        return pose_interpolate(one[1], two[1], (t - one[0]) / (two[0] - one[0])), one[2]


ops = st.lists(st.tuples(st.integers(0, 40), st.sampled_from(range(len(POOL))), st.sampled_from(["p", "q"])),
               min_size=1, max_size=60)


def _check_same(buf: Buffer, ref: Tf2List, child: str = "c") -> None:
    cache = buf._caches[buf._ids[child]]
    assert len(cache) == len(ref.items)
    stamps, poses, parents = cache.arrays()
    assert stamps.tolist() == [it[0] for it in reversed(ref.items)]
    assert [buf._names[p] for p in parents.tolist()] == [it[2] for it in reversed(ref.items)]
    np.testing.assert_array_equal(poses, np.array([it[1] for it in reversed(ref.items)]).reshape(-1, 7))
    for t in range(42):
        got, want = cache.sample(t), ref.sample(t)
        if want is None:
            assert isinstance(got, CacheMiss)
        else:
            assert not isinstance(got, CacheMiss)
            assert buf._names[got[1]] == want[1]
            np.testing.assert_allclose(got[0], want[0], atol=1e-12)


@settings(max_examples=300, deadline=None)
@given(ops, st.sampled_from([None, 0, 3, 10]))
def test_cache_matches_tf2s_list_algorithm(sequence, window) -> None:
    buf = Buffer(cache_time=Duration(nanoseconds=window)) if window is not None else Buffer(unbounded=True)
    ref = Tf2List(window)
    for stamp, value, parent in sequence:
        assert buf.insert(parent, "c", stamp, POOL[value], "me") == ref.insert(stamp, POOL[value], parent)
        _check_same(buf, ref)


@settings(max_examples=200, deadline=None)
@given(ops, st.sampled_from([None, 3, 10]))
def test_insert_many_equals_single_inserts(sequence, window) -> None:
    def fresh() -> Buffer:
        return Buffer(cache_time=Duration(nanoseconds=window)) if window is not None else Buffer(unbounded=True)

    one_by_one, bulk = fresh(), fresh()
    ref = Tf2List(window)
    accepted = 0
    for stamp, value, _ in sequence:
        accepted += one_by_one.insert("p", "c", stamp, POOL[value], "me")
        ref.insert(stamp, POOL[value], "p")
    got = bulk.insert_many("p", "c", [s for s, _, _ in sequence], [POOL[v] for _, v, _ in sequence], "me")
    assert got == accepted
    _check_same(bulk, ref)


def test_insert_many_appends_sorted_data_in_one_step_with_tf2s_lazy_pruning() -> None:
    bulk = Buffer(cache_time=Duration(seconds=10))
    stamps = np.arange(1, 30_001) * 1_000_000  # 30 s at 1 kHz
    poses = np.tile(POOL[1], (stamps.size, 1))
    assert bulk.insert_many("p", "c", stamps, poses, "me") == stamps.size
    cache = bulk._caches[bulk._ids["c"]]
    # Pruned by the newest stamp before the last insert: 10 s plus that one sample remain.
    assert cache.oldest_stamp() == stamps[-2] - 10 * SEC
    assert len(cache) == 10_002
    assert cache.nbytes() <= 80 * len(cache)  # 68 bytes a sample plus at most 1/8 spare


@pytest.mark.parametrize("window", [None, 10])
def test_first_samples_in_shared_rows_never_touch_each_other(window) -> None:
    # 700 frames' first samples share rows of a few arrays; each frame then gets one of the
    # operations that move its samples to an array of its own (newer, older, same stamp,
    # another parent, bulk, clear), in random order while its neighbours still share.
    rng = random.Random(7)
    buf = Buffer(cache_time=Duration(nanoseconds=window)) if window is not None else Buffer(unbounded=True)
    children = [f"c{k}" for k in range(700)]
    refs = {c: Tf2List(window) for c in children}
    for k, c in enumerate(children):
        stamp, value = 20 + k % 7, k % len(POOL)
        assert buf.insert("p", c, stamp, POOL[value], "me")
        refs[c].insert(stamp, POOL[value], "p")
    order = children[:]
    rng.shuffle(order)
    for k, c in enumerate(order):
        stamp = refs[c].items[0][0]
        kind = k % 7
        if kind == 6:
            continue
        if kind == 5:
            buf._caches[buf._ids[c]].clear()
            refs[c].items.clear()
            continue
        rows = [(stamp + 1, 1, "p"), (stamp - 3, 2, "p"), (stamp, 1, "p"), (stamp + 2, 0, "q"),
                (stamp - 1, 0, "q")][kind:kind + 1]
        if kind == 4:
            rows = [(stamp + 1, 2, "p"), (stamp + 5, 1, "p"), (stamp + 9, 0, "p")]
            assert buf.insert_many("p", c, [r[0] for r in rows], [POOL[r[1]] for r in rows], "me") == 3
        else:
            for st_, value, parent in rows:
                buf.insert(parent, c, st_, POOL[value], "me")
        for st_, value, parent in rows:
            refs[c].insert(st_, POOL[value], parent)
    for c in children:
        _check_same(buf, refs[c], c)


def test_steady_state_storage_stays_bounded_and_compact() -> None:
    buf = Buffer(cache_time=Duration(nanoseconds=1000))
    for k in range(20_000):
        assert buf.insert("p", "c", k * 10, POOL[k % 3], "me")
    cache = buf._caches[buf._ids["c"]]
    assert len(cache) == 102  # 1000 ns window at 10 ns steps, pruned lazily by one insert
    assert cache.nbytes() <= 2 * 68 * 102 + 68 * 32


def test_unbounded_buffer_keeps_everything() -> None:
    buf = Buffer(unbounded=True)
    buf.insert("map", "robot", 3600 * SEC, POOL[0], "me")
    assert buf.insert("map", "robot", 1 * SEC, POOL[1], "me")  # an hour older: still accepted
    assert buf.insert_many("map", "robot", np.arange(2, 100) * SEC, np.tile(POOL[2], (98, 1)), "me") == 98
    got = buf.lookup_transform("map", "robot", Time(seconds=1))
    assert got.transform.translation.x == 2.0
    assert len(buf._caches[buf._ids["robot"]]) == 100


def test_insert_api_validates_like_set_transform(caplog) -> None:
    buf = Buffer()
    with caplog.at_level(logging.ERROR, logger="robotmodel.tf"):
        assert buf.insert("a", "a", SEC, POOL[0], "me") is False
        assert buf.insert("a", "b", SEC, (0, 0, 0, 0, 0, 0, 0), "me") is False
        assert buf.insert_many("a", "b", [SEC, 2 * SEC], [(math.nan, 0, 0, 0, 0, 0, 1), POOL[0]], "me") == 1
    assert "TF_SELF_TRANSFORM" in caplog.text and "TF_DENORMALIZED_QUATERNION" in caplog.text
    assert "TF_NAN_INPUT" in caplog.text
    assert buf.insert("/a", "/c", SEC, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -2.0), "me", is_static=True)
    q = buf.lookup_transform("a", "c", Time(seconds=5)).transform.rotation
    assert (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 1.0)  # canonical: normalized, tf2's sign
    with pytest.raises(InvalidArgumentException):
        buf.insert("a", "b", SEC, (1.0, 2.0), "me")
    with pytest.raises(InvalidArgumentException):
        buf.insert_many("a", "b", [SEC, 2 * SEC], [POOL[0]], "me")
    with pytest.raises(InvalidArgumentException):
        buf.insert("a", "b", 1.5, POOL[0], "me")


def test_set_transform_is_an_adapter_over_insert() -> None:
    via_msg, raw = Buffer(), Buffer()
    msg = make("map", "base", (1, 2, 3), 0.4, sec=7)
    via_msg.set_transform(msg, "me")
    t, r = msg.transform.translation, msg.transform.rotation
    raw.insert("map", "base", 7 * SEC, (t.x, t.y, t.z, r.x, r.y, r.z, r.w), "me")
    a = via_msg.lookup_transform("map", "base", Time())
    b = raw.lookup_transform("map", "base", Time())
    assert a == b


def _wait_for(predicate, seconds: float = 5.0) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.005)
    return False


def test_waiter_registers_its_chain_and_wakes_on_a_middle_link() -> None:
    buf = Buffer()
    buf.insert("map", "odom", SEC, POOL[0], "me")
    buf.insert("odom", "base", SEC, POOL[0], "me")
    buf.insert("odom", "base", 2 * SEC, POOL[1], "me")
    buf.insert_many("world", "elsewhere", [SEC, 2 * SEC], [POOL[0], POOL[0]], "me")
    result: list[object] = []

    def wait() -> None:
        start = time.monotonic()
        result.append(buf.lookup_transform("map", "base", Time(seconds=2), timeout=Duration(seconds=20)))
        result.append(time.monotonic() - start)

    waiter = threading.Thread(target=wait)
    waiter.start()
    assert _wait_for(lambda: bool(buf._waiters))
    with buf._lock:
        assert set(buf._waiters) == {"map", "odom", "base"}  # not "world" or "elsewhere"
    buf.insert("world", "elsewhere", 3 * SEC, POOL[0], "me")  # unrelated: no wake-up needed
    buf.insert("map", "odom", 2 * SEC, POOL[2], "me")  # the stale middle link catches up
    waiter.join(10)
    assert not waiter.is_alive()
    assert result[0].header.stamp.sec == 2
    assert result[1] < 10  # woken by the insert, not by the timeout
    assert buf._waiters == {}


def test_no_log_handler_runs_under_the_buffer_lock() -> None:
    buf = Buffer(cache_time=Duration(seconds=1))
    buf.insert("a", "b", 10 * SEC, POOL[0], "me")
    outcomes: list[bool] = []

    class Probe(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            other = threading.Thread(target=lambda: buf.can_transform("a", "b", Time()))
            other.start()
            other.join(5)
            outcomes.append(not other.is_alive())

    probe = Probe()
    logger = logging.getLogger("robotmodel.tf")
    logger.addHandler(probe)
    try:
        assert buf.insert("a", "b", 1 * SEC, POOL[0], "me") is False  # TF_OLD_DATA
        assert buf.insert("a", "a", 11 * SEC, POOL[0], "me") is False  # TF_SELF_TRANSFORM
        assert buf.insert_many("a", "b", [1], [POOL[0]], "me") == 0  # TF_OLD_DATA from the bulk path
    finally:
        logger.removeHandler(probe)
    assert outcomes == [True, True, True]


def test_wait_for_transform_async_resolves_on_the_insert_outside_the_lock() -> None:
    buf = Buffer()
    ready = buf.wait_for_transform_async("a", "a", Time())
    assert ready.done() and ready.result().child_frame_id == "a"  # identical frames: at once
    future = buf.wait_for_transform_async("map", "base", Time(seconds=2))
    assert not future.done()
    lock_free: list[bool] = []

    def on_done(done) -> None:
        other = threading.Thread(target=lambda: buf.can_transform("map", "base", Time()))
        other.start()
        other.join(5)
        lock_free.append(not other.is_alive())

    future.add_done_callback(on_done)
    buf.insert("map", "odom", 2 * SEC, POOL[0], "me")
    assert not future.done()  # odom -> base still missing
    buf.insert("odom", "base", 2 * SEC, POOL[1], "me")
    assert future.done()
    got = future.result()
    assert (got.header.frame_id, got.child_frame_id, got.header.stamp.sec) == ("map", "base", 2)
    assert got.transform.translation.x == 3.0
    assert lock_free == [True]
    assert buf._waiters == {}


def test_cancelled_request_is_forgotten() -> None:
    buf = Buffer()
    future = buf.wait_for_transform_full_async("map", Time(seconds=1), "base", Time(seconds=1), "odom")
    assert set(buf._waiters) == {"map", "odom", "base"}
    assert future.cancel()
    assert buf._waiters == {}
    buf.insert("map", "odom", SEC, POOL[0], "me")  # nothing left to retry
    bad = buf.wait_for_transform_async("", "base", Time())  # waiting cannot fix an argument
    assert isinstance(bad.exception(timeout=0), InvalidArgumentException)
    assert buf._waiters == {}


def test_unbounded_bulk_merge_of_shuffled_rows_equals_single_inserts() -> None:
    rng = np.random.default_rng(7)
    stamps = rng.integers(0, 500, 3000)  # out of order, many repeated stamps
    pick = rng.integers(0, len(POOL), 3000)
    poses = np.array([POOL[k] for k in pick])
    poses[::7, 0] = -0.0  # -0.0 and 0.0 rows are equal samples
    poses[1::7, 0] = 0.0
    one_by_one, bulk = Buffer(unbounded=True), Buffer(unbounded=True)
    one_by_one.insert_many("p", "c", [1000], [POOL[0]], "me")
    bulk.insert_many("p", "c", [1000], [POOL[0]], "me")
    for s, row in zip(stamps.tolist(), poses.tolist(), strict=True):
        one_by_one.insert("p", "c", s, tuple(row), "me")
    assert bulk.insert_many("p", "c", stamps, poses, "me") == 3000
    for a, b in zip(one_by_one._caches[one_by_one._ids["c"]].arrays(), bulk._caches[bulk._ids["c"]].arrays(),
                    strict=True):
        np.testing.assert_array_equal(a, b)
