"""``robotmodel view-frames`` (alias ``view_frames``): listen to TF, then draw the frame tree.

As ROS 2 Jazzy's tf2_tools view_frames: listens for ``--wait-time`` seconds (default 5),
logs the frames YAML in its ``Result:`` line, and writes ``frames_<YYYY-MM-DD_HH.MM.SS>.gv``
(local time) or ``NAME.gv`` with ``-o NAME``, then the PDF with graphviz's ``dot`` when it
is installed. It also writes the frames YAML next to them as ``NAME.yaml``.

With ``--bag FILE`` it draws the tree of a recording instead (no listening): every frame
with its newest parent, rates and spans over the whole recording.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

from robotmodel.cli._bag_args import add_bag_arguments
from robotmodel.cli._bus_args import stop_on_signals
from robotmodel.cli._common import write_atomic
from robotmodel.cli._ros_args import add_node_arguments
from robotmodel.cli._rosfmt import ros_log

__all__ = ["default_output_name", "register", "result_message", "run"]

_NODE = "view_frames"


def register(sub: Any) -> None:
    """Add the ``view-frames`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "view-frames", aliases=["view_frames"],
        help="listen to /tf and /tf_static, then write the frame tree as .gv/.pdf (tf2_tools)",
        description="Create a diagram of the TF frames being broadcast on the bus.",
    )
    parser.add_argument("--wait-time", "-t", "--duration", type=float, default=5.0, metavar="SECONDS",
                        help="listen for this many seconds before drawing the tree (default 5.0)")
    parser.add_argument("-o", "--output", metavar="NAME", help="output base name (default frames_<date>)")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (repeatable)")
    add_bag_arguments(parser)
    add_node_arguments(parser, _NODE)
    parser.set_defaults(func=run)


def default_output_name(now: float | None = None) -> str:
    """``frames_<YYYY-MM-DD_HH.MM.SS>`` in local time, view_frames' name without ``-o``."""
    return "frames_" + time.strftime("%Y-%m-%d_%H.%M.%S", time.localtime(now))


def result_message(frames_yaml: str) -> str:
    """The ``Result:`` log text: the FrameGraph service response as rclpy prints it."""
    return f"Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml={frames_yaml!r})"


def run(args: argparse.Namespace) -> int:
    """Listen, then write the .gv (and .pdf, .yaml)."""
    if not args.wait_time >= 0.0:
        print("robotmodel view-frames: error: --wait-time must be >= 0", file=sys.stderr)
        return 2
    from robotmodel.tf import Buffer, write_view_frames

    if args.bag is not None:
        from robotmodel.cli._bag_args import load_bag

        loaded = load_bag(args)
        buffer: Buffer = loaded.buffer
        now_ns = loaded.end_ns or time.time_ns()
    else:
        stop = stop_on_signals()
        from robotmodel.bus import Node
        from robotmodel.tf_ros import TransformListener

        buffer = Buffer()
        # /tf and /tf_static are absolute: the namespace names the node only, as in ROS.
        from robotmodel.cli._ros_args import warn_ignored_params

        warn_ignored_params(args.ros, args.namespace, args.node_name or _NODE)
        with Node(args.node_name or _NODE, args.namespace, connect=args.connect, remappings=args.ros.remaps) as node, \
                TransformListener(buffer, node):
            ros_log("INFO", _NODE, f"Listening to tf data for {args.wait_time} seconds...")
            stop.wait(args.wait_time)
        now_ns = time.time_ns()
    ros_log("INFO", _NODE, "Generating graph...")
    frames_yaml = buffer.all_frames_as_yaml()
    ros_log("INFO", _NODE, result_message(frames_yaml))
    name = args.output if args.output is not None else default_output_name()
    ros_log("INFO", _NODE, f"Exporting graph in {name}.pdf file...")
    _gv, pdf = write_view_frames(buffer, name, now_ns)
    write_atomic(Path(f"{name}.yaml"), frames_yaml if frames_yaml.endswith("\n") or not frames_yaml
                 else frames_yaml + "\n")
    if pdf is None:
        print(f"dot (graphviz) is not installed: {name}.pdf was not created", file=sys.stderr)
    return 0
