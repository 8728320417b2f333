"""``robotmodel demo``: the whole pipeline on the bundled diffbot, every part a process on a private bus.

The program is :func:`robotmodel.demo.run_demo` (what runs, and how it is stopped, is written there).
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``demo`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "demo", help="run the whole pipeline on the bundled diffbot: publishers, odometry, TF tools, viewer, "
                     "recording",
        description="Drive the bundled diffbot with the odometry example while robot_state_publisher, "
                    "joint_state_publisher, a static map->odom transform, tf2_echo, view_frames, the viewer and "
                    "a recorder run beside it as processes on a private bus (own port and ROS_DOMAIN_ID). "
                    "Writes the recording, the frame diagram and a screenshot into a fresh folder, then answers "
                    "one question from the recording.")
    parser.add_argument("--duration", type=float, default=35.0, metavar="S",
                        help="seconds to run (default 35: the odometry pattern takes 30)")
    parser.add_argument("--no-browser", action="store_true", help="do not open the viewer in the web browser")
    parser.add_argument("--output", metavar="DIR", help="folder for the files (default ./robotmodel-demo-<time>)")
    parser.add_argument("--time-scale", type=float, default=1.0, metavar="X",
                        help="run the odometry example X times faster than real time (default 1)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Start everything, run for --duration (or until Ctrl-C), stop everything, report."""
    from robotmodel.demo import run_demo

    return run_demo(duration=args.duration, output=args.output, browser=not args.no_browser,
                    time_scale=args.time_scale)
