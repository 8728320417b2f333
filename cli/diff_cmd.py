"""``robotmodel diff``: what a change to a robot description changes, as ``diff`` reports files."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from robotmodel.cli._common import add_mapping_arguments, add_model_options, apply_verbose, load_description

from robotmodel.errors import RobotModelError


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


def _fail(args: argparse.Namespace, message: str) -> int:
    print(f"robotmodel {args.command}: error: {' '.join(message.splitlines())}", file=sys.stderr)
    return 2


def run(args: argparse.Namespace) -> int:
    """Print the diff; 0 when equal, 1 when different, 2 when a description cannot be read."""
    if args.git is None and args.new is None:
        return _fail(args, "two files to compare, OLD and NEW (or one FILE with --git REV)")
    if args.git is not None and args.new is not None:
        return _fail(args, "--git REV compares one FILE with its revision REV; got two files")
    if not args.tolerance >= 0.0 or args.tolerance == float("inf"):
        return _fail(args, f"--tolerance must be a finite number >= 0, not {args.tolerance}")
    if args.old == "-" and args.new == "-":
        return _fail(args, "only one of OLD and NEW can be '-' (stdin)")
    from robotmodel.diff import diff_descriptions, load_revision, render_json, render_text

    apply_verbose(args)
    try:
        if args.git is not None:
            old, old_label = load_revision(args.old, args.git, args.mappings, package_paths=args.package_path,
                                           untrusted=args.untrusted)
            new_file = args.old
        else:
            old, _ = load_description(args, args.old)
            old_label, new_file = args.old, args.new
        new, _ = load_description(args, new_file)
        diff = diff_descriptions(old, new, tolerance=args.tolerance, old_label=old_label, new_label=new_file)
    except RobotModelError as exc:
        return _fail(args, str(exc))
    sys.stdout.write(render_json(diff) if args.format == "json" else render_text(diff))
    sys.stdout.flush()
    return 0 if diff.equal else 1
