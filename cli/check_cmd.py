"""``robotmodel check-urdf`` (alias ``check_urdf``): urdfdom's check_urdf, plus lint, for one file or many.

The program is :func:`robotmodel.check.run_check`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_mapping_arguments, add_model_options, apply_verbose, options_from

FORMATS = ("text", "json", "github", "sarif")  # robotmodel.check.FORMATS; not imported: --help stays light


def register(sub: Any) -> None:
    """Add the ``check-urdf`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "check-urdf", aliases=["check_urdf"],
        help="parse and check URDF/xacro files; prints the tree as urdfdom's check_urdf does",
        description="Check URDF (or xacro) files ('-' reads stdin). For one file, on success stdout is "
        "exactly check_urdf's and lint warnings follow on stderr; on failure stdout is empty, one line per "
        "problem goes to stderr and the exit code is 1 (urdfdom exits 255). Beyond urdfdom it rejects "
        "partial cycles, links with two parents, self-joints, zero axes, NaN/inf and mimics of "
        "missing joints. Several files (and globs, ** included) are checked in parallel and end with a "
        "summary line on stderr; the exit code is 1 if any fails. A robotmodel.toml or [tool.robotmodel] "
        "in pyproject.toml names entry points and their xacro args; macro-only xacro files are checked "
        "through the entries that include them, and without FILE every entry is checked.",
    )
    add_mapping_arguments(parser)
    parser.add_argument("files", metavar="FILE", nargs="*",
                        help="a .urdf or .xacro file or glob ('-' reads stdin)")
    add_model_options(parser)
    parser.add_argument("--strict", action="store_true", help="treat lint warnings as errors")
    parser.add_argument(
        "--format", choices=FORMATS, default="text",
        help="json: robot, root, tree and findings (with codes and places); github: workflow commands "
        "(annotations on the pull request); sarif: a SARIF 2.1.0 log for code scanning",
    )
    parser.add_argument("--config", metavar="PATH",
                        help="the project config (default: robotmodel.toml or a pyproject.toml with "
                        "[tool.robotmodel], searched upward from the working directory)")
    parser.add_argument("--no-config", action="store_true", help="ignore any project config")
    parser.add_argument("-j", "--jobs", type=int, default=0, metavar="N",
                        help="check N files at once (default: one per CPU core)")
    # Kept so errors found after parsing (no FILE, '-' among files) print this command's usage too.
    parser.set_defaults(func=run, parser=parser)


def run(args: argparse.Namespace) -> int:
    """Check the files."""
    from robotmodel.check import CheckOptions, run_check

    apply_verbose(args)
    return run_check(options_from(CheckOptions, args), args.parser.error)
