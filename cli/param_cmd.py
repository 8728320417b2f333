"""``robotmodel param list|get|set|dump|delete|describe|load``: node parameters, as ``ros2 param`` (``rosparam`` too).

ROS 2's forms take a node and a name (``param get /robot_state_publisher publish_frequency``);
ROS 1's take one parameter server key (``rosparam get /robot_state_publisher/publish_frequency``).
The programs are :mod:`robotmodel.graphtools`'s ``run_param_*``; delete, describe and load
are in :mod:`._param_verbs`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bus_args import add_bus_options
from robotmodel.cli._param_verbs import register_verbs

__all__ = ["register"]


def register(sub: Any) -> None:
    """Add the ``param`` subcommand with its verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "param", aliases=["rosparam"],
        help="list, get, set, dump, delete, describe or load node parameters (as ros2 param / rosparam)",
        description="Node parameters: through ROS 2's parameter services, or ROS 1's parameter server.")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True
    lst = verbs.add_parser("list", help="output a list of available parameters",
                           description="Output a list of available parameters.")
    lst.add_argument("node_name", nargs="?", default=None, help="name of the ROS node (default: every node)")
    add_bus_options(lst)
    lst.set_defaults(func=run_list)
    get = verbs.add_parser("get", help="get parameter", description="Get parameter.")
    get.add_argument("node_name", help="name of the ROS node (ROS 1 form: the parameter's full name)")
    get.add_argument("parameter_name", nargs="?", default=None, help="name of the parameter")
    get.add_argument("--hide-type", action="store_true", help="hide the type information")
    add_bus_options(get)
    get.set_defaults(func=run_get)
    put = verbs.add_parser("set", help="set parameter", description="Set parameter.")
    put.add_argument("node_name", help="name of the ROS node (ROS 1 form: the parameter's full name)")
    put.add_argument("parameter_name", help="name of the parameter (ROS 1 form: the value)")
    put.add_argument("value", nargs="?", default=None, help="value of the parameter, in YAML")
    add_bus_options(put)
    put.set_defaults(func=run_set)
    dump = verbs.add_parser("dump", help="show all of the parameters of a node in a YAML file format",
                            description="Show all of the parameters of a node in a YAML file format.")
    dump.add_argument("node_name", help="name of the ROS node")
    add_bus_options(dump)
    dump.set_defaults(func=run_dump)
    register_verbs(verbs)


def run_list(args: argparse.Namespace) -> int:
    """Print the parameter names."""
    from robotmodel.graphtools import run_param_list

    return run_param_list(args.node_name, connect=args.connect, spin_time=args.spin_time)


def run_get(args: argparse.Namespace) -> int:
    """Print one value."""
    from robotmodel.graphtools import run_param_get

    return run_param_get(args.node_name, args.parameter_name, hide_type=args.hide_type, connect=args.connect,
                         spin_time=args.spin_time)


def run_set(args: argparse.Namespace) -> int:
    """Set one value."""
    from robotmodel.graphtools import run_param_set

    return run_param_set(args.node_name, args.parameter_name, args.value, connect=args.connect,
                         spin_time=args.spin_time)


def run_dump(args: argparse.Namespace) -> int:
    """Print the node's parameters as YAML."""
    from robotmodel.graphtools import run_param_dump

    return run_param_dump(args.node_name, connect=args.connect, spin_time=args.spin_time)
