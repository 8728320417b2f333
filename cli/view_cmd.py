"""``robotmodel view``: the robot in the browser (meshcat), with joint sliders, frames and live modes.

The program is :func:`robotmodel.viewer.run_view` (the live modes: :class:`robotmodel.viewer.LiveViewer`).
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_mapping_arguments, options_from
from robotmodel.cli._node_args import add_node_arguments


def _port(text: str) -> int:
    """``--port``'s type: a TCP port, 0 to 65535 (argparse prints the error and exits 2)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid port: '{text}'") from None
    if not 0 <= value <= 65535:
        raise argparse.ArgumentTypeError(f"port {value} is out of range: a TCP port is 0 to 65535")
    return value


def add_viewer_arguments(parser: argparse.ArgumentParser, *, live_flags: bool = True) -> None:
    """The arguments ``view`` and ``joint-state-publisher-gui`` share."""
    add_mapping_arguments(parser)
    parser.add_argument("file", metavar="FILE", nargs="?",
                        help="a .urdf or .xacro file ('-' reads stdin; default: the robot_description topic)")
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="search DIR first for ROS packages ($(find pkg), package://); repeatable")
    parser.add_argument("--untrusted", action="store_true",
                        help="refuse $(env), $(optenv) and reads outside the input's package roots")
    parser.add_argument("--port", type=_port, default=None,
                        help="serve on this port of 127.0.0.1 (default: 7000, or the next free one)")
    parser.add_argument("--open", action="store_true", help="open the page in the default web browser")
    parser.add_argument("--collisions", action="store_true", help="show collision geometry too")
    parser.add_argument("--frames", default=None, metavar="all|none|LINK,...",
                        help="draw these links' frames as named axes (default: none); with --tf, these "
                             "frames from /tf (default: all)")
    parser.add_argument("--camera", metavar="X,Y,Z[:TX,TY,TZ]",
                        help="put the camera at X,Y,Z looking at TX,TY,TZ (default 0,0,0): metres in the "
                             "scene's frame (the fixed frame), Z up; write --camera=-1,... when X is negative")
    parser.add_argument("--joint", action="append", default=[], metavar="NAME=VALUE",
                        help="initial joint value (radians or metres); repeatable")
    parser.add_argument("--no-cache", action="store_true", help="convert meshes again, ignoring the disk cache")
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to (e.g. tcp/192.168.1.10:7447); repeatable")
    if live_flags:
        parser.add_argument("--follow", action="store_true",
                            help="draw the robot from /joint_states on the bus")
        parser.add_argument("--tf", action="store_true", help="draw the frames on /tf and /tf_static")
        parser.add_argument("--fixed-frame", metavar="FRAME",
                            help="the frame --tf draws from, as rviz's Fixed Frame (default: the robot's root)")
        parser.add_argument("--track", metavar="FRAME",
                            help="with --tf: the camera follows FRAME, keeping its offset (and any orbit or "
                                 "zoom done in the page)")
        parser.add_argument("--publish", action="store_true", help="publish the sliders' values on /joint_states")
    add_node_arguments(parser, "robotmodel_view")


def register(sub: Any) -> None:
    """Add the ``view`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "view", help="show the robot in the browser, with joint sliders (meshcat)",
        description="Serve a page on 127.0.0.1 showing the robot's visuals (meshes included), one slider "
        "per movable joint (as joint_state_publisher_gui), and frames as named axes. With --static-html or "
        "--screenshot it writes the file and exits instead. Runs until Ctrl-C.",
    )
    add_viewer_arguments(parser)
    parser.add_argument("--static-html", metavar="OUT.html",
                        help="write one self-contained page of the robot (offline-viewable) and exit")
    parser.add_argument("--screenshot", metavar="OUT.png",
                        help="render the robot with headless Chromium to a PNG and exit")
    parser.add_argument("--size", default="1280x800", metavar="WxH", help="screenshot size (default 1280x800)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Write the files, or serve until Ctrl-C."""
    from robotmodel.viewer import ViewOptions, run_view

    return run_view(options_from(ViewOptions, args))
