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
    import sys

    from robotmodel.cli._common import joint_values
    from robotmodel.cli._live import serve_live
    from robotmodel.cli.jsp_cmd import jsp_settings
    from robotmodel.cli.view_cmd import _load, frames_spec

    from robotmodel.rcl import RosArgsError, logger_name, node_params, ros_log

    name = args.node_name or "robotmodel_view"
    try:
        # joint_state_publisher_gui runs joint_state_publisher inside: the same parameters.
        settings = jsp_settings(node_params(args.ros, args.namespace, name),
                                lambda text: ros_log("WARN", logger_name(args.namespace, name), text))
    except RosArgsError as exc:
        print(f"robotmodel joint-state-publisher-gui: error: {exc}", file=sys.stderr)
        return 2
    initial = joint_values(args.joint)
    initial.update(settings.pop("zeros"))  # zeros.JOINT wins over --joint, as a parameter over its flag
    desc = _load(args) if args.file is not None else None
    code: int = serve_live(args, desc, initial, frames_spec(args.frames), publish=True, jsp_options=settings)
    return code
