"""Shared test fixtures: where the real robot files are."""

from __future__ import annotations

import os
import sysconfig
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
# The steering repo's shared/ sits beside the checkout, in CI as on a developer's machine.
CORPUS = Path(os.environ.get("ROBOTMODEL_CORPUS", REPO.parent / "shared" / "corpus"))
BUNDLED = REPO / "urdf"


CMEEL_PREFIX = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix"
# example-robot-data (PyPI, cmeel build) ships its 69 robots as data, no Python module.
ERD_ROBOTS = CMEEL_PREFIX / "share" / "example-robot-data" / "robots"
# urdfdom's own binaries, from the cmeel-urdfdom PyPI package: the reference we match.
CHECK_URDF_BIN = CMEEL_PREFIX / "bin" / "check_urdf"
URDF_TO_GRAPHVIZ_BIN = CMEEL_PREFIX / "bin" / "urdf_to_graphviz"


def erd_urdfs() -> list[Path]:
    """Every URDF file of example-robot-data, sorted (69 with version 6.0.0)."""
    return sorted(ERD_ROBOTS.rglob("*.urdf"))


def urdfdom_env() -> dict[str, str]:
    """Environment in which urdfdom's cmeel binaries find their shared libraries."""
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = f"{CMEEL_PREFIX / 'lib'}:{env.get('LD_LIBRARY_PATH', '')}"
    return env


@pytest.fixture(scope="session")
def corpus() -> Path:
    """The ../shared/corpus folder of real xacro packages."""
    if not CORPUS.is_dir():
        pytest.fail(f"corpus not found at {CORPUS} (set ROBOTMODEL_CORPUS)")
    return CORPUS
