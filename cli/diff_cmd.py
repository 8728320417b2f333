"""``robotmodel diff``: what a change to a robot description changes, as ``diff`` reports files.

The program is :func:`robotmodel.diff.run_diff`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_mapping_arguments, add_model_options, apply_verbose


def register(sub: Any) -> None:
    """Add the ``diff`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "diff", help="semantic diff of two robot descriptions (links, joints, poses at zero)",
        description="Compare two robot descriptions (URDF or xacro; '-' reads one from stdin), or with "
        "--git REV one file as it was at git revision REV against the working copy: links and joints "
        "added, removed, renamed and changed (origins in mm and degrees), materials, and how every "
        "link on both sides moved at the zero configuration (every joint at 0). Numbers are equal "
        "within --tolerance. Exit 0 when equal, 1 when different, 2 on error, as diff.",
    )
    add_mapping_arguments(parser)
    parser.add_argument("old", metavar="OLD", help="the description before the change (with --git: FILE)")
    parser.add_argument("new", metavar="NEW", nargs="?", help="the description after the change (not with --git)")
    parser.add_argument("--git", metavar="REV",
                        help="compare FILE at git revision REV (xacro includes from that revision) with FILE")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format")
    parser.add_argument("--tolerance", type=float, default=1e-9, metavar="T",
                        help="numbers within T are equal (relative above 1; metres and radians); default 1e-9")
    add_model_options(parser)
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Print the diff; 0 when equal, 1 when different, 2 when a description cannot be read."""
    from robotmodel.diff import run_diff

    apply_verbose(args)
    return run_diff(args.old, args.new, args.mappings, git=args.git, format=args.format, tolerance=args.tolerance,
                    package_paths=args.package_path, untrusted=args.untrusted, command=args.command)
