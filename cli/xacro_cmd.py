"""``robotmodel xacro``: expand a xacro file like the ``xacro`` command, without ROS.

Takes every option of xacro 2.1.1's command line, with its meaning: ``-o FILE``,
``--deps``, ``-i/--inorder`` (a no-op), ``--root-dir DIR``, ``-q``, ``-v`` (repeatable)
and ``--verbosity N``; ``name:=value`` words may stand anywhere. The program is
:func:`robotmodel.xacro.run_xacro`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments, apply_verbose

VERBOSITY_HELP = (
    "set verbosity level: 0 quiet, suppressing warnings; 1 default, warnings and error locations; "
    "2 stack trace in xacro (here: the error stays one line); 3 log property definitions and uses "
    "at top level; 4 at all levels"
)


def register(sub: Any) -> None:
    """Add the ``xacro`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "xacro", help="expand a xacro file to URDF (same output as the xacro command)",
        description="Expand a xacro file to URDF. Output is the same text the xacro command prints.",
    )
    add_model_arguments(parser)
    parser.add_argument(
        "-o", dest="output", metavar="FILE", help="write output to FILE (atomically) instead of stdout"
    )
    parser.add_argument("--deps", action="store_true", dest="just_deps", help="print file dependencies")
    parser.add_argument("--inorder", "-i", action="store_true", dest="in_order",
                        help="processing in read order (default, can be omitted)")
    parser.add_argument("--root-dir", metavar="DIR", help="set the root directory to resolve relative paths to")
    parser.add_argument("-q", action="store_const", const=0, dest="verbosity",
                        help="quiet operation, suppressing warnings")
    parser.add_argument("-v", action="count", dest="verbosity", help="increase verbosity")
    parser.add_argument("--verbosity", type=int, metavar="level", dest="verbosity", help=VERBOSITY_HELP)
    parser.set_defaults(func=run, verbosity=1, parser=parser)


def run(args: argparse.Namespace) -> int:
    """Expand and print or write the result."""
    from robotmodel.xacro import run_xacro

    apply_verbose(args)
    if args.file == "-" and args.just_deps:
        args.parser.error("--deps needs an input file, not stdin")
    return run_xacro(args.file, args.mappings, output=args.output, just_deps=args.just_deps, in_order=args.in_order,
                     root_dir=args.root_dir, verbosity=args.verbosity, package_paths=args.package_path,
                     untrusted=args.untrusted)
