"""ros2cli's options of ``topic hz`` (``--filter``, ``--wall-time``, ``-s``) and ``topic pub`` (QoS), live on zenoh."""

from __future__ import annotations

import re
import threading
import time
from typing import Any

import pytest

from robotmodel.bus import Node
from robotmodel.topic import HzMeter

RATE = re.compile(r"^average rate: ([\d.]+)$")
DEADLINE_S = 40.0


def test_hz_meter_counts_gaps_and_reports_a_second_apart_as_ros2() -> None:
    meter = HzMeter(window=3)
    assert meter.add(0) == ""  # a clock at 0 (no /clock yet) counts nothing
    for t in (1_000, 1_250, 1_500, 2_000):  # ms: gaps 250, 250, 500
        assert meter.add(t * 1_000_000) == ""
    assert meter.report() is None  # the first report only sets when the next may come
    meter.add(3_100 * 1_000_000)  # gap 1100; the window keeps the last 3: 250, 500, 1100
    stats = meter.report()
    assert stats is not None
    assert stats.window == 3
    assert stats.rate == pytest.approx(3 / 1.85)
    assert (stats.min_delta, stats.max_delta) == (0.25, 1.1)
    assert stats.text().splitlines()[1] == f"\tmin: 0.250s max: 1.100s std dev: {stats.std_dev:.5f}s window: 3"
    assert meter.report() is None  # not a second since the last report
    assert meter.add(0) == "time has reset, resetting counters"
    assert meter.report() is None


def test_hz_filter_and_sim_time_against_wall_time(procs: Any, bus_wire: str) -> None:
    """20 messages/s alternating 'a'/'b' and a /clock running at twice the wall clock.

    Filtered to the 'a's: 10 Hz of wall time (--wall-time), 5 Hz of the /clock's time (-s).
    """
    assert bus_wire == "zenoh"
    from robotmodel.msgs.builtin_interfaces import Time
    from robotmodel.msgs.rosgraph_msgs import Clock
    from robotmodel.msgs.std_msgs import String

    stop = threading.Event()
    with Node("hz_source") as node:
        pub = node.create_publisher(String, "/hz_filtered", 10)
        clock = node.create_publisher(Clock, "/clock", 10)

        def loop() -> None:
            start = deadline = time.monotonic_ns()
            tick = 0
            while not stop.is_set():
                sim = 1_000_000_000 + 2 * (time.monotonic_ns() - start)
                clock.publish(Clock(clock=Time(sec=sim // 1_000_000_000, nanosec=sim % 1_000_000_000)))
                pub.publish(String(data="ab"[tick % 2]))
                tick += 1
                deadline += 50_000_000  # 20 Hz on absolute deadlines
                stop.wait(max(0.0, (deadline - time.monotonic_ns()) / 1e9))

        thread = threading.Thread(target=loop, daemon=True)
        thread.start()
        try:
            expr = "m.data == 'a'"
            wall = procs.cli("topic", "hz", "/hz_filtered", "--filter", expr, "--wall-time", "-s", "--spin-time", "1")
            sim = procs.cli("rostopic", "hz", "/hz_filtered", "--filter", expr, "-s", "-w", "50", "--spin-time", "1")
            for proc in (wall, sim):
                assert proc.wait_for(lambda ls: sum(bool(RATE.match(ln)) for ln in ls) >= 2, DEADLINE_S), proc.errors
        finally:
            stop.set()
            thread.join(5)
    wall_rate = [float(m.group(1)) for ln in wall.lines if (m := RATE.match(ln))][-1]
    sim_rate = [float(m.group(1)) for ln in sim.lines if (m := RATE.match(ln))][-1]
    assert abs(wall_rate - 10.0) / 10.0 < 0.1, wall.lines
    assert abs(sim_rate - 5.0) / 5.0 < 0.1, sim.lines


def test_hz_filter_errors_name_the_expression(procs: Any, bus_wire: str) -> None:
    assert bus_wire == "zenoh"
    bad = procs.cli("topic", "hz", "/any", "--filter", "m.data ==")
    assert bad.popen.wait(DEADLINE_S) == 1
    bad.wait_for(lambda _: False, 0.1)
    assert bad.errors == ["robotmodel topic: error: --filter 'm.data ==' is not a Python expression: invalid syntax"], bad.errors


def test_pub_qos_options_node_name_and_stdin_show_in_topic_info(procs: Any, bus_wire: str) -> None:
    assert bus_wire == "zenoh"
    pub = procs.cli("topic", "pub", "--stdin", "-r", "5", "-n", "qos_talker", "--qos-profile", "sensor_data",
                    "--qos-depth", "3", "--qos-durability", "transient_local", "/qos_probe", "std_msgs/msg/String")
    assert pub.popen.stdin is not None
    pub.popen.stdin.write("data: piped\n")
    pub.popen.stdin.close()
    assert pub.wait_for(lambda ls: "publishing #1: std_msgs.msg.String(data='piped')" in ls, DEADLINE_S), pub.errors
    info = procs.cli("topic", "info", "-v", "/qos_probe", "--spin-time", "1")
    assert info.popen.wait(DEADLINE_S) == 0, info.errors
    info.wait_for(lambda _: False, 0.1)
    # sensor_data is rclpy's best effort, keep last 5; depth and durability overridden.
    for line in ("Node name: qos_talker", "  Reliability: BEST_EFFORT", "  History (Depth): KEEP_LAST (3)",
                 "  Durability: TRANSIENT_LOCAL"):
        assert line in info.lines, info.lines


def test_pub_max_wait_time_gives_up_with_ros2s_words(procs: Any, bus_wire: str) -> None:
    assert bus_wire == "zenoh"
    pub = procs.cli("topic", "pub", "-1", "--max-wait-time-secs", "0.3", "/nobody_listens", "std_msgs/msg/String")
    assert pub.popen.wait(DEADLINE_S) == 1
    pub.wait_for(lambda _: False, 0.1)
    assert pub.lines == ["Waiting for at least 1 matching subscription(s)..."], pub.lines
    assert pub.errors == ["robotmodel topic: error: Timed out waiting for subscribers: Expected 1 subcribers but "
                          "only got 0 subscribers"], pub.errors


def test_pub_yaml_header_auto_and_time_now_are_stamped() -> None:
    from robotmodel.msgs._dynamic import message_class
    from robotmodel.topic import message_from_yaml

    stamps: list[Any] = []
    msg = message_from_yaml("geometry_msgs/msg/PoseStamped", "{header: auto, pose: {position: {x: 1.5}}}", stamps)
    assert (msg.header.stamp.sec, msg.header.frame_id, msg.pose.position.x) == (0, "", 1.5)
    (setter,) = stamps  # topic pub calls it with the time of each publication
    setter(message_class("builtin_interfaces/msg/Time")(sec=7, nanosec=8))
    assert (msg.header.stamp.sec, msg.header.stamp.nanosec) == (7, 8)
    before = time.time_ns()
    header = message_from_yaml("std_msgs/msg/Header", "{stamp: now, frame_id: map}")  # no list: stamped once, now
    after = time.time_ns()
    assert before <= header.stamp.sec * 1_000_000_000 + header.stamp.nanosec <= after
    assert header.frame_id == "map"
