"""``robotmodel joint-state-publisher-gui``: joint_state_publisher_gui in the browser.

The viewer's page with its sliders, publishing their values on ``/joint_states`` (at
joint_state_publisher's 10 Hz, mimic joints included).
"""

from __future__ import annotations

import argparse
from typing import Any


def register(sub: Any) -> None:
    """Add the ``joint-state-publisher-gui`` subcommand (alias ``joint_state_publisher_gui``)."""
    from robotmodel.cli.view_cmd import add_viewer_arguments

    parser: argparse.ArgumentParser = sub.add_parser(
        "joint-state-publisher-gui", aliases=["joint_state_publisher_gui"],
        help="sliders in the browser publishing /joint_states (joint_state_publisher_gui)",
        description="joint_state_publisher_gui: one slider per movable joint (Center and Randomize "
        "buttons), published on /joint_states, with the robot drawn beside them. Serves a page on "
        "127.0.0.1 and prints its URL. Without FILE the robot comes from /robot_description. Runs until "
        "Ctrl-C.",
    )
    add_viewer_arguments(parser, live_flags=False)
    parser.epilog = (f"{parser.epilog} joint_state_publisher's parameters apply (rate, zeros.JOINT as the "
                     "sliders' start, source_list, publish_default_*, use_mimic_tags, ...; see "
                     "joint-state-publisher --help).")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Serve the page with publishing on."""
    from robotmodel.cli._common import options_from

    from robotmodel.viewer import ViewOptions, run_joint_state_publisher_gui

    return run_joint_state_publisher_gui(options_from(ViewOptions, args))
