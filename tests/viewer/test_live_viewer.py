"""The live viewer as a Python program starts it: robot from /robot_description, joints from /joint_states."""

from __future__ import annotations

import threading
import time
import urllib.request
from pathlib import Path

import pytest
from conftest import BUNDLED
from livebus import Bus

from robotmodel.model import load
from robotmodel.viewer import LiveViewer

DIFFBOT = BUNDLED / "diffbot.urdf.xacro"


def test_a_python_program_starts_the_live_viewer(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    bus = Bus(tmp_path, "zenoh")
    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID"):
        monkeypatch.setenv(key, bus.env[key])
    monkeypatch.delenv("ZENOH_SESSION_CONFIG_URI", raising=False)
    stop = threading.Event()
    timer = threading.Timer(120, stop.set)  # the deadline for the robot to arrive
    timer.start()
    try:
        # Under /r1, as the viewer's relative topics resolve (robot_description, joint_states).
        bus.robotmodel("robot-state-publisher", str(DIFFBOT), "--namespace", "r1")
        bus.robotmodel("joint-state-publisher", str(DIFFBOT), "--namespace", "r1", "--zeros", "left_wheel_joint=0.7")
        with LiveViewer(namespace="/r1", follow=True, port=0) as live:
            assert live.start(stop), "no robot_description within the deadline"
            assert live.viewer is not None and live.url is not None
            assert live.viewer.description.name == load(DIFFBOT).name
            with urllib.request.urlopen(live.url, timeout=30) as page:
                assert page.status == 200 and b"<html" in page.read().lower()
            deadline = time.monotonic() + 60
            while abs(live.viewer.positions.get("left_wheel_joint", 0.0) - 0.7) > 1e-9:
                assert time.monotonic() < deadline, live.viewer.positions
                time.sleep(0.05)
    finally:
        timer.cancel()
        bus.reap()
