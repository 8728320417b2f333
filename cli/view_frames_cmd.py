"""``robotmodel view-frames`` (alias ``view_frames``): listen to TF, then draw the frame tree.

The program is :func:`robotmodel.tf_ros.run_view_frames` (tf2_tools' view_frames; ``--bag``
reads a recording instead).
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bag_args import add_bag_arguments
from robotmodel.cli._node_args import add_node_arguments

__all__ = ["register", "run"]

_NODE = "view_frames"


def register(sub: Any) -> None:
    """Add the ``view-frames`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "view-frames", aliases=["view_frames"],
        help="listen to /tf and /tf_static, then write the frame tree as .gv/.pdf (tf2_tools)",
        description="Create a diagram of the TF frames being broadcast on the bus.",
    )
    parser.add_argument("--wait-time", "-t", "--duration", type=float, default=5.0, metavar="SECONDS",
                        help="listen for this many seconds before drawing the tree (default 5.0)")
    parser.add_argument("-o", "--output", metavar="NAME", help="output base name (default frames_<date>)")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (repeatable)")
    add_bag_arguments(parser)
    add_node_arguments(parser, _NODE)
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run view_frames with the options."""
    from robotmodel.tf_ros import run_view_frames

    return run_view_frames(wait_time=args.wait_time, output=args.output, connect=args.connect,
                           namespace=args.namespace, ros=args.ros, bag=args.bag, urdf=args.urdf,
                           progress=False if args.no_progress else None)
