"""The default wire follows the environment as ROS's setup does: a sourced ROS 1 means the ROS 1 wire."""

from __future__ import annotations

import subprocess
import sys

import pytest

from robotmodel.bus import BACKENDS, default_wire


@pytest.mark.parametrize(("environ", "wire"), [
    ({}, "zenoh"),
    ({"ROS_VERSION": "1", "ROS_MASTER_URI": "http://localhost:11311"}, "ros1"),
    ({"ROS_VERSION": "1"}, "zenoh"),  # no master named: not a sourced ROS 1
    ({"ROS_MASTER_URI": "http://localhost:11311"}, "zenoh"),  # a leftover URI alone decides nothing
    ({"ROS_VERSION": "2", "ROS_MASTER_URI": "http://localhost:11311"}, "zenoh"),
    ({"ROS_VERSION": "2", "RMW_IMPLEMENTATION": "rmw_zenoh_cpp"}, "zenoh"),
], ids=["nothing", "ros1", "ros1-no-master", "uri-only", "ros2", "ros2-zenoh"])
def test_default_wire_from_the_environment(environ: dict[str, str], wire: str) -> None:
    assert default_wire(environ) == wire
    assert wire in BACKENDS


def test_a_context_without_a_wire_takes_the_environments() -> None:
    # A sourced ROS 1 whose master is not there: the Context tries the ROS 1 wire and says so.
    code = ("import robotmodel.bus as b\n"
            "try:\n    b.Context()\nexcept b.BusError as e:\n    print(e)\n")
    env = {"ROS_VERSION": "1", "ROS_MASTER_URI": "http://127.0.0.1:9", "PATH": "/usr/bin"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60,
                         check=True).stdout
    assert "master http://127.0.0.1:9 is unreachable" in out
