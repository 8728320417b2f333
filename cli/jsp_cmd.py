"""``robotmodel joint-state-publisher``: ROS 2's joint_state_publisher as a process on the bus.

The program is :func:`robotmodel.publishers.run_joint_state_publisher`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_mapping_arguments
from robotmodel.cli._node_args import add_node_arguments

_PARAMS_HELP = (
    "Parameters (--ros-args -p NAME:=VALUE or --params-file FILE): rate, "
    "publish_default_positions, publish_default_velocities, publish_default_efforts, "
    "use_mimic_tags, use_smallest_joint_limits (bool), source_list (a list: "
    "source_list:=\"['/a/joint_states']\"), delta, zeros.JOINT (numbers; in a params file "
    "'zeros: {j1: 0.5}'). A parameter wins over the same setting's --flag (zeros per joint); "
    "dependent_joints and robot_description are reported and ignored, as joint_state_publisher "
    "takes mimic joints from the URDF and the robot from FILE or the topic."
)
def _zero(word: str) -> tuple[str, float]:
    name, sep, text = word.partition("=")
    try:
        if not sep or not name:
            raise ValueError
        return name, float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE with a number, got '{word}'") from None


def _rate(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = 0.0
    if not value > 0:
        raise argparse.ArgumentTypeError(f"rate must be a positive number of Hz, got '{text}'")
    return value


def register(sub: Any) -> None:
    """Add the ``joint-state-publisher`` subcommand (alias ``joint_state_publisher``)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "joint-state-publisher", aliases=["joint_state_publisher"],
        help="publish /joint_states for a robot's movable joints (joint_state_publisher)",
        description="ROS 2's joint_state_publisher: publishes a JointState for every movable joint on "
        "/joint_states at --rate, each at 0 (or the middle of its limits when 0 is outside them) unless "
        "--zeros or a --source-list topic says otherwise; mimic joints follow their masters. Without FILE "
        "the robot comes from /robot_description, and every new description there is followed. "
        "Put FILE before --zeros/--source-list. Runs until Ctrl-C or SIGTERM.",
    )
    add_mapping_arguments(parser)
    parser.add_argument("file", metavar="FILE", nargs="?", help="a .urdf or .xacro file (default: the "
                        "robot_description topic)")
    parser.add_argument("--rate", type=_rate, default=10.0, metavar="HZ", help="publishing rate (default 10)")
    parser.add_argument("--zeros", type=_zero, nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                        help="initial joint positions, used as given")
    parser.add_argument("--source-list", nargs="+", action="extend", default=[], metavar="TOPIC",
                        help="JointState topics whose values are merged in (latest value per joint wins)")
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="search DIR first for ROS packages ($(find pkg), package://); repeatable")
    parser.add_argument("--untrusted", action="store_true",
                        help="refuse $(env), $(optenv) and reads outside the input's package roots")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    add_node_arguments(parser, "joint_state_publisher")
    parser.epilog = f"{parser.epilog} {_PARAMS_HELP}"
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Publish until stopped."""
    from robotmodel.publishers import run_joint_state_publisher

    return run_joint_state_publisher(args.file, args.mappings, package_paths=args.package_path,
                                     untrusted=args.untrusted, rate=args.rate, zeros=dict(args.zeros),
                                     source_list=args.source_list, connect=args.connect, namespace=args.namespace,
                                     ros=args.ros)
