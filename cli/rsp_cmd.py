"""``robotmodel robot-state-publisher``: ROS 2's robot_state_publisher as a process on the bus."""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments
from robotmodel.cli._ros_args import add_node_arguments

_NODE = "robot_state_publisher"


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
    add_node_arguments(parser, _NODE)
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Load the robot, publish, and serve joint states until stopped."""
    from robotmodel.cli._bus_args import stop_on_signals
    from robotmodel.cli._common import load_description
    from robotmodel.cli._publisher_log import ros_console
    from robotmodel.cli._ros_args import logger_name

    from robotmodel.bus import Node
    from robotmodel.publishers import RobotStatePublisher, check_publish_frequency

    check_publish_frequency(args.publish_frequency)
    desc, _ = load_description(args)
    name = args.node_name or _NODE
    log = ros_console(logger_name(args.namespace, name))
    stop = stop_on_signals()
    # RSP's topics are relative (joint_states, robot_description): they follow the namespace; /tf does not.
    with Node(name, args.namespace, connect=args.connect) as node, RobotStatePublisher(
            desc, bus=node, publish_frequency=args.publish_frequency, frame_prefix=args.frame_prefix,
            ignore_timestamp=args.ignore_timestamp, logger=log):
        stop.wait()
    return 0
