"""The ``--bag FILE`` options shared by the commands that read a recording instead of the bus."""

from __future__ import annotations

import argparse

__all__ = ["add_bag_arguments"]


def add_bag_arguments(parser: argparse.ArgumentParser, *, required: bool = False) -> None:
    """``--bag FILE``, ``--urdf FILE`` (the robot for joint states) and ``--no-progress``."""
    parser.add_argument("--bag", required=required, metavar="FILE",
                        help="read TF from this recording (ROS 1 .bag, ROS 2 bag folder, .db3 or .mcap)")
    parser.add_argument("--urdf", metavar="FILE",
                        help="with --bag: the robot whose /joint_states to turn into TF when there is no /tf "
                             "(default: the recorded /robot_description)")
    parser.add_argument("--no-progress", action="store_true", help="with --bag: no progress bar on stderr")
