"""A rospy tutorial program (odometry to TF) unchanged on the zenoh, DDS and in-process wires (one smoke each).

The wire is named explicitly (RMW_IMPLEMENTATION=rmw_zenoh_cpp for zenoh; the others by the
init_node that opens the node first), so this holds whichever wire is the default.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest
from livebus import Bus

HERE = Path(__file__).resolve().parent
BACKEND_CLASSES = {"zenoh": "ZenohBackend", "dds": "DdsBackend", "inprocess": "InProcessBackend"}


@pytest.mark.parametrize("wire", ["zenoh", "dds", "inprocess"])
def test_odom_to_tf_on_a_ros2_wire(tmp_path: Path, wire: str) -> None:
    bus = Bus(tmp_path)
    try:
        for var in ("ROS_VERSION", "ROS_MASTER_URI"):
            bus.env.pop(var, None)
        bus.env["RMW_IMPLEMENTATION"] = "rmw_zenoh_cpp" if wire == "zenoh" else "rmw_fastrtps_cpp"
        proc = bus.start(sys.executable, str(HERE / "wire_smoke.py"), wire)
        assert proc.wait_line(r"^wire (\w+)$", 60).group(1) == BACKEND_CLASSES[wire]
        got = proc.wait_line(r"^tf (\S+) (\S+) (\S+) (\S+)$", 60)
        assert [float(v) for v in got.groups()] == pytest.approx([1.5, -0.5, math.sin(0.3), math.cos(0.3)])
        proc.wait_line(r"^ended True$", 30)
        assert proc.popen.wait(30) == 0  # it ends by itself once rospy is shut down
    finally:
        bus.reap()
