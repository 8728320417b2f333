"""``robotmodel urdf-to-graphviz`` (alias ``urdf_to_graphviz``): the robot's tree as a graph."""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments, load_description


def register(sub: Any) -> None:
    """Add the ``urdf-to-graphviz`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "urdf-to-graphviz", aliases=["urdf_to_graphviz"],
        help="write the link/joint tree as OUTPUT.gv and OUTPUT.pdf (urdfdom's layout)",
        description="Write $ROBOT_NAME.gv and .pdf in the current directory, or OUTPUT.gv and OUTPUT.pdf. "
        "The .gv is byte-identical to urdfdom's urdf_to_graphviz. Unlike urdfdom, the PDF is only "
        "reported as created when graphviz's dot actually made it.",
    )
    add_model_arguments(parser)
    # urdfdom's form: `urdf_to_graphviz FILE [OUTPUT]`.
    parser.add_argument("output", nargs="?", metavar="OUTPUT", help="output base name (default: the robot's name)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Write the .gv, then the .pdf when graphviz's ``dot`` is installed."""
    from robotmodel.check import run_urdf_to_graphviz

    return run_urdf_to_graphviz(load_description(args)[0], args.output)
