"""``robotmodel fk``: every link's pose in the root frame for given joint values."""

from __future__ import annotations

import argparse
import json
import math
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
    from robotmodel.kinematics import KinematicModel, KinematicState, parse_joint_words

    desc, _ = load_description(args)
    model = KinematicModel(desc)
    state = KinematicState(model).update(parse_joint_words(args.joint), clamp=args.clamp)
    links = [args.link] if args.link else list(model.link_names)
    # An unknown --link is the library's UnknownLinkError, as from every kinematics API.
    poses = {name: state.link_pose(name) for name in links}
    if args.format == "json":
        report = {"root": model.root, "links": {
            name: {"xyz": list(p.translation), "quat_xyzw": list(p.rotation), "rpy": list(p.rpy())}
            for name, p in poses.items()
        }}
        print(json.dumps(report, indent=2))
        return 0
    print(f"root: {model.root}")
    for name, pose in poses.items():
        x, y, z = pose.translation
        qx, qy, qz, qw = pose.rotation
        r, p, yaw = pose.rpy()
        print(f"{name}:")
        print(f"  Translation: [{x:.6f}, {y:.6f}, {z:.6f}]")
        print(f"  Rotation: in Quaternion (xyzw) [{qx:.6f}, {qy:.6f}, {qz:.6f}, {qw:.6f}]")
        print(f"  Rotation: in RPY (radian) [{r:.6f}, {p:.6f}, {yaw:.6f}]")
        print(f"  Rotation: in RPY (degree) [{math.degrees(r):.6f}, {math.degrees(p):.6f}, "
              f"{math.degrees(yaw):.6f}]")
    return 0
