"""A headless stand-in for turtle_teleop_key: a fixed Twist on ``/turtle1/cmd_vel`` at 10 Hz.

Run: python examples/turtle_teleop.py [--linear 0.3] [--angular 0.2] [--duration S]
"""

from __future__ import annotations

import argparse

from robotmodel.bus import Node
from robotmodel.msgs import Twist
from robotmodel.signals import stop_on_signals
from robotmodel.time import Duration, Rate, SystemClock


def main() -> None:
    """Drive turtle1 on a circle until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--linear", type=float, default=0.3, help="linear.x in m/s (default 0.3)")
    parser.add_argument("--angular", type=float, default=0.2, help="angular.z in rad/s (default 0.2)")
    parser.add_argument("--turtle", default="turtle1", help="which turtle to drive")
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)
    with Node("teleop_turtle") as node:
        pub = node.create_publisher(Twist, f"/{args.turtle}/cmd_vel", 1)
        msg = Twist()
        msg.linear.x, msg.angular.z = args.linear, args.angular
        rate = Rate(10.0, clock)
        while not shutdown.is_set() and (end is None or clock.now() < end):
            pub.publish(msg)
            rate.sleep()


if __name__ == "__main__":
    main()
