"""Entry point of the ``robotmodel`` console script.

Each subcommand lives in its own module exposing ``register(subparsers)``, which adds
a parser (with its ROS spelling as an alias) and sets ``func`` to a callable taking the
parsed namespace and returning an exit code. Errors the library raises on purpose
(:class:`robotmodel.errors.RobotModelError`) are printed as one line and give exit 1;
anything else is a bug and keeps its traceback.

Subparsers are :class:`robotmodel.cli._parser.CommandParser`: a command that calls
``add_model_arguments`` (or ``add_mapping_arguments``) gets xacro's ``name:=value`` words
from anywhere on the line, and errors print that command's usage. Command modules are
imported to build ``--help``, so they import only argparse-level code at the top and their
implementation inside the handler (tests/cli/test_startup.py checks the module set).
"""

from __future__ import annotations

import argparse
import importlib
import logging
import sys
from collections.abc import Sequence

from robotmodel.cli._parser import CommandParser

from robotmodel.errors import RobotModelError

# Order here is the order of `robotmodel --help`.
COMMAND_MODULES: tuple[str, ...] = (
    "robotmodel.cli.demo_cmd",
    "robotmodel.cli.xacro_cmd",
    "robotmodel.cli.check_cmd",
    "robotmodel.cli.graphviz_cmd",
    "robotmodel.cli.fk_cmd",
    "robotmodel.cli.diff_cmd",
    "robotmodel.cli.static_tf_cmd",
    "robotmodel.cli.tf2_echo_cmd",
    "robotmodel.cli.view_frames_cmd",
    "robotmodel.cli.tf_export_cmd",
    "robotmodel.cli.record_cmd",
    "robotmodel.cli.bag_cmd",
    "robotmodel.cli.rsp_cmd",
    "robotmodel.cli.jsp_cmd",
    "robotmodel.cli.jsp_gui_cmd",
    "robotmodel.cli.view_cmd",
    "robotmodel.cli.topic_cmd",
    "robotmodel.cli.node_cmd",
    "robotmodel.cli.param_cmd",
    "robotmodel.cli.router_cmd",
    "robotmodel.cli.launch_cmd",
    "robotmodel.cli.run_cmd",
)


def build_parser() -> argparse.ArgumentParser:
    """Build the top-level parser with every subcommand registered."""
    parser = argparse.ArgumentParser(
        prog="robotmodel",
        description="ROS's robot-model and transform tools without ROS.",
    )
    # Each subcommand's parser is a CommandParser: name:=value words anywhere, its own usage on errors.
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=CommandParser)
    sub.required = True
    for name in COMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the process exit code."""
    logging.basicConfig(format="%(message)s", level=logging.WARNING)
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        code: int = args.func(args)
    except RobotModelError as exc:
        # One line, always: join any lines a wrapped library message carries.
        print(f"robotmodel {args.command}: error: {' '.join(str(exc).splitlines())}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    return code


if __name__ == "__main__":
    sys.exit(main())
