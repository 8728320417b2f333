"""``robotmodel bag info FILE`` (a recording's summary, as ``ros2 bag info`` prints it) and ``bag record``.

ROS 1 ``.bag`` (with rosbag info's compression line), ROS 2 bag folders (db3 or MCAP),
bare MCAP and db3 files. The program is :func:`robotmodel.recording.run_bag_info`; ``bag record``
is ``robotmodel record`` (:func:`robotmodel.recording.run_record`).
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli.record_cmd import add_record_arguments

__all__ = ["register"]


def register(sub: Any) -> None:
    """Add the ``bag`` subcommand with its ``info`` and ``record`` verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "bag", help="inspect a recording (as ros2 bag)",
        description="Inspect a recording: ROS 1 .bag, ROS 2 bag folder (db3 or MCAP), bare MCAP or db3.")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True
    info = verbs.add_parser("info", help="print information about a bag",
                            description="Print a recording's files, size, storage, duration, start, end, message "
                                        "count and topics (type, count, serialization format), as ros2 bag info; "
                                        "a ROS 1 bag also gets rosbag info's compression line.")
    info.add_argument("bag_path", metavar="FILE", help="the recording (a .bag or .mcap/.db3 file, or a bag folder)")
    info.set_defaults(func=_info)
    record = verbs.add_parser("record", help="record topics from the bus into an MCAP file (as robotmodel record)",
                              description="Record topics (default /tf /tf_static /joint_states /robot_description) "
                                          "into MCAP (rosbag2's ros2 profile, CDR) until Ctrl-C or SIGTERM; the same "
                                          "program as 'robotmodel record'.")
    add_record_arguments(record)


def _info(args: argparse.Namespace) -> int:
    from robotmodel.recording import run_bag_info

    return run_bag_info(args.bag_path)
