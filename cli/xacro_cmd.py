"""``robotmodel xacro``: expand a xacro file like the ``xacro`` command, without ROS."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from robotmodel.cli._common import add_model_arguments, split_mappings, write_atomic

from robotmodel.xacro import expand


def register(sub: Any) -> None:
    """Add the ``xacro`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "xacro", help="expand a xacro file to URDF (same output as the xacro command)",
        description="Expand a xacro file to URDF. Output is the same text the xacro command prints.",
    )
    add_model_arguments(parser)
    parser.add_argument(
        "-o", dest="output", metavar="FILE", help="write to FILE (atomically) instead of stdout"
    )
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Expand and print or write the result."""
    text = expand(
        args.file, split_mappings(args.mappings),
        package_paths=args.package_path, untrusted=args.untrusted,
    )
    if args.output:
        write_atomic(args.output, text)
    else:
        sys.stdout.write(text)
    return 0
