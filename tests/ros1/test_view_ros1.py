"""``view --tf``, ``view --publish`` and ``view_frames`` on ROS 1 against real broadcasters and listeners.

Three real broadcasters on one roscore: Debian's C++ static_transform_publisher (map -> odom,
latched /tf_static) and two rospy tf2_ros broadcasters (odom -> base_link, base_link -> laser).
``robotmodel view_frames`` names each frame's broadcaster by its caller id, as tf2_tools'
view_frames does; the live viewer with ``--tf`` (as ``robotmodel view --tf`` serves it) holds
each frame at its pose from the fixed frame, read headless from its scene; ``robotmodel view
--publish`` sends its sliders' values to a rospy subscriber.
"""

from __future__ import annotations

import json
import sys
import threading
from pathlib import Path

import numpy as np
import umsgpack
import yaml
from ros1helpers import SYSTEM_PYTHON, Ros1World, wait_until

from robotmodel.bus import Node
from robotmodel.model import load
from robotmodel.viewer import LiveViewer, Viewer

HERE = Path(__file__).resolve().parent
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
STATIC_TRANSFORM_PUBLISHER = "/usr/lib/tf2_ros/static_transform_publisher"
# frame -> (its position seen from map, the caller id of its broadcaster (None: the anonymous static one))
EXPECTED = {"odom": ((1.0, 2.0, 3.0), None), "base_link": ((1.5, 2.0, 3.0), "/bc_base"),
            "laser": ((1.5, 2.0, 3.2), "/bc_laser")}


def _tf_positions(viewer: Viewer) -> dict[str, np.ndarray]:
    """frame -> position of the /tf triads in the viewer's scene (what a page would be sent)."""
    found = {}
    for packed in viewer.commands():
        cmd = umsgpack.unpackb(packed)
        if cmd["type"] == "set_transform" and "/tf/" in cmd["path"]:
            matrix = np.frombuffer(cmd["matrix"].data, dtype=np.float32).reshape(4, 4).T
            found[cmd["path"].rsplit("/", 1)[1]] = matrix[:3, 3]
    return found


def test_view_tf_publish_and_view_frames_against_real_broadcasters(ros1: Ros1World, tmp_path: Path) -> None:
    ros1.start(STATIC_TRANSFORM_PUBLISHER, "1", "2", "3", "0", "0", "0", "map", "odom")
    for name, parent, child, xyz in (("bc_base", "odom", "base_link", "0.5 0 0"),
                                     ("bc_laser", "base_link", "laser", "0 0 0.2")):
        ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_tf_broadcaster.py"), name, parent, child, *xyz.split())
    echo = ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_joint_echo.py"), "/joint_states")
    echo.wait_line("^ready", 60)
    ros1.env["ROS_VERSION"] = "1"
    rm = [sys.executable, "-m", "robotmodel.cli.main"]
    view = ros1.start(*rm, "view", str(ARM), "--publish", "--joint", "arm_elbow_joint=1.1", "--port", "0")
    frames = ros1.start(*rm, "view_frames", "--wait-time", "3", "-o", str(tmp_path / "frames"))

    with Node("rm_view", backend="ros1", connect=[ros1.uri]) as node, \
            LiveViewer(load(ARM), tf=True, fixed_frame="map", node=node,
                       make_viewer=lambda d: Viewer(d, serve=False)) as live:
        assert live.start(threading.Event())
        assert live.viewer is not None
        viewer = live.viewer

        def placed() -> bool:
            got = _tf_positions(viewer)
            return all(f in got and np.allclose(got[f], xyz, atol=1e-6) for f, (xyz, _) in EXPECTED.items())

        wait_until(placed, 60, f"every frame where map sees it: {EXPECTED}")

    assert frames.popen.wait(60) == 0, frames.lines
    stp = next(n for n in ros1.tool("rosnode", "list").split() if n.startswith("/static_transform_publisher"))
    tree = yaml.safe_load((tmp_path / "frames.yaml").read_text())
    assert {f: tree[f]["broadcaster"] for f in EXPECTED} == {f: b or stp for f, (_, b) in EXPECTED.items()}, tree
    assert (tmp_path / "frames.gv").is_file()

    # view --publish: the sliders' values (the --joint one among them) reach a rospy subscriber
    view.wait_line(r"^http://127\.0\.0\.1:\d+/", 60)
    got = echo.wait_line(r"^/joint_states \d+ (.*)$", 60).group(1)
    names, positions, _, _ = json.loads(got)
    assert dict(zip(names, positions, strict=True))["arm_elbow_joint"] == 1.1, got
