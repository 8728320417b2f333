"""The ``ros1`` fixture for tests/standins: a private real roscore per test (see tests/ros1helpers.py)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from ros1helpers import MISSING, Ros1World


@pytest.fixture
def ros1(tmp_path: Path) -> Iterator[Ros1World]:
    """A private real roscore for this test (skips where Debian's ROS 1 is absent)."""
    if MISSING:
        pytest.skip(MISSING)
    world = Ros1World(tmp_path / "ros_home")
    try:
        yield world
    finally:
        world.reap()
