"""``robotmodel record -o OUT.mcap [TOPIC ...]``: record topics from the bus into an MCAP file.

As ``ros2 bag record`` with MCAP storage: rosbag2's ros2 profile, CDR payloads, receive
times as log times. Default topics: /tf, /tf_static, /joint_states, /robot_description.
Ctrl-C or SIGTERM finish the file (summary and index) and exit 0; a crash leaves every
chunk flushed so far (one per second) recoverable.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from robotmodel.rcl import ros_log
from robotmodel.signals import stop_on_signals

__all__ = ["register", "run"]

_NODE = "rosbag2_recorder"
_DEFAULT_TOPICS = ("/tf", "/tf_static", "/joint_states", "/robot_description")


def register(sub: Any) -> None:
    """Add the ``record`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "record", help="record topics from the bus into an MCAP file (ros2 bag record)",
        description="Record topics (default /tf /tf_static /joint_states /robot_description) into MCAP "
                    "(rosbag2's ros2 profile, CDR) until Ctrl-C or SIGTERM.",
    )
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="topics to record")
    parser.add_argument("-o", "--output", required=True, metavar="OUT.mcap", help="the MCAP file to write")
    parser.add_argument("--flush-interval", type=float, default=1.0, metavar="SECONDS",
                        help="finish a chunk and flush it to disk this often (default 1.0)")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (repeatable)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Subscribe, write until a stop signal, then close the file properly."""
    out = Path(args.output)
    if out.exists():
        print(f"robotmodel record: error: {out} already exists (not overwritten)", file=sys.stderr)
        return 1
    if not args.flush_interval > 0:
        print("robotmodel record: error: --flush-interval must be > 0", file=sys.stderr)
        return 2
    stop = stop_on_signals()
    from robotmodel.bus import Node
    from robotmodel.recording import McapWriter, Recorder

    topics = args.topics or list(_DEFAULT_TOPICS)
    with McapWriter(out, flush_every_s=args.flush_interval) as writer, Node(_NODE, connect=args.connect) as node:
        recorder = Recorder(node, writer, topics,
                            on_subscribed=lambda t, _ty: ros_log("INFO", _NODE, f"Subscribed to topic '{t}'"))
        ros_log("INFO", _NODE, f"Recording to '{out}'...")
        try:
            # Flushes in quiet spells too, so a crash never loses more than one interval.
            while not stop.wait(args.flush_interval / 2):
                writer.flush_if_due()
        finally:
            recorder.close()
    ros_log("INFO", _NODE, f"Recording stopped: {writer.messages} message(s) in '{out}'")
    return 0
