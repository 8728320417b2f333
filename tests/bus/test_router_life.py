"""The zenoh router's own life: started detached by the first tool, outliving it, ended by ``router --stop``.

Real processes on this test's own port and domain (``bus_env``); the router a tool starts is
stopped after each test (tests/conftest.py). The rmw_zenoh client that is not ours is
zenoh-ros2-sdk (a test extra); without it that test skips with one line.
"""

from __future__ import annotations

import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
import zenoh

SDK_PEER = Path(__file__).with_name("zenoh_sdk_peer.py")
DEADLINE_S = 30.0


def listening(port: int) -> bool:
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=2.0):
            return True
    except OSError:
        return False


def wait_listening(port: int) -> None:
    end = time.monotonic() + DEADLINE_S
    while not listening(port):
        assert time.monotonic() < end, f"nothing listens on port {port} within {DEADLINE_S} s"
        time.sleep(0.02)


def robotmodel(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], env=env, capture_output=True,
                          text=True, timeout=DEADLINE_S, check=False)


@pytest.fixture
def zenoh_env(bus_env: dict[str, str]) -> dict[str, str]:
    """The test's bus on the zenoh wire, named as a ROS 2 shell names rmw_zenoh."""
    return dict(bus_env, RMW_IMPLEMENTATION="rmw_zenoh_cpp")


def test_an_rmw_zenoh_client_keeps_its_router_and_meets_the_next_tool(procs: Any, zenoh_env: dict[str, str]) -> None:
    pytest.importorskip("zenoh_ros2_sdk", reason="zenoh-ros2-sdk is not installed (a test extra)")
    port = int(zenoh_env["ROBOTMODEL_ZENOH_PORT"])
    procs.env = zenoh_env
    echo = ("topic", "echo", "/chatter", "std_msgs/msg/String", "--once")
    first = procs.run(procs.cli_args(*echo))
    wait_listening(port)  # the first tool found no router and started one
    client = procs.run([sys.executable, str(SDK_PEER), "talker", str(port)])
    client.wait_line("ready", timeout=DEADLINE_S)
    first.wait_line("data: hello", timeout=DEADLINE_S)
    assert first.popen.wait(DEADLINE_S) == 0
    second = procs.run(procs.cli_args(*echo))
    second.wait_line("data: hello", timeout=DEADLINE_S)
    assert second.popen.wait(DEADLINE_S) == 0
    # The client printed each change of its routers: one router from its start on, never lost
    # when the first tool exited (its router was not that tool).
    routers = [line.split()[1:] for line in client.lines if line.startswith("routers")]
    linked = [r for r in routers if r]
    assert len(linked) == 1 and len(linked[0]) == 1 and routers[-1] == linked[0], routers


def test_router_stop_frees_the_port_for_a_router_like_rmw_zenohd(zenoh_env: dict[str, str]) -> None:
    port = int(zenoh_env["ROBOTMODEL_ZENOH_PORT"])
    assert robotmodel(zenoh_env, "topic", "list").returncode == 0
    assert listening(port), "the router the tool started went with it"
    stopped = robotmodel(zenoh_env, "router", "--stop")
    assert (stopped.returncode, stopped.stdout) == (0, "The router has been stopped\n"), stopped.stderr
    assert not listening(port)
    # rmw_zenohd's own settings (DEFAULT_RMW_ZENOH_ROUTER_CONFIG.json5), on loopback here.
    config = zenoh.Config()
    for key, value in (("mode", '"router"'), ("listen/endpoints", f'["tcp/127.0.0.1:{port}"]'),
                       ("scouting/multicast/enabled", "false"), ("timestamping/enabled", "true"),
                       ("routing/router/peers_failover_brokering", "true")):
        config.insert_json5(key, value)
    rmw_zenohd = zenoh.open(config)
    try:
        listed = robotmodel(zenoh_env, "topic", "list")
        assert listed.returncode == 0, listed.stderr
        # That tool met rmw_zenohd's stand-in and started no router of its own.
        again = robotmodel(zenoh_env, "router", "--stop")
        assert (again.returncode, again.stdout) == (0, "The router is not running\n"), again.stderr
        assert listening(port)
    finally:
        rmw_zenohd.close()  # type: ignore[no-untyped-call]
