"""``param delete|describe|load``'s parsers and handlers (``list|get|set|dump`` are in param_cmd)."""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bus_args import add_bus_options

__all__ = ["register_verbs"]


def _node_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--include-hidden-nodes", action="store_true", help="consider hidden nodes as well")
    parser.add_argument("--timeout", metavar="N", type=int, default=1,
                        help="wait for N seconds until node becomes available (default 1 sec)")
    add_bus_options(parser)


def register_verbs(verbs: Any) -> None:
    """Add the verbs to ``param``'s subparsers."""
    delete = verbs.add_parser("delete", help="delete parameter", description="Delete parameter.")
    delete.add_argument("node_name", help="name of the ROS node (ROS 1 form: the parameter's full name)")
    delete.add_argument("parameter_name", nargs="?", default=None, help="name of the parameter")
    _node_options(delete)
    delete.set_defaults(func=run_delete)
    describe = verbs.add_parser("describe", help="show descriptive information about declared parameters",
                                description="Show descriptive information about declared parameters.")
    describe.add_argument("node_name", help="name of the ROS node")
    describe.add_argument("parameter_names", nargs="+", help="names of the parameters")
    _node_options(describe)
    describe.set_defaults(func=run_describe)
    load = verbs.add_parser("load", help="load parameter file for a node",
                            description="Load parameter file for a node (ROS 1 form: load FILE [NAMESPACE] into "
                                        "the parameter server).")
    load.add_argument("node_name", help="name of the ROS node (ROS 1 form: the file)")
    load.add_argument("parameter_file", nargs="?", default=None,
                      help="parameter file (ROS 1 form: the namespace to load into)")
    load.add_argument("--no-use-wildcard", action="store_true",
                      help="do not load parameters in the '/**' namespace into the node")
    _node_options(load)
    load.set_defaults(func=run_load)


def run_delete(args: argparse.Namespace) -> int:
    """Delete one parameter."""
    from robotmodel.graphtools import run_param_delete

    return run_param_delete(args.node_name, args.parameter_name, timeout=args.timeout,
                            include_hidden_nodes=args.include_hidden_nodes, connect=args.connect,
                            spin_time=args.spin_time)


def run_describe(args: argparse.Namespace) -> int:
    """Print the parameters' descriptors."""
    from robotmodel.graphtools import run_param_describe

    return run_param_describe(args.node_name, args.parameter_names, timeout=args.timeout,
                              include_hidden_nodes=args.include_hidden_nodes, connect=args.connect,
                              spin_time=args.spin_time)


def run_load(args: argparse.Namespace) -> int:
    """Set the file's parameters."""
    from robotmodel.graphtools import run_param_load

    return run_param_load(args.node_name, args.parameter_file, use_wildcard=not args.no_use_wildcard,
                          timeout=args.timeout, include_hidden_nodes=args.include_hidden_nodes, connect=args.connect,
                          spin_time=args.spin_time)
