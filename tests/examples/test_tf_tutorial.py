"""tf_broadcaster.py and tf_listener.py as two processes, with the test process on the bus too."""

from __future__ import annotations

import itertools
import re
import statistics
import threading
import time

import pytest

from robotmodel.bus import Node
from robotmodel.msgs import TFMessage


def test_listener_prints_camera_at_10_hz_from_a_50_hz_broadcaster(live):
    stamps: list[int] = []
    lock = threading.Lock()

    def on_tf(msg: TFMessage) -> None:
        with lock:
            stamps.extend(t.header.stamp.sec * 10**9 + t.header.stamp.nanosec for t in msg.transforms
                          if (t.header.frame_id, t.child_frame_id) == ("base_link", "camera_link"))

    with Node("tf_check") as node:
        node.create_subscription(TFMessage, "/tf", on_tf, 100)
        # The listener first: until the broadcaster runs, each lookup raises LookupException,
        # which the tutorial's loop swallows (nothing printed, no crash).
        listener = live.example("tf_listener.py", "--duration", "8")
        listener.wait_for(lambda: listener.popen.poll() is None, 5, "listener running")
        before = time.time_ns()
        broadcaster = live.example("tf_broadcaster.py", "--duration", "6")
        broadcaster.wait_line("broadcasting")
        listener.wait_line("camera_link in base_link", timeout=30)
        assert broadcaster.popen.wait(30) == 0
        assert listener.popen.wait(30) == 0
    lines = [re.search(r"at (\d+): translation \(([-\d.]+), ([-\d.]+), ([-\d.]+)\) rotation \(([-\d., ]+)\)", line)
             for line in listener.out]
    assert all(lines), listener.out
    assert {m.groups()[1:] for m in lines} == {("0.100", "0.000", "0.200", "0.000, 0.000, 0.000, 1.000")}
    assert "Traceback" not in "\n".join(listener.err + broadcaster.err)
    # Nothing printed (and nothing raised) before the broadcaster ran.
    assert min(int(m.group(1)) for m in lines) > before
    # 50 Hz on /tf, seen from the test process: stamps 20 ms apart.
    with lock:
        seen = sorted(stamps)
    assert len(seen) > 100
    assert statistics.median(b - a for a, b in itertools.pairwise(seen)) / 1e6 == pytest.approx(20, abs=2)
    # 10 Hz lookups of the latest transform: printed stamps about 100 ms apart.
    printed = [int(m.group(1)) for m in lines]
    assert len(printed) >= 20
    assert statistics.median(b - a for a, b in itertools.pairwise(printed)) / 1e6 == pytest.approx(100, abs=25)
