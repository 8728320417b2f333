"""``robotmodel robot-state-publisher``: ROS 2's robot_state_publisher as a process on the bus.

The program is :func:`robotmodel.publishers.run_robot_state_publisher`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments
from robotmodel.cli._node_args import add_node_arguments

_PARAMS_HELP = (
    "Parameters (--ros-args -p NAME:=VALUE or --params-file FILE), with ROS's types: "
    "robot_description (string: the URDF itself; it replaces FILE), publish_frequency (double: "
    "50.0, not 50), ignore_timestamp (bool), frame_prefix (string). A parameter wins over the "
    "same setting's --flag; others are reported and ignored."
)
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
    add_model_arguments(parser, file_optional=True,
                        file_help="a .urdf or .xacro file ('-' reads stdin); not needed with "
                        "--ros-args -p robot_description:=\"$(xacro robot.xacro)\"")
    parser.add_argument("--publish-frequency", type=float, default=None, metavar="HZ",
                        help="maximum /tf rate, compared on stamps (0 to 1000; default 20, on ROS 1 50; 0: no cap)")
    parser.add_argument("--frame-prefix", default="", metavar="PREFIX",
                        help="prepended verbatim to every frame id, static ones included")
    parser.add_argument("--ignore-timestamp", action="store_true",
                        help="publish every joint state, whatever its stamp")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    add_node_arguments(parser, _NODE)
    parser.epilog = f"{parser.epilog} {_PARAMS_HELP}"
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Publish until stopped."""
    from robotmodel.publishers import run_robot_state_publisher

    return run_robot_state_publisher(args.file, args.mappings, package_paths=args.package_path,
                                     untrusted=args.untrusted, publish_frequency=args.publish_frequency,
                                     frame_prefix=args.frame_prefix, ignore_timestamp=args.ignore_timestamp,
                                     connect=args.connect, namespace=args.namespace, ros=args.ros)
