"""``robotmodel robot-state-publisher``: ROS 2's robot_state_publisher as a process on the bus."""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments


def register(sub: Any) -> None:
    """Add the ``robot-state-publisher`` subcommand (alias ``robot_state_publisher``)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "robot-state-publisher", aliases=["robot_state_publisher"],
        help="publish /robot_description, /tf_static, and /tf from /joint_states (robot_state_publisher)",
        description="ROS 2's robot_state_publisher: publishes the robot's URDF on /robot_description and "
        "its fixed joints on /tf_static (both latched), and for each JointState on /joint_states the "
        "moving joints on /tf, stamped with the joint state's stamp. Runs until Ctrl-C or SIGTERM.",
    )
    add_model_arguments(parser)
    parser.add_argument("--publish-frequency", type=float, default=20.0, metavar="HZ",
                        help="maximum /tf rate, compared on stamps (0 to 1000; default 20; 0: no cap)")
    parser.add_argument("--frame-prefix", default="", metavar="PREFIX",
                        help="prepended verbatim to every frame id, static ones included")
    parser.add_argument("--ignore-timestamp", action="store_true",
                        help="publish every joint state, whatever its stamp")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Load the robot, publish, and serve joint states until stopped."""
    from robotmodel.cli._bus_args import stop_on_signals
    from robotmodel.cli._common import load_description
    from robotmodel.cli._publisher_log import ros_console

    from robotmodel.publishers import RobotStatePublisher, check_publish_frequency

    check_publish_frequency(args.publish_frequency)
    desc, _ = load_description(args)
    log = ros_console("robot_state_publisher")
    stop = stop_on_signals()
    with RobotStatePublisher(desc, publish_frequency=args.publish_frequency, frame_prefix=args.frame_prefix,
                             ignore_timestamp=args.ignore_timestamp, logger=log, connect=args.connect):
        stop.wait()
    return 0
