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
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Serve the page with publishing on."""
    from robotmodel.cli._common import joint_values
    from robotmodel.cli._live import serve_live
    from robotmodel.cli.view_cmd import _load, frames_spec

    desc = _load(args) if args.file is not None else None
    code: int = serve_live(args, desc, joint_values(args.joint), frames_spec(args.frames), publish=True)
    return code
