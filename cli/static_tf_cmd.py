"""``robotmodel static-transform-publisher`` (alias ``static_transform_publisher``).

The program is :func:`robotmodel.tf_ros.run_static_transform_publisher`; it parses its own
words (ROS 2's flags and positional forms, ROS 1's with a period), as ROS's does.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``static-transform-publisher`` subcommand (it parses its own words, as ROS's does)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "static-transform-publisher", aliases=["static_transform_publisher"],
        prefix_chars="+", add_help=False,
        help="publish a static transform on /tf_static (tf2_ros's flags and positional forms)",
        description="--x X --y Y --z Z [--qx --qy --qz --qw | --roll --pitch --yaw] --frame-id F "
        "--child-frame-id C [--connect ENDPOINT] [--namespace NS] [--ros-args -r __ns:=/NS -r /tf_static:=TOPIC]; "
        "or x y z yaw pitch roll F C [period_ms]; or "
        "x y z qx qy qz qw F C [period_ms]",
    )
    parser.add_argument("words", nargs="*")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run static_transform_publisher on the words."""
    from robotmodel.tf_ros import run_static_transform_publisher

    return run_static_transform_publisher(args.words)
