"""``robotmodel launch FILE | PKG FILE [name:=value ...]``: ROS 1/2 XML and ROS 2 Python launch files, without ROS.

The nodes this project provides run as processes on the bus (robot/joint state publishers,
the sliders, static transforms, the viewer for rviz); any other node is listed as skipped.
See :mod:`robotmodel.launch` for what is read; the program is :func:`robotmodel.launch.run_launch`.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._common import add_mapping_arguments


def register(sub: Any) -> None:
    """Add the ``launch`` subcommand (alias ``roslaunch``)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "launch", aliases=["roslaunch"],
        help="run a ROS 1 or ROS 2 XML or ROS 2 Python launch file's description nodes (roslaunch / ros2 launch)",
        description="Read a ROS 1 (.launch) or ROS 2 (.launch.xml) XML launch file, or run a ROS 2 Python launch file "
        "(.launch.py, the file's own code against robotmodel's launch, launch_ros and ament_index_python), and "
        "start the nodes "
        "robotmodel provides as processes on the bus: robot_state_publisher, joint_state_publisher(_gui), "
        "static_transform_publisher (tf or tf2_ros), and the viewer for rviz/rviz2. Other nodes are listed "
        "as skipped. Ctrl-C or SIGTERM stop every process.",
    )
    add_mapping_arguments(parser)
    parser.epilog = (f"{parser.epilog or ''} Each process gets what ROS would hand its node, as '--ros-args' (see the "
                     "command's --help): -r __node:=NAME and -r __ns:=/NS, parameters not mapped onto the command's "
                     "flags as -p NAME:=VALUE (ROS 2 <set_parameter> too), ROS 2 <param from=FILE/> as --params-file "
                     "FILE, and the remap rules as -r FROM:=TO: ROS 1 <remap> inside the node or earlier in its "
                     "group/file scope (the last rule per resolved name), ROS 2 <set_remap> in scope then the node's "
                     "own <remap> (the first match wins). --dry-run shows the command lines.").strip()
    parser.add_argument("target", metavar="FILE|PKG", help="a launch file, or a package name followed by FILE")
    parser.add_argument("file", metavar="FILE", nargs="?", help="the launch file's name inside package PKG")
    parser.add_argument("--dry-run", action="store_true",
                        help="print the processes that would start (and the skipped nodes), start nothing")
    parser.add_argument("-s", "--show-args", "--show-arguments", action="store_true", dest="show_args",
                        help="show the arguments a Python launch file declares (as ros2 launch --show-args), "
                        "start nothing")
    parser.add_argument("--no-browser", action="store_true",
                        help="serve the viewer pages without opening a browser")
    parser.add_argument("--package-path", action="append", default=[], metavar="DIR",
                        help="search DIR first for ROS packages ($(find pkg), PKG); repeatable")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Read the file, print the plan, then run it (unless --dry-run)."""
    from robotmodel.launch import run_launch

    return run_launch(args.target, args.file, args.mappings, package_paths=args.package_path, dry_run=args.dry_run,
                      browser=not args.no_browser, show_args=args.show_args)
