"""TransformBroadcaster and TransformListener in separate processes on a real (zenoh) bus.

The broadcaster sends ``base -> moving`` at 100 Hz with stamps on a 10 ms grid and a pose
known in closed form (tf_children.pose_at). Expected interpolated poses are worked out
here by hand: translation linearly between the two neighbouring samples, rotation about
the fixed z axis with its angle linear in time (SLERP between two rotations about one
axis moves the angle linearly).
"""

from __future__ import annotations

import json
import math
import signal
import time

import numpy as np
from tf_ros.tf_children import pose_at

STEP = 10_000_000


def test_interpolated_lookups_and_timeout_issued_before_data(bus):
    t0 = time.time_ns() // STEP * STEP
    broadcaster = bus.child("broadcaster", "mover", str(t0), "GO")
    broadcaster.wait_line("^READY$")
    listener = bus.child("interp", str(t0))
    listener.wait_line("^WAITING$")
    # The lookup with a 2 s timeout is now pending with no data anywhere; start sending.
    broadcaster.send("go\n")
    got = listener.wait_line(r"^GOT ([0-9.]+)$")
    assert float(got.group(1)) < 2.0
    line = listener.wait_line(r"^\[")
    results = json.loads(line.string)
    assert len(results) == 5
    for res in results:
        k, t = res["k"], res["t"]
        s0, s1 = t0 + k * STEP, t0 + (k + 1) * STEP
        r = (t - s0) / (s1 - s0)
        p0, _ = pose_at(s0, t0)
        p1, _ = pose_at(s1, t0)
        expected_t = [(1 - r) * a + r * b for a, b in zip(p0, p1, strict=True)]
        yaw = (1 - r) * 0.8 * (s0 - t0) / 1e9 + r * 0.8 * (s1 - t0) / 1e9
        expected_q = [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]
        assert res["stamp"] == t
        assert np.allclose(res["translation"], expected_t, atol=1e-12, rtol=0), res
        assert np.allclose(res["rotation"], expected_q, atol=1e-12, rtol=0), res
        # Not simply a neighbouring sample: the interpolation moved y off both of them.
        assert min(abs(res["translation"][1] - p0[1]), abs(res["translation"][1] - p1[1])) > 1e-6
    assert listener.popen.wait(30) == 0
    assert broadcaster.stop() == 0
    assert not any("Traceback" in line for line in listener.err + broadcaster.err)


def test_lookup_waits_for_a_broadcaster_process_started_after_it(bus):
    t0 = time.time_ns() // STEP * STEP
    listener = bus.child("interp", str(t0), "30")
    listener.wait_line("^WAITING$")
    # Only now does the broadcaster process start (its start-up alone takes a while, hence the
    # longer timeout here; the test above holds the 2 s one with a broadcaster already up).
    broadcaster = bus.child("broadcaster", "late_mover", str(t0))
    got = listener.wait_line(r"^GOT ([0-9.]+)$", timeout=60)
    assert float(got.group(1)) < 30.0
    listener.wait_line(r"^\[", timeout=60)
    assert listener.popen.wait(30) == 0
    assert broadcaster.stop() == 0


def stamps_of(proc):
    return [int(line.split()[1]) for line in proc.out if line.startswith("STAMP ")]


def test_kill9_publisher_and_restart_listener_recovers(bus):
    first = bus.child("broadcaster", "mover", str(time.time_ns()))
    # Started first, this process holds the rendezvous port the others connect to.
    first.wait_line("^READY$")
    watcher = bus.child("watch")
    watcher.wait_line(r"^STAMP \d+$")
    first.popen.send_signal(signal.SIGKILL)
    first.popen.wait(10)
    restart_t0 = time.time_ns()
    second = bus.child("broadcaster", "mover", str(restart_t0))
    watcher.wait_for(lambda: any(s >= restart_t0 for s in stamps_of(watcher)), 30.0,
                     "a stamp from the restarted broadcaster")
    assert watcher.stop(signal.SIGTERM) == 0
    assert second.stop() == 0
    # The listener never failed a lookup once data had arrived, and logged nothing.
    after_first = watcher.out[next(i for i, line in enumerate(watcher.out) if line.startswith("STAMP")):]
    assert "NONE" not in after_first
    assert watcher.err == []


def test_garbage_on_tf_is_dropped_with_a_warning_and_listening_goes_on(bus):
    watcher = bus.child("watch")
    watcher.wait_line("^LISTENING$")
    garbage = bus.child("garbage")
    garbage.wait_line("^SENT$")
    warning = watcher.wait_line(r"dropped a message on '/tf'", stream="err")
    assert "tf2_msgs/msg/TFMessage" in warning.string
    assert garbage.popen.wait(30) == 0
    broadcaster = bus.child("broadcaster", "mover", str(time.time_ns()))
    watcher.wait_line(r"^STAMP \d+$")
    assert watcher.stop() == 0
    assert broadcaster.stop() == 0
    assert not any("Traceback" in line for line in watcher.err)
