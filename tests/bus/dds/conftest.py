"""The tests here run on the DDS wire: the processes they start speak it (RMW_IMPLEMENTATION)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from rclpyside import DEADLINE_S, MISSING, PEER, RCLPY, rclpy_env


@pytest.fixture
def bus_wire() -> str:
    """The DDS wire, for ``bus_env`` and the processes ``procs`` starts."""
    return "dds"


@pytest.fixture
def rclpy(procs: Any, bus_env: dict[str, str], tmp_path: Path) -> Callable[..., Any]:
    """Start a role of rclpy_peer.py on Fast DDS in this test's domain, kept on this machine (skips without rclpy)."""
    if MISSING:
        pytest.skip(MISSING)
    env = rclpy_env(bus_env, tmp_path)

    def start(*args: str) -> Any:
        proc = procs.run([str(RCLPY), str(PEER), *args], env=env)
        proc.wait_line("ready", timeout=DEADLINE_S)
        return proc

    return start
