"""tests/standins: message packages for real ROS 1 that Debian lacks, built once per test session."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def ros1_msgs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A directory holding genpy-built ``turtlesim.msg`` and ``nav_msgs.msg`` (for PYTHONPATH)."""
    from ros1helpers import MISSING, SYSTEM_PYTHON

    if MISSING:
        pytest.skip(MISSING)
    out = tmp_path_factory.mktemp("ros1_msgs")
    subprocess.run([SYSTEM_PYTHON, str(Path(__file__).with_name("ros1_msggen.py")), str(out)], check=True,
                   timeout=120, capture_output=True)
    return out
