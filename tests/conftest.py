"""Shared test fixtures: where the real robot files are, and a private real ROS 1 master."""

from __future__ import annotations

import atexit
import os
import re
import shutil
import sysconfig
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, settings

# Property tests run on a loaded 2-core machine beside live process tests: no per-example
# deadline and no too-slow health check (both measure the machine, not the code), and in CI
# the examples are derived from the test, so a run is repeatable.
settings.register_profile(
    "robotmodel", deadline=None, suppress_health_check=[HealthCheck.too_slow],
    derandomize=bool(os.environ.get("CI")), print_blob=True,
)
settings.load_profile("robotmodel")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Run the slow tests (each pip-installs robotmodel into a new venv) first.

    Collected in name order they came last, and under xdist a worker that starts a minutes-long
    test at the end holds up the whole run; started first, each on its own worker (xdist hands
    the first tests out round robin), they overlap the rest of the suite.
    """
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)

# A developer's shell with ROS 1 sourced (ROS_VERSION=1, ROS_MASTER_URI) would move every
# process the tests start onto the ROS 1 wire (robotmodel.bus.default_wire); the tests name
# the ROS 1 wire where they mean it (tests/ros1, the conformance suite's "ros1" cases).
os.environ.pop("ROS_VERSION", None)
# Every test names its wire (robotmodel's own default is DDS unless the shell says otherwise):
# the live fixtures set RMW_IMPLEMENTATION per bus (livebus.set_wire, tests/bus's ``wire``),
# and what starts outside them (an in-process Context() without a backend, a child started
# with this environment) is on zenoh, the wire those tests were written for.
os.environ["RMW_IMPLEMENTATION"] = "rmw_zenoh_cpp"

# A zenoh-wire tool that finds no router starts one detached, to outlive it (robotmodel.bus._router).
# Each test process (each xdist worker) gets a runtime directory of its own, where those routers
# leave their claims, and every router a test started is stopped after that test: none is left
# behind, and a router of the other worker's test is never touched. (Set once per process: some
# tests import this module a second time, as `conftest`.)
_RUN_PREFIX = f"robotmodel-test-run-{os.getpid()}-"
if Path(os.environ.get("XDG_RUNTIME_DIR", "")).name.startswith(_RUN_PREFIX):
    RUNTIME_DIR = Path(os.environ["XDG_RUNTIME_DIR"])
else:
    RUNTIME_DIR = Path(tempfile.mkdtemp(prefix=_RUN_PREFIX))
    os.environ["XDG_RUNTIME_DIR"] = str(RUNTIME_DIR)
    atexit.register(shutil.rmtree, RUNTIME_DIR, ignore_errors=True)


@pytest.fixture(autouse=True)
def _routers_stopped() -> Iterator[None]:
    """Stop the zenoh routers this test's tools started in the background."""
    yield
    claims = RUNTIME_DIR / "robotmodel"
    found = sorted(claims.glob("router-*")) if claims.is_dir() else []
    if found:
        from robotmodel.bus import stop_router

        for port in {int(m[1]) for f in found if (m := re.match(r"router-(\d+)", f.name))}:
            stop_router(port)
        for f in found:
            f.unlink(missing_ok=True)


REPO = Path(__file__).resolve().parents[1]
# Real robot packages for the corpus tests: $ROBOTMODEL_CORPUS, else shared/corpus beside the
# checkout. Optional: a fresh clone without it skips those tests (see the corpus fixture).
CORPUS = Path(os.environ.get("ROBOTMODEL_CORPUS", REPO.parent / "shared" / "corpus"))
CORPUS_MISSING = f"corpus not found at {CORPUS} (set ROBOTMODEL_CORPUS to run these tests)"
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
    """The corpus folder of real xacro packages; the test skips, with one line saying why, without it."""
    if not CORPUS.is_dir():
        pytest.skip(CORPUS_MISSING)
    return CORPUS


@pytest.fixture
def ros1(tmp_path: Path) -> Iterator[Any]:
    """A private real roscore for this test, reaped with all it started (skips where Debian's ROS 1 is absent).

    Imported here, not at the top: ``ros1helpers`` probes for ROS 1 once, which only the
    tests that use this fixture (tests/ros1, tests/standins) should pay for.
    """
    from ros1helpers import MISSING, Ros1World

    if MISSING:
        pytest.skip(MISSING)
    world = Ros1World(tmp_path / "ros_home")
    try:
        yield world
    finally:
        world.reap()
