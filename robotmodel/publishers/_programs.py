"""``robotmodel joint-state-publisher``: ROS 2's joint_state_publisher as a process on the bus."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Mapping, Sequence
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
_NODE = "joint_state_publisher"
_BOOLS = ("publish_default_positions", "publish_default_velocities", "publish_default_efforts", "use_mimic_tags",
          "use_smallest_joint_limits")
_WHY = {
    "dependent_joints": "joint_state_publisher replaces it with the URDF's mimic tags once a robot is loaded",
    "robot_description": "joint_state_publisher reads the robot from FILE or the robot_description topic",
    "use_sim_time": "there is no /clock here",
    "qos_overrides": "QoS overrides are not read here",
}


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
    add_node_arguments(parser, _NODE)
    parser.epilog = f"{parser.epilog} {_PARAMS_HELP}"
    parser.set_defaults(func=run)


def jsp_settings(values: Mapping[str, Any], warn: Callable[[str], None], *, rate: float = 10.0,
                 zeros: Mapping[str, float] | None = None, source_list: Sequence[str] = ()) -> dict[str, Any]:
    """JointStatePublisher's keyword settings: the given ones, then the parameter overrides ``values`` over them.

    Raises RosArgsError (rclcpp's text) for a wrong type; ``warn`` hears of the overrides not used.
    """
    from robotmodel.rcl import RosArgsError, typed_param, warn_unused_params

    # joint_state_publisher declares its parameters from the overrides (rclpy), so a number is a number.
    given = typed_param(values, "rate", "integer", "double")
    if given is not None:
        if not (isinstance(given, (int, float)) and given > 0):
            raise RosArgsError(f"rate must be a positive number of Hz, got '{given}'")
        rate = float(given)
    settings: dict[str, Any] = {"rate": rate, "zeros": dict(zeros or {}), "source_list": list(source_list)}
    for flag in _BOOLS:
        value = typed_param(values, flag, "bool")
        if value is not None:
            settings[flag] = value
    delta = typed_param(values, "delta", "double", "integer")
    if isinstance(delta, (int, float)):
        settings["delta"] = float(delta)
    sources = typed_param(values, "source_list", "string_array")
    if isinstance(sources, tuple):
        settings["source_list"] = [str(topic) for topic in sources]
    for param in values:
        zero = typed_param(values, param, "double", "integer") if param.startswith("zeros.") else None
        if isinstance(zero, (int, float)):
            settings["zeros"][param.removeprefix("zeros.")] = float(zero)
    warn_unused_params(values, lambda n: n in _BOOLS or n in ("rate", "delta", "source_list") or n.startswith("zeros."),
                warn, _WHY)
    return settings


def run(args: argparse.Namespace) -> int:
    """Load the robot (or wait for it on the bus) and publish until stopped."""
    import sys

    from robotmodel.cli._common import load_description

    from robotmodel.bus import Node
    from robotmodel.publishers import JointStatePublisher
    from robotmodel.rcl import RosArgsError, logger_name, node_params, ros_console
    from robotmodel.signals import stop_on_signals

    name = args.node_name or _NODE
    log = ros_console(logger_name(args.namespace, name))
    try:
        settings = jsp_settings(node_params(args.ros, args.namespace, name), log.warning, rate=args.rate,
                                zeros=dict(args.zeros), source_list=args.source_list)
    except RosArgsError as exc:
        print(f"robotmodel joint-state-publisher: error: {exc}", file=sys.stderr)
        return 2
    desc = load_description(args)[0] if args.file is not None else None
    stop = stop_on_signals()
    # joint_states, robot_description and relative --source-list topics resolve under the namespace.
    with Node(name, args.namespace, connect=args.connect, remappings=args.ros.remaps) as node, JointStatePublisher(
            desc, bus=node, logger=log, **settings):
        stop.wait()
    return 0
