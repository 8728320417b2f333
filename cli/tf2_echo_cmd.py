"""``robotmodel tf2-echo SOURCE TARGET [RATE]`` (alias ``tf2_echo``): print a transform as it arrives.

The program (and its ``--bag`` form) is :func:`robotmodel.tf_ros.run_tf2_echo`; it parses its
own words, as ROS's does.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``tf2-echo`` subcommand (it parses its own words, as ROS's does)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "tf2-echo", aliases=["tf2_echo", "tf_echo"], prefix_chars="\x01", add_help=False,
        help="print a transform from the bus (or a recording: --bag FILE) in tf2_echo's format",
        description="tf2-echo SOURCE TARGET [RATE] [--connect ENDPOINT] [--namespace NS] [--ros-args -r /tf:=TOPIC] | "
                    "tf2-echo --bag FILE SOURCE TARGET [--time T | --every DT] [--urdf FILE]",
    )
    parser.add_argument("words", nargs="*")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run tf2_echo on the words."""
    from robotmodel.tf_ros import run_tf2_echo

    return run_tf2_echo(args.words)
