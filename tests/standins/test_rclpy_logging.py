"""``--ros-args --log-level [logger:=]LEVEL`` as rcl applies it, compared with the real rclpy.

``rclpy_logging_probe.py`` runs with robotmodel's rclpy (DDS wire) and, its imports
swapped, with Jazzy's rclpy from PyPI (``.venv-rclpy``, Fast DDS): the lines its three
loggers print (severity, logger, text; not the stamps) and their effective levels must be
the same. A node command (static_transform_publisher) follows the level too.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from livebus import Bus, DomainLease
from standins.test_rclpy_params import RCLPY, real_variant

HERE = Path(__file__).resolve().parent
PROBE = HERE / "rclpy_logging_probe.py"
LINE = re.compile(r"^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[\d+\.\d{9}\] \[(probe|probe\.child|other)\]: (.*)$", re.M)
REAL_IMPORTS = [("from robotmodel.rclpy.logging", "from rclpy.logging")]


def _lines(stderr: str) -> list[tuple[str, str, str]]:
    return LINE.findall(stderr)


@pytest.mark.parametrize("levels", [["--log-level", "probe:=debug"],
                                    ["--log-level", "warn", "--log-level", "probe.child:=debug"]],
                         ids=["one-logger", "default-and-child"])
def test_log_levels_as_the_real_rclpy(tmp_path: Path, levels: list[str]) -> None:
    if not RCLPY.exists():
        pytest.skip(f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)")
    text = PROBE.read_text()
    for ours_import, theirs in REAL_IMPORTS:
        text = text.replace(ours_import, theirs)
    real = tmp_path / "real_probe.py"
    real.write_text(real_variant(text))
    args = ["--ros-args", *levels]
    base = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV", "ROS_", "RMW_"))}
    lease = DomainLease()
    try:
        env = {**base, "ROS_DOMAIN_ID": str(lease.domain_id), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
               "ROS_HOME": str(tmp_path)}
        theirs = subprocess.run([str(RCLPY), str(real), *args], capture_output=True, text=True, timeout=120,
                                check=False, env={**env, "RMW_IMPLEMENTATION": "rmw_fastrtps_cpp"})
        ours = subprocess.run([sys.executable, str(PROBE), *args], capture_output=True, text=True, timeout=120,
                              check=False, env={**env, "RMW_IMPLEMENTATION": "rmw_cyclonedds_cpp"})
    finally:
        lease.release()
    assert theirs.returncode == 0, theirs.stderr
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout.splitlines() == theirs.stdout.splitlines()
    assert _lines(ours.stderr) == _lines(theirs.stderr)
    assert ("DEBUG", "probe.child", "debug line") in _lines(ours.stderr)  # a level was set: not the default


def test_a_node_command_follows_the_log_level(tmp_path: Path) -> None:
    """static_transform_publisher's INFO line goes at ``--log-level warn``; its transform still reaches tf2_echo."""
    bus = Bus(tmp_path, "dds")
    try:
        loud = bus.robotmodel("static_transform_publisher", "--x", "1", "--frame-id", "a", "--child-frame-id", "b")
        loud.wait_line(r"\[INFO\] .*\[static_transform_publisher", stream="err", timeout=60)
        quiet = bus.robotmodel("static_transform_publisher", "--x", "2", "--frame-id", "a", "--child-frame-id", "c",
                               "--ros-args", "--log-level", "warn")
        echo = bus.robotmodel("tf2_echo", "a", "c")
        echo.wait_line(r"Translation: \[2\.000, 0\.000, 0\.000\]", timeout=60)
        assert quiet.stop() == 0
        assert not any("[INFO]" in line for line in quiet.err), quiet.err
    finally:
        bus.reap()
