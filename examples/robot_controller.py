"""The odometry tutorial's robot controller: velocity commands on /cmd_vel at 10 Hz.

10 s straight at 0.5 m/s, 10 s turning in place at 0.5 rad/s, then linear = angular =
0.5·sin(t − 20) until t = 30 s, then stop. The tutorial's rclpy node with its imports
changed; a Rate loop on the example's clock replaces rclpy's timer, so ``--time-scale``
runs the pattern faster than real time (start ``sensor_simulator.py`` with the same scale).

Run: python examples/robot_controller.py [--duration S] [--time-scale X]
"""

from __future__ import annotations

import argparse
import math

from robotmodel.bus import Node
from robotmodel.msgs import Twist
from robotmodel.signals import stop_on_signals
from robotmodel.time import Duration, PlaybackClock, Rate, SystemClock


class RobotController:
    """Publishes the drive pattern on /cmd_vel (the tutorial's RobotController node)."""

    def __init__(self, node: Node, clock: PlaybackClock) -> None:
        self.clock = clock
        self.publisher_ = node.create_publisher(Twist, "/cmd_vel", 10)
        # Start the pattern once the simulator listens, so its first seconds are not lost.
        self.publisher_.wait_for_subscriptions(1, timeout=10.0)
        self.start_time = self.clock.now()
        self.phase = ""

    def timer_callback(self) -> None:
        """One command, from the time since the start."""
        elapsed = (self.clock.now() - self.start_time).nanoseconds / 1e9
        msg = Twist()
        if elapsed < 10.0:
            phase = "driving straight at 0.5 m/s"
            msg.linear.x = 0.5
        elif elapsed < 20.0:
            phase = "turning at 0.5 rad/s"
            msg.angular.z = 0.5
        elif elapsed < 30.0:
            phase = "weaving: linear = angular = 0.5 sin(t - 20)"
            msg.linear.x = 0.5 * math.sin(elapsed - 20.0)
            msg.angular.z = 0.5 * math.sin(elapsed - 20.0)
        else:
            phase = "stopped"
        self.publisher_.publish(msg)
        if phase != self.phase:
            self.phase = phase
            print(f"[robot_controller] t={elapsed:5.2f} s: {phase}", flush=True)


def main() -> None:
    """Publish commands until --duration seconds of the example's clock, or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    parser.add_argument("--time-scale", type=float, default=1.0, help="clock seconds per wall second")
    args = parser.parse_args()
    stop = stop_on_signals()
    clock = PlaybackClock(SystemClock().now(), rate=args.time_scale)
    with Node("robot_controller") as node:
        controller = RobotController(node, clock)
        end = None if args.duration is None else controller.start_time + Duration(seconds=args.duration)
        rate = Rate(10.0, clock)
        while not stop.is_set() and (end is None or clock.now() < end):
            controller.timer_callback()
            rate.sleep()
        node.create_publisher(Twist, "/cmd_vel", 10).publish(Twist())  # leave the robot stopped


if __name__ == "__main__":
    main()
