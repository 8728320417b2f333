"""``robotmodel demo``: the whole pipeline on the bundled diffbot, every part a process on a private bus.

Started and stopped here, nothing by hand: the recorder (MCAP), a static map → odom
transform, robot_state_publisher and joint_state_publisher on the diffbot (from xacro),
the odometry example (``robot_controller`` and ``sensor_simulator``, whose wheel angles
reach joint_state_publisher through ``--source-list /wheel_states``), a live ``tf2_echo
map base_footprint``, ``view_frames``, and the viewer following the robot, with a
screenshot of it taken by headless Chromium when one is installed. After the run, one
offline question is answered from the recording with ``tf2-echo --bag``.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]

ROBOT = "diffbot.urdf.xacro"
#: The recorded topics: TF, the robot, and the odometry example's own.
TOPICS = ("/tf", "/tf_static", "/joint_states", "/robot_description", "/odom", "/cmd_vel")
#: map → odom, as a localization node would publish it.
MAP_TO_ODOM = ("1.0", "0.5", "0.0")
#: The viewer's camera, in odom, before it follows base_link with this offset: above, behind and to
#: the right of the robot as it sets off along x, close enough for the robot to fill the picture.
VIEWER_CAMERA = "-0.6,-0.45,0.4:0,0,0"


def register(sub: Any) -> None:
    """Add the ``demo`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "demo", help="run the whole pipeline on the bundled diffbot: publishers, odometry, TF tools, viewer, "
                     "recording",
        description="Drive the bundled diffbot with the odometry example while robot_state_publisher, "
                    "joint_state_publisher, a static map->odom transform, tf2_echo, view_frames, the viewer and "
                    "a recorder run beside it as processes on a private bus (own port and ROS_DOMAIN_ID). "
                    "Writes the recording, the frame diagram and a screenshot into a fresh folder, then answers "
                    "one question from the recording.")
    parser.add_argument("--duration", type=float, default=35.0, metavar="S",
                        help="seconds to run (default 35: the odometry pattern takes 30)")
    parser.add_argument("--no-browser", action="store_true", help="do not open the viewer in the web browser")
    parser.add_argument("--output", metavar="DIR", help="folder for the files (default ./robotmodel-demo-<time>)")
    parser.add_argument("--time-scale", type=float, default=1.0, metavar="X",
                        help="run the odometry example X times faster than real time (default 1)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Start everything, run for --duration (or until Ctrl-C), stop everything, report."""
    from robotmodel.cli._demo_run import Demo

    code: int = Demo(args).run()
    return code
