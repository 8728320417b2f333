"""ROS 2 services on the zenoh wire against an rmw_zenoh implementation that is not ours (zenoh-ros2-sdk).

The SDK (a test extra; without it these skip with one line) builds its service keys, liveliness
tokens, attachments and RIHS01 type hashes itself from ROS's .srv texts (``zenoh_sdk_services.py``),
so a call that gets through shows robotmodel's key, type hash and attachment read as another
rmw_zenoh reads them. Both directions: the SDK's parameter client reads and sets robotmodel's
robot_state_publisher's parameters (expected values are the URDF files' texts and the
parameters robot_state_publisher declares), and robotmodel's client calls the SDK's server.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from livebus import Bus

HERE = Path(__file__).resolve().parent
PEER = HERE / "zenoh_sdk_services.py"
DEADLINE_S = 30.0
# The types of ROS's rcl_interfaces/msg/ParameterType.
PARAMETER_STRING, PARAMETER_DOUBLE = 4, 3


def urdf(height: float) -> str:
    return (f'<robot name="mast"><link name="base"/><link name="top"/>'
            f'<joint name="lift" type="prismatic"><parent link="base"/><child link="top"/>'
            f'<origin xyz="0 0 {height}"/><axis xyz="0 0 1"/>'
            f'<limit lower="0" upper="1" effort="1" velocity="1"/></joint></robot>\n')


@pytest.fixture
def zenoh_bus(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Bus]:
    pytest.importorskip("zenoh_ros2_sdk", reason="zenoh-ros2-sdk is not installed (a test extra)")
    bus = Bus(tmp_path, "zenoh")
    bus.env["ROS_HOME"] = str(tmp_path)
    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "RMW_IMPLEMENTATION"):
        monkeypatch.setenv(key, bus.env[key])
    try:
        yield bus
    finally:
        bus.reap()


def test_an_rmw_zenoh_parameter_client_reads_and_sets_robot_state_publisher(zenoh_bus: Bus, tmp_path: Path) -> None:
    first, second = tmp_path / "first.urdf", tmp_path / "second.urdf"
    first.write_text(urdf(1.0))
    second.write_text(urdf(2.0))
    rsp = zenoh_bus.robotmodel("robot-state-publisher", str(first), "--ros-args", "-p", "publish_frequency:=7.5")
    rsp.wait_line(r"Robot initialized", stream="err")
    port = zenoh_bus.env["ROBOTMODEL_ZENOH_PORT"]
    client = zenoh_bus.start(sys.executable, str(PEER), "param_client", port, "/robot_state_publisher", str(second))
    assert client.popen.wait(DEADLINE_S * 3) == 0, "\n".join(client.out + client.err[-30:])
    answers = [(line.split(" ", 1)[0], json.loads(line.split(" ", 1)[1])) for line in client.out]
    # robot_state_publisher's parameters (ROS 2 Jazzy's RSP declares these; use_sim_time every node has).
    assert answers[0] == ("list", ["frame_prefix", "ignore_timestamp", "publish_frequency", "robot_description",
                                   "use_sim_time"])
    # The reply names its request as rmw_zenoh's server does: the request's sequence number and the
    # client's GID (rmw_service_data.cpp, send_response), and a fresh source time.
    assert answers.pop(1) == ("reply_attachment", {"sequence_number": 41, "sent": 41, "gid_is_the_client's": True,
                                                   "stamped_after_the_request": True})
    assert answers[1] == ("get", [{"type": PARAMETER_STRING, "string": first.read_text(), "double": 0.0},
                                  {"type": PARAMETER_DOUBLE, "string": "", "double": 7.5}])
    # robot_description takes the second file; publish_frequency refuses a string as rclcpp does.
    assert answers[2][0] == "set"
    assert answers[2][1][0] == [True, ""]
    assert answers[2][1][1][0] is False and "publish_frequency" in answers[2][1][1][1]
    assert answers[3] == ("get", [{"type": PARAMETER_STRING, "string": second.read_text(), "double": 0.0},
                                  {"type": PARAMETER_DOUBLE, "string": "", "double": 7.5}])
    assert len(answers) == 4
    assert rsp.stop() == 0


def test_a_robotmodel_client_calls_an_rmw_zenoh_server(zenoh_bus: Bus) -> None:
    from robotmodel.bus import Context, Node
    from robotmodel.msgs._dynamic import service_class

    AddTwoInts = service_class("example_interfaces/srv/AddTwoInts")

    ctx = Context(backend="zenoh", domain_id=int(zenoh_bus.env["ROS_DOMAIN_ID"]))
    try:
        node = Node("adder_client", context=ctx)  # its context starts the router the SDK joins
        client = node.create_client("example_interfaces/srv/AddTwoInts", "/add_two_ints")
        server = zenoh_bus.start(sys.executable, str(PEER), "add_server", zenoh_bus.env["ROBOTMODEL_ZENOH_PORT"])
        server.wait_line("^ready$", DEADLINE_S)
        assert client.wait_for_service(DEADLINE_S), "the SDK's server was never seen (its SS token)"
        for a, b in ((2, 3), (-40, 1 << 40)):
            assert client.call(AddTwoInts.Request(a=a, b=b), DEADLINE_S).sum == a + b
        server.wait_line(f"^served {-40} {1 << 40}$", DEADLINE_S)
        server.popen.stdin.close()  # type: ignore[union-attr]
        assert server.popen.wait(DEADLINE_S) == 0
    finally:
        ctx.close()
