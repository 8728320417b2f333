"""``robotmodel node list|info``: the graph's nodes, as ``ros2 node`` shows them (``rosnode`` an alias).

The programs are :func:`robotmodel.graphtools.run_node_list` and :func:`robotmodel.graphtools.run_node_info`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bus_args import add_bus_options

__all__ = ["register"]


def register(sub: Any) -> None:
    """Add the ``node`` subcommand with its ``list`` and ``info`` verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "node", aliases=["rosnode"], help="list the nodes on the bus, or what one offers (as ros2 node)",
        description="Inspect the nodes of the ROS graph.")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True
    lst = verbs.add_parser("list", help="output a list of available nodes", description="Output a list of nodes.")
    lst.add_argument("-a", "--all", action="store_true", help="display all nodes even hidden ones")
    lst.add_argument("-c", "--count-nodes", action="store_true", help="only display the number of nodes discovered")
    add_bus_options(lst)
    lst.set_defaults(func=run_list)
    info = verbs.add_parser("info", help="output information about a node",
                            description="Output information about a node.")
    info.add_argument("node_name", help="fully qualified node name to request information for (e.g. /talker)")
    add_bus_options(info)
    info.set_defaults(func=run_info)


def run_list(args: argparse.Namespace) -> int:
    """Print the nodes."""
    from robotmodel.graphtools import run_node_list

    return run_node_list(count_nodes=args.count_nodes, all_nodes=args.all, connect=args.connect,
                         spin_time=args.spin_time)


def run_info(args: argparse.Namespace) -> int:
    """Print one node's endpoints."""
    from robotmodel.graphtools import run_node_info

    return run_node_info(args.node_name, connect=args.connect, spin_time=args.spin_time)
