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
BW = re.compile(r"^([\d.]+) B/s from \d+ messages$")
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
    info = procs.cli("topic", "info", "/tf_static", "--spin-time", "1")
    assert info.popen.wait(DEADLINE_S) == 0, info.errors
    assert info.wait_for(lambda ls: ls == ["Type: tf2_msgs/msg/TFMessage", "Publisher count: 1",
                                           "Subscription count: 0"], 2), info.lines
    nodes = procs.cli("node", "list", "--spin-time", "1")
    assert nodes.popen.wait(DEADLINE_S) == 0, nodes.errors
    assert nodes.wait_for(lambda ls: "/robot_state_publisher" in ls, 2), nodes.lines


def test_topic_hz_and_bw_wait_for_a_50_hz_publisher_and_measure_it(procs: Any, bus_wire: str) -> None:
    assert bus_wire == "zenoh"
    stop = threading.Event()
    sent: list[int] = []
    # Started before anyone publishes: both wait for the topic after ros2's warning, as ros2's tools do.
    hz = procs.cli("topic", "hz", "/hz_probe", "--spin-time", "1")
    bw = procs.cli("rostopic", "bw", "/hz_probe", "--spin-time", "1")
    for proc in (hz, bw):
        assert proc.wait_for(lambda ls: "WARNING: topic [/hz_probe] does not appear to be published yet" in ls,
                             DEADLINE_S), proc.errors
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
            assert hz.wait_for(lambda ls: sum(bool(RATE.match(ln)) for ln in ls) >= 3, DEADLINE_S), hz.errors
            assert bw.wait_for(lambda ls: sum(bool(BW.match(ln)) for ln in ls) >= 3, DEADLINE_S), bw.errors
        finally:
            stop.set()
            thread.join(5)
    published = (len(sent) - 1) / ((sent[-1] - sent[0]) / 1e9)
    assert abs(published - 50.0) / 50.0 < 0.05, published
    rate, rate_detail = _last_pair(hz.lines, RATE)
    assert abs(float(rate.group(1)) - 50.0) / 50.0 < 0.05, (hz.lines, published)
    assert re.match(r"^\tmin: [\d.]+s max: [\d.]+s std dev: [\d.]+s window: \d+$", rate_detail), hz.lines
    band, band_detail = _last_pair(bw.lines, BW)
    # A std_msgs/String "x" in CDR: 4 bytes of encapsulation, a 4-byte length, "x" and its NUL.
    assert band_detail == "\tMessage size mean: 10.00 B min: 10.00 B max: 10.00 B", bw.lines
    assert abs(float(band.group(1)) - 500.0) / 500.0 < 0.05, bw.lines


def _last_pair(lines: list[str], first: re.Pattern[str]) -> tuple[re.Match[str], str]:
    """The last report whose two lines have both arrived: the first line's match, the second line."""
    for i in range(len(lines) - 2, -1, -1):
        if m := first.match(lines[i]):
            return m, lines[i + 1]
    pytest.fail(f"no complete report in {lines}")


def test_topic_pub_yaml_fills_named_fields_and_refuses_wrong_ones() -> None:
    from robotmodel.errors import BusError
    from robotmodel.topic import message_from_yaml

    msg = message_from_yaml("sensor_msgs/JointState", "{name: [a], position: [1], header: {stamp: {sec: 3}}}")
    assert (msg.name, msg.position, msg.header.stamp.sec, msg.header.frame_id, msg.velocity) == (["a"], [1.0], 3, "",
                                                                                                 [])
    with pytest.raises(BusError, match="'String' object has no attribute 'dta'"):
        message_from_yaml("std_msgs/msg/String", "{dta: x}")
    with pytest.raises(BusError, match="The 'data' field must be of type 'str'"):
        message_from_yaml("std_msgs/msg/String", "{data: 5}")
    with pytest.raises(BusError, match="The passed message type is invalid"):
        message_from_yaml("std_msgs/msg/Nope", "")
