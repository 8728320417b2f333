"""``robotmodel fk``: every link's pose in the root frame for given joint values.

The program is :func:`robotmodel.kinematics.run_fk`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_model_arguments, load_description


def register(sub: Any) -> None:
    """Add the ``fk`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "fk", help="forward kinematics: each link's pose in the root frame",
        description="Print every link's pose (or one link's) in the root frame. Joints not given "
        "take joint_state_publisher's default: 0, or the middle of the limits when 0 is outside them.",
    )
    add_model_arguments(parser)
    parser.add_argument("--joint", action="append", default=[], metavar="NAME=VALUE",
                        help="a joint value (radians or metres); repeatable")
    parser.add_argument("--link", help="print only this link")
    parser.add_argument("--clamp", action="store_true", help="clamp values into the joint limits")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Compute and print the poses."""
    from robotmodel.kinematics import parse_joint_words, run_fk

    return run_fk(load_description(args)[0], parse_joint_words(args.joint), link=args.link, clamp=args.clamp,
                  format=args.format)
