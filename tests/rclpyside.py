"""The real ROS 2 for the DDS tests: Jazzy's rclpy on Fast DDS in its own interpreter (``.venv-rclpy``).

``ROBOTMODEL_RCLPY_PYTHON`` names the interpreter (default ``.venv-rclpy/bin/python`` in the
checkout, which ``.ci/rclpy-venv`` makes); :data:`MISSING` says why the tests skip without it.
The roles it can play are in ``tests/bus/dds/rclpy_peer.py``.
"""

from __future__ import annotations

import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PEER = ROOT / "tests" / "bus" / "dds" / "rclpy_peer.py"
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(ROOT / ".venv-rclpy" / "bin" / "python")))
MISSING = "" if RCLPY.exists() else f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)"
# Generous for a loaded 2-core machine (Fast DDS and Cyclone each discover in about a second).
DEADLINE_S = 30.0


def rclpy_env(bus_env: dict[str, str], home: Path) -> dict[str, str]:
    """The test's bus environment for rclpy: Fast DDS, discovery on loopback, its own ROS_HOME."""
    env = {k: v for k, v in bus_env.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    env.update(RMW_IMPLEMENTATION="rmw_fastrtps_cpp", ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"), PYTHONUNBUFFERED="1")
    env.pop("ROS_LOCALHOST_ONLY", None)
    return env
