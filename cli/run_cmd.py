"""``robotmodel run PACKAGE EXECUTABLE [ARGS ...]`` (alias ``rosrun``): a ROS executable's stand-in, as ``ros2 run``.

A tutorial's ``ros2 run tf2_ros static_transform_publisher --x 1 ...`` or ``ros2 run
robot_state_publisher robot_state_publisher --ros-args -p robot_description:=...`` runs here
as written after ``robotmodel``: the pair names the robotmodel command
(:data:`robotmodel.launch.STANDINS`), which gets the arguments unchanged.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``run`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "run", aliases=["rosrun"],
        help="run the stand-in of a ROS executable by package and name (as ros2 run / rosrun)",
        description="Run robotmodel's stand-in of PACKAGE EXECUTABLE with ARGS as given, e.g. "
                    "'robotmodel run tf2_ros static_transform_publisher --x 1 --frame-id a --child-frame-id b'.",
    )
    parser.add_argument("package", metavar="PACKAGE", help="the ROS package (e.g. tf2_ros)")
    parser.add_argument("executable", metavar="EXECUTABLE", help="the executable in it (e.g. tf2_echo)")
    parser.add_argument("args", nargs=argparse.REMAINDER, metavar="ARGS", help="its arguments, unchanged")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the stand-in command with the arguments."""
    from robotmodel.cli.main import main

    from robotmodel.launch import standin_command

    code: int = main([*standin_command(args.package, args.executable), *args.args])
    return code
