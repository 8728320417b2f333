"""Turtle follow (ROS 2 tf2 tutorial): turtlesim stand-in, a broadcaster per turtle, the follower.

The test process watches both turtles' poses on the bus (turtlesim's Pose registered here
from its message definition) and asserts that turtle2, spawned at (4, 2, 0), closes in on
turtle1 while turtle1 drives a circle; the world → turtleN transforms the broadcasters
publish equal the poses once both turtles stand still.
"""

from __future__ import annotations

import math
import threading
import time
from typing import Any

from rosbags.typesys import get_types_from_msg

from robotmodel.bus import Node, typestore
from robotmodel.tf import Buffer, Duration, Time
from robotmodel.tf_ros import TransformListener

POSE = "turtlesim/msg/Pose"
# turtlesim's msg/Pose.msg
POSE_MSG = "float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n"


def test_turtle2_closes_in_on_turtle1(live):
    store = typestore()
    if POSE not in store.fielddefs:
        store.register(get_types_from_msg(POSE_MSG, POSE))
    latest: dict[str, Any] = {}
    first: dict[str, Any] = {}
    lock = threading.Lock()

    def on_pose(name: str) -> Any:
        def callback(msg: Any) -> None:
            with lock:
                first.setdefault(name, msg)
                latest[name] = msg
        return callback

    def gap() -> float:
        with lock:
            a, b = latest["turtle1"], latest["turtle2"]
        return math.hypot(a.x - b.x, a.y - b.y)

    buffer = Buffer()
    with Node("turtle_check") as node, TransformListener(buffer, node):
        for name in ("turtle1", "turtle2"):
            node.create_subscription(POSE, f"/{name}/pose", on_pose(name), 10)
        sim = live.example("turtlesim.py", "--spawn", "turtle2", "4", "2", "0")
        sim.wait_line(r"Spawning turtle \[turtle2\] at x=\[4\.0+\], y=\[2\.0+\], theta=\[0\.0+\]")
        for name in ("turtle1", "turtle2"):
            live.example("turtle_tf2_broadcaster.py", "--turtlename", name)
        buffer.lookup_transform("turtle2", "turtle1", Time(), timeout=Duration(seconds=30))
        start_gap = gap()
        with lock:
            assert (first["turtle2"].x, first["turtle2"].y, first["turtle2"].theta) == (4.0, 2.0, 0.0)
        assert abs(start_gap - math.hypot(5.544445 - 4, 5.544445 - 2)) < 1e-5
        teleop = live.example("turtle_teleop.py", "--linear", "0.3", "--angular", "0.2")
        follower = live.example("turtle_tf2_listener.py")
        gaps = []
        deadline = time.monotonic() + 40
        while time.monotonic() < deadline:
            time.sleep(0.5)
            gaps.append(gap())
            if gaps[-1] < 0.3 * start_gap:
                break
        assert gaps[-1] < 0.3 * start_gap, gaps
        # Stop the drivers; turtlesim halts each turtle 1 s after its last command, and its poses
        # then say so (zero velocities). The broadcasters' /tf follows the poses one hop behind.
        assert follower.stop() == 0 and teleop.stop() == 0

        def standing() -> bool:
            with lock:
                poses = {n: (m.x, m.y, m.linear_velocity, m.angular_velocity) for n, m in latest.items()}
            if any(v != 0.0 or w != 0.0 for _x, _y, v, w in poses.values()):
                return False
            for name, (x, y, _v, _w) in poses.items():
                t = buffer.lookup_transform("world", name, Time()).transform.translation
                if abs(t.x - x) > 1e-6 or abs(t.y - y) > 1e-6:
                    return False
            return True

        deadline = time.monotonic() + 30
        while not standing() and time.monotonic() < deadline:
            time.sleep(0.05)
        for name in ("turtle1", "turtle2"):
            with lock:
                pose = latest[name]
            t = buffer.lookup_transform("world", name, Time()).transform
            assert abs(t.translation.x - pose.x) < 1e-6 and abs(t.translation.y - pose.y) < 1e-6
            assert abs(math.remainder(2 * math.atan2(t.rotation.z, t.rotation.w) - pose.theta, 2 * math.pi)) < 1e-6
    assert not [line for line in follower.out if "Traceback" in line]
