"""static_transforms.sh: the seed's three static_transform_publisher commands, checked from a listener."""

from __future__ import annotations

import sys

from conftest import REPO
from procscan import assert_none_left

from robotmodel.bus import Node
from robotmodel.tf import Buffer, Duration, Time
from robotmodel.tf_ros import TransformListener


def test_three_static_transforms_in_ros1_forms(live):
    live.env["ROBOTMODEL"] = f"{sys.executable} -m robotmodel.cli.main"
    script = live.start("bash", str(REPO / "examples" / "static_transforms.sh"), "--duration", "60")
    buffer = Buffer()
    expected = {("base_link", "laser_link"): (0.15, 0.0, 0.3), ("base_link", "camera_link"): (0.1, 0.0, 0.2),
                ("map", "odom"): (0.0, 0.0, 0.0)}
    with Node("static_check") as node, TransformListener(buffer, node):
        for (parent, child), xyz in expected.items():
            t = buffer.lookup_transform(parent, child, Time(), timeout=Duration(seconds=30))
            tr, q = t.transform.translation, t.transform.rotation
            assert (tr.x, tr.y, tr.z) == xyz
            assert (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 1.0)
        # Both sensors hang off base_link: the camera is 5 cm behind and 10 cm below the laser. (ROS 1's
        # period form republishes on /tf, so the two chains arrive at their own stamps: wait for both.)
        t = buffer.lookup_transform("laser_link", "camera_link", Time(), timeout=Duration(seconds=5)).transform.translation
        assert abs(t.x + 0.05) < 1e-12 and t.y == 0.0 and abs(t.z + 0.1) < 1e-12
        assert not buffer.can_transform("map", "base_link", Time())
    assert script.stop() == 0
    # The script's trap stopped its three publishers too.
    assert_none_left(live.env["ROBOTMODEL_ZENOH_PORT"])
