"""BufferCore.insert_records (a whole decoded message under one lock) is one insert per record."""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotmodel.errors import TransformException
from robotmodel.msgs._tfcodec import TFRecord
from robotmodel.tf import Buffer, Duration, Time

SEC = 1_000_000_000
GOOD = (1.0, 2.0, 3.0, 0.0, 0.0, math.sin(0.2), math.cos(0.2))
POSES = [GOOD, (0.5, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0), (0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0),
         (math.nan, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)]
record = st.builds(TFRecord, st.sampled_from(["a", "b", "/b", "", "c"]), st.sampled_from(["b", "c", "/d", "a"]),
                   st.sampled_from([0, SEC, 2 * SEC, 7 * SEC, 30 * SEC, -1]), st.sampled_from(POSES))


def state(buf: Buffer) -> list[object]:
    out: list[object] = [buf.all_frames_as_yaml(), buf.all_frame_names()]
    for cache in buf._caches:
        if cache is None:
            continue
        if hasattr(cache, "arrays"):
            out.append([a.tolist() for a in cache.arrays()])
        else:
            out.append((cache.pose, cache.parent))
    return out


@settings(max_examples=80, deadline=None)
@given(st.lists(st.lists(record, max_size=8), max_size=6), st.booleans())
def test_the_same_state_failures_and_logs_as_one_insert_per_record(messages: list[list[TFRecord]],
                                                                  static: bool) -> None:
    one, batch = Buffer(cache_time=Duration(seconds=10)), Buffer(cache_time=Duration(seconds=10))
    logger = logging.getLogger("robotmodel.tf")
    for msg in messages:
        handler_one, handler_batch = _Collect(), _Collect()
        logger.addHandler(handler_one)
        failed_one = []
        for rec in msg:
            try:
                one.insert(rec.parent, rec.child, rec.stamp_ns, rec.pose, "who", static)
            except TransformException as exc:
                failed_one.append((rec, type(exc), str(exc)))
        logger.removeHandler(handler_one)
        logger.addHandler(handler_batch)
        failed_batch = [(rec, type(exc), str(exc)) for rec, exc in batch.insert_records(msg, "who", static)]
        logger.removeHandler(handler_batch)
        assert failed_batch == failed_one
        # The same texts; within one message the checks' come before TF_OLD_DATA's (logged once unlocked).
        assert sorted(handler_batch.lines) == sorted(handler_one.lines)
        assert state(batch) == state(one)


class _Collect(logging.Handler):
    def __init__(self) -> None:
        super().__init__()
        self.lines: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.lines.append(record.getMessage())


def test_a_waiting_request_is_answered_once_the_message_is_in() -> None:
    buf = Buffer()
    future = buf.wait_for_transform_async("a", "c", Time(seconds=1))
    assert not future.done()
    buf.insert_records([TFRecord("a", "b", SEC, GOOD), TFRecord("b", "c", SEC, GOOD)], "who")
    got = future.result(timeout=0)
    assert got.header.frame_id == "a" and got.child_frame_id == "c"
    np.testing.assert_allclose(got.transform.translation.z, 6.0)


def test_a_bad_record_is_reported_and_the_rest_go_in() -> None:
    buf = Buffer()
    failures = buf.insert_records([TFRecord("a", "b", -1, GOOD), TFRecord("a", "c", SEC, GOOD)], "who")
    assert [rec.child for rec, _ in failures] == ["b"]
    assert buf.can_transform("a", "c", Time(seconds=1))
    with pytest.raises(TransformException):
        buf.lookup_transform("a", "b", Time())
