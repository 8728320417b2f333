"""``robotmodel run PACKAGE EXECUTABLE ARGS`` (``rosrun``): a tutorial's ``ros2 run`` line runs its stand-in."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from livebus import Bus
from robotmodel.robots import path as robot_path


def _cli(*words: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *words], capture_output=True, text=True,
                          timeout=120, check=False)


def test_run_xacro_prints_what_the_xacro_command_prints() -> None:
    model = str(robot_path("diffbot.urdf.xacro"))
    direct, via_run = _cli("xacro", model), _cli("run", "xacro", "xacro", model)
    assert direct.returncode == via_run.returncode == 0, via_run.stderr
    assert via_run.stdout == direct.stdout and "<robot" in direct.stdout


@pytest.mark.parametrize(("words", "text"), [
    (("run", "turtlesim", "turtlesim_node"), "Package 'turtlesim' not found"),
    (("rosrun", "tf2_ros", "buffer_server"), "No executable found: package 'tf2_ros' has no 'buffer_server'"),
])
def test_a_pair_without_a_stand_in_is_one_line(words: tuple[str, ...], text: str) -> None:
    done = _cli(*words)
    assert done.returncode == 1 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and text in done.stderr, done.stderr


def test_tutorial_ros2_run_lines_meet_on_the_bus(tmp_path: Path) -> None:
    """``ros2 run tf2_ros static_transform_publisher`` (flag form) and ``rosrun tf tf_echo`` as typed."""
    bus = Bus(tmp_path, "dds")
    try:
        bus.robotmodel("run", "tf2_ros", "static_transform_publisher", "--x", "1.5", "--yaw", "0.5",
                       "--frame-id", "world", "--child-frame-id", "camera")
        echo = bus.robotmodel("rosrun", "tf", "tf_echo", "world", "camera")
        echo.wait_line(r"- Translation: \[1\.500, 0\.000, 0\.000\]", timeout=60)
        assert echo.stop() == 0
    finally:
        bus.reap()
