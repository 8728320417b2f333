"""The default wire follows the environment as ROS's setup does: a sourced ROS 1 means ROS 1, else RMW_IMPLEMENTATION."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robotmodel.bus import BACKENDS, BusError, default_wire


@pytest.mark.parametrize(("environ", "wire"), [
    ({}, "dds"),  # a stock ROS 2 speaks Fast DDS without naming it
    ({"ROS_VERSION": "1", "ROS_MASTER_URI": "http://localhost:11311"}, "ros1"),
    ({"ROS_VERSION": "1", "ROS_MASTER_URI": "http://localhost:11311", "RMW_IMPLEMENTATION": "rmw_zenoh_cpp"},
     "ros1"),  # a sourced ROS 1 wins over a leftover ROS 2 variable, as its setup.bash means
    ({"ROS_VERSION": "1"}, "dds"),  # no master named: not a sourced ROS 1
    ({"ROS_MASTER_URI": "http://localhost:11311"}, "dds"),  # a leftover URI alone decides nothing
    ({"ROS_VERSION": "2", "ROS_MASTER_URI": "http://localhost:11311"}, "dds"),
    ({"ROS_VERSION": "2", "RMW_IMPLEMENTATION": "rmw_zenoh_cpp"}, "zenoh"),
    ({"RMW_IMPLEMENTATION": " rmw_zenoh_cpp "}, "zenoh"),
    ({"ROS_VERSION": "2", "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp"}, "dds"),
    ({"RMW_IMPLEMENTATION": "rmw_cyclonedds_cpp"}, "dds"),
    ({"RMW_IMPLEMENTATION": "rmw_connextdds"}, "dds"),
    ({"RMW_IMPLEMENTATION": ""}, "dds"),
], ids=["nothing", "ros1", "ros1-over-rmw", "ros1-no-master", "uri-only", "ros2", "ros2-zenoh", "zenoh-spaces",
        "fastrtps", "cyclonedds", "connext", "empty-rmw"])
def test_default_wire_from_the_environment(environ: dict[str, str], wire: str) -> None:
    assert default_wire(environ) == wire
    assert wire in BACKENDS


def test_an_unknown_rmw_is_one_clear_error() -> None:
    with pytest.raises(BusError) as caught:
        default_wire({"RMW_IMPLEMENTATION": "rmw_nonesuch_cpp"})
    text = str(caught.value)
    assert "\n" not in text and "RMW_IMPLEMENTATION 'rmw_nonesuch_cpp'" in text and "rmw_zenoh_cpp" in text


def test_a_command_under_an_unknown_rmw_says_so_in_one_line(tmp_path: Path) -> None:
    env = {"RMW_IMPLEMENTATION": "rmw_nonesuch_cpp", "PATH": "/usr/bin", "ROS_HOME": str(tmp_path)}
    done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "list"], env=env, check=False,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1 and done.stdout == ""
    (line,) = done.stderr.splitlines()
    assert "RMW_IMPLEMENTATION 'rmw_nonesuch_cpp' is not a middleware robotmodel speaks" in line


def test_a_context_without_a_wire_takes_the_environments() -> None:
    # A sourced ROS 1 whose master is not there: the Context tries the ROS 1 wire and says so.
    code = ("import robotmodel.bus as b\n"
            "try:\n    b.Context()\nexcept b.BusError as e:\n    print(e)\n")
    env = {"ROS_VERSION": "1", "ROS_MASTER_URI": "http://127.0.0.1:9", "PATH": "/usr/bin"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60,
                         check=True).stdout
    assert "master http://127.0.0.1:9 is unreachable" in out
