"""``robotmodel robot-state-publisher``: ROS 2's robot_state_publisher as a process on the bus."""

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
_PARAMS = frozenset({"robot_description", "publish_frequency", "ignore_timestamp", "frame_prefix"})
_WHY = {"use_sim_time": "there is no /clock here", "qos_overrides": "QoS overrides are not read here"}


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
    parser.add_argument("--publish-frequency", type=float, default=20.0, metavar="HZ",
                        help="maximum /tf rate, compared on stamps (0 to 1000; default 20; 0: no cap)")
    parser.add_argument("--frame-prefix", default="", metavar="PREFIX",
                        help="prepended verbatim to every frame id, static ones included")
    parser.add_argument("--ignore-timestamp", action="store_true",
                        help="publish every joint state, whatever its stamp")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    add_node_arguments(parser, _NODE)
    parser.epilog = f"{parser.epilog} {_PARAMS_HELP}"
    parser.set_defaults(func=run)


def _settings(args: argparse.Namespace, name: str, log: Any) -> str | None:
    """Apply the node's parameter overrides to ``args``; returns the robot_description text, if given."""
    from robotmodel.rcl import node_params, typed_param, warn_unused_params

    values = node_params(args.ros, args.namespace, name)
    for param, kind in (("publish_frequency", "double"), ("ignore_timestamp", "bool"), ("frame_prefix", "string")):
        value = typed_param(values, param, kind)
        if value is not None:
            setattr(args, param, value)
    text = typed_param(values, "robot_description", "string")
    warn_unused_params(values, lambda n: n in _PARAMS, log.warning, _WHY)
    return None if text is None else str(text)


def run(args: argparse.Namespace) -> int:
    """Load the robot, publish, and serve joint states until stopped."""
    import sys

    from robotmodel.cli._common import load_description

    from robotmodel.bus import Node
    from robotmodel.publishers import RobotStatePublisher, check_publish_frequency
    from robotmodel.rcl import RosArgsError, logger_name, ros_console
    from robotmodel.signals import stop_on_signals

    name = args.node_name or _NODE
    log = ros_console(logger_name(args.namespace, name))
    try:
        text = _settings(args, name, log)
    except RosArgsError as exc:
        print(f"robotmodel robot-state-publisher: error: {exc}", file=sys.stderr)
        return 2
    check_publish_frequency(args.publish_frequency)
    # As RSP before 3.5.1: the parameter is the robot; FILE is the fallback when it is empty.
    desc: Any = text if text else (load_description(args)[0] if args.file is not None else None)
    if desc is None:
        log.critical("robot_description parameter must not be empty")
        return 1
    stop = stop_on_signals()
    # RSP's topics are relative (joint_states, robot_description): they follow the namespace; /tf does not.
    with Node(name, args.namespace, connect=args.connect, remappings=args.ros.remaps) as node, RobotStatePublisher(
            desc, bus=node, publish_frequency=args.publish_frequency, frame_prefix=args.frame_prefix,
            ignore_timestamp=args.ignore_timestamp, logger=log):
        stop.wait()
    return 0
