"""``robotmodel topic hz`` and ``param get|set|dump`` against live processes, on the wire each test names."""

from __future__ import annotations

import re
import threading
import time
from typing import Any

import pytest
from conftest import BUNDLED

from robotmodel.bus import Node

ARM = BUNDLED / "arm.urdf.xacro"
RATE = re.compile(r"^average rate: ([\d.]+)$")
DEADLINE_S = 40.0


@pytest.mark.parametrize("bus_wire", ["zenoh", "dds"])
def test_param_get_set_dump_on_robot_state_publisher(procs: Any, bus_wire: str) -> None:
    rsp = procs.cli("robot-state-publisher", str(ARM))
    assert rsp.wait_for(lambda ls: any("Robot initialized" in ln for ln in ls), DEADLINE_S, "stderr"), rsp.errors

    def param(*args: str) -> list[str]:
        proc = procs.cli("param", *args)
        assert proc.popen.wait(DEADLINE_S) == 0, proc.errors
        proc.wait_for(lambda _: False, 0.1)  # the readers drain what is left
        return proc.lines

    # ROS 2's robot_state_publisher declares publish_frequency 20.0 (its README's default).
    assert param("get", "/robot_state_publisher", "publish_frequency") == ["Double value is: 20.0"]
    assert param("set", "/robot_state_publisher", "publish_frequency", "50.0") == ["Set parameter successful"]
    assert param("get", "/robot_state_publisher", "publish_frequency") == ["Double value is: 50.0"]
    dump = param("dump", "/robot_state_publisher")
    assert dump[:2] == ["/robot_state_publisher:", "  ros__parameters:"]
    assert "    publish_frequency: 50.0" in dump
    assert param("list", "/robot_state_publisher")[0] == "/robot_state_publisher:"


def test_topic_hz_within_5_percent_of_a_50_hz_publisher(procs: Any, bus_wire: str) -> None:
    assert bus_wire == "zenoh"
    stop = threading.Event()
    sent: list[int] = []
    with Node("hz_source") as node:
        pub = node.create_publisher("std_msgs/msg/String", "/hz_probe", 10)

        def loop() -> None:
            from robotmodel.bus import typestore

            string = typestore().types["std_msgs/msg/String"](data="x")
            deadline = time.monotonic_ns()
            while not stop.is_set():
                pub.publish(string)
                sent.append(time.monotonic_ns())
                deadline += 20_000_000  # 50 Hz, on absolute deadlines
                stop.wait(max(0.0, (deadline - time.monotonic_ns()) / 1e9))

        thread = threading.Thread(target=loop, daemon=True)
        thread.start()
        try:
            hz = procs.cli("topic", "hz", "/hz_probe", "--spin-time", "1")
            assert hz.wait_for(lambda ls: sum(bool(RATE.match(ln)) for ln in ls) >= 3, DEADLINE_S), hz.errors
        finally:
            stop.set()
            thread.join(5)
    published = (len(sent) - 1) / ((sent[-1] - sent[0]) / 1e9)
    rates = [float(m.group(1)) for ln in hz.lines if (m := RATE.match(ln))]
    assert abs(published - 50.0) / 50.0 < 0.05, published
    assert abs(rates[-1] - 50.0) / 50.0 < 0.05, (rates, published)
    assert re.match(r"^\tmin: [\d.]+s max: [\d.]+s std dev: [\d.]+s window: \d+$", hz.lines[-1]), hz.lines
