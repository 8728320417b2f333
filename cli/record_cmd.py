"""``robotmodel record [-o NAME] [TOPIC ...]``: record topics from the bus into a bag folder or an MCAP file.

As ``ros2 bag record`` with MCAP storage (a bag folder; ``-o OUT.mcap`` a bare MCAP file):
rosbag2's ros2 profile, CDR payloads, receive times as log times. Default topics: /tf,
/tf_static, /joint_states, /robot_description. Ctrl-C or SIGTERM finish the recording
(summary, index, metadata.yaml) and exit 0; a crash leaves every chunk flushed so far (one
per second) recoverable. The program is :func:`robotmodel.recording.run_record`.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["add_record_arguments", "register", "run"]


def register(sub: Any) -> None:
    """Add the ``record`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "record", help="record topics from the bus into a bag (ros2 bag record)",
        description="Record topics (default /tf /tf_static /joint_states /robot_description) into MCAP "
                    "(rosbag2's ros2 profile, CDR) until Ctrl-C or SIGTERM.",
    )
    add_record_arguments(parser)


def add_record_arguments(parser: argparse.ArgumentParser) -> None:
    """The words of ``record`` (also ``bag record``)."""
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record")
    parser.add_argument("-a", "--all", action="store_true",
                        help="record every topic, including those that appear later (hidden ones excepted), "
                             "as ros2 bag / rosbag record -a")
    output = parser.add_mutually_exclusive_group()
    output.add_argument("-o", "--output", metavar="NAME",
                        help="the bag folder to write, as ros2 bag record (NAME/NAME_0.mcap and metadata.yaml; "
                             "default rosbag2_YYYY_MM_DD-HH_MM_SS), or one MCAP file when NAME ends in .mcap")
    output.add_argument("-O", "--output-name", dest="output_name", metavar="NAME",
                        help="rosbag record's form: write NAME, with .mcap added unless it ends so")
    parser.add_argument("-s", "--storage", choices=["mcap"], default="mcap",
                        help="storage of the bag (MCAP, rosbag2's default since Iron)")
    parser.add_argument("--flush-interval", type=float, default=1.0, metavar="SECONDS",
                        help="finish a chunk and flush it to disk this often (default 1.0)")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (repeatable)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Record until stopped."""
    from robotmodel.recording import run_record

    name = args.output_name
    output = args.output if name is None else name if name.endswith(".mcap") else f"{name}.mcap"
    return run_record(output, args.topics, all_topics=args.all, flush_interval=args.flush_interval,
                      connect=args.connect)
