"""A small turtlesim stand-in: turtles integrating ``/turtleN/cmd_vel`` into ``/turtleN/pose``.

As ROS's turtlesim_node, without the window: turtle1 starts at the middle of the 11.09 m
square (5.544445, 5.544445, 0); each turtle turns by ``angular.z`` and moves by
``linear.x`` along its heading every 16 ms, stops when no command came for 1 s, stays
inside the square, and publishes ``turtlesim/msg/Pose`` (registered here, with turtlesim's
definition, so the keys and type hash are ROS 2's). The bus has no services: turtles that
the tutorials spawn through turtlesim's ``spawn`` service are given with ``--spawn``.

Run: python examples/turtlesim.py --spawn turtle2 4 2 0 [--duration S]
"""

from __future__ import annotations

import argparse
import math
import threading
from typing import Any

from robotmodel.bus import Node, typestore
from robotmodel.msgs import Twist
from robotmodel.signals import stop_on_signals
from robotmodel.time import Duration, Rate, SystemClock, Time

POSE_TYPE = "turtlesim/msg/Pose"
_POSE_MSG = """float32 x
float32 y
float32 theta

float32 linear_velocity
float32 angular_velocity
"""
SIZE = 11.088889  # the side of turtlesim's square, in metres
START = 5.544445
_PERIOD_S = 0.016
_COMMAND_TIMEOUT_S = 1.0


def pose_class() -> Any:
    """turtlesim/msg/Pose as a rosbags class (registered in the bus's typestore on first use)."""
    store = typestore()
    if POSE_TYPE not in store.fielddefs:
        from rosbags.typesys import get_types_from_msg

        store.register(get_types_from_msg(_POSE_MSG, POSE_TYPE))
    return store.types[POSE_TYPE]


class Turtle:
    """One turtle: its pose, its latest command, and its topics."""

    def __init__(self, node: Node, name: str, x: float, y: float, theta: float) -> None:
        self.name, self.x, self.y, self.theta = name, x, y, theta
        self.linear = self.angular = 0.0
        self.last_command: Time | None = None
        self.lock = threading.Lock()
        self.pose_pub: Any = node.create_publisher(POSE_TYPE, f"/{name}/pose", 1)
        self.sub = node.create_subscription(Twist, f"/{name}/cmd_vel", self.on_cmd_vel, 1)

    def on_cmd_vel(self, msg: Twist) -> None:
        """Keep the latest command and when it came."""
        with self.lock:
            self.linear, self.angular = msg.linear.x, msg.angular.z
            self.last_command = SystemClock().now()

    def update(self, now: Time, dt: float, pose_type: Any) -> None:
        """Turn, then move, then publish the pose."""
        with self.lock:
            if self.last_command is None or now - self.last_command > Duration(seconds=_COMMAND_TIMEOUT_S):
                self.linear = self.angular = 0.0
            linear, angular = self.linear, self.angular
        self.theta = math.remainder(self.theta + angular * dt, 2 * math.pi)
        self.x = min(max(self.x + math.cos(self.theta) * linear * dt, 0.0), SIZE)
        self.y = min(max(self.y + math.sin(self.theta) * linear * dt, 0.0), SIZE)
        self.pose_pub.publish(pose_type(x=self.x, y=self.y, theta=self.theta, linear_velocity=linear,
                                        angular_velocity=angular))


def main() -> None:
    """Simulate turtle1 and the --spawn turtles until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spawn", nargs=4, action="append", default=[], metavar=("NAME", "X", "Y", "THETA"),
                        help="another turtle, as turtlesim's spawn service would add it (repeatable)")
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)
    pose_type = pose_class()
    with Node("turtlesim") as node:
        turtles = [Turtle(node, "turtle1", START, START, 0.0)]
        for name, x, y, theta in args.spawn:
            turtles.append(Turtle(node, name, float(x), float(y), float(theta)))
        for t in turtles:
            print(f"[turtlesim] Spawning turtle [{t.name}] at x=[{t.x:f}], y=[{t.y:f}], theta=[{t.theta:f}]",
                  flush=True)
        rate = Rate(1.0 / _PERIOD_S, clock)
        last = clock.now()
        while not shutdown.is_set() and (end is None or clock.now() < end):
            now = clock.now()
            dt, last = (now - last).nanoseconds / 1e9, now
            for t in turtles:
                t.update(now, dt, pose_type)
            rate.sleep()


if __name__ == "__main__":
    main()
