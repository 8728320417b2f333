"""The parser of every subcommand: xacro's ``name:=value`` words and ROS's ``--ros-args`` blocks taken out first."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import NoReturn

__all__ = ["CommandParser"]


class CommandParser(argparse.ArgumentParser):
    """The parser of one subcommand.

    As the ``xacro`` command does, every word holding ``:=`` is taken out of the line
    before parsing when the command takes xacro arguments (see
    :func:`add_mapping_arguments`), so ``name:=value`` may stand anywhere; the mappings
    land in ``args.mappings``. Errors, unknown options included, print this
    subcommand's usage rather than the top level's.
    """

    takes_mappings = False
    #: Set by :func:`robotmodel.cli._node_args.add_node_arguments`: ``--ros-args`` blocks are read first.
    takes_ros_args = False
    ros_node_name: str | None = None

    def parse_known_args(  # type: ignore[override]
        self, args: Sequence[str] | None = None, namespace: argparse.Namespace | None = None
    ) -> tuple[argparse.Namespace, list[str]]:
        words = list(sys.argv[1:] if args is None else args)
        ros = None
        if self.takes_ros_args:
            # Before the mappings: '__ns:=/r1' is a ROS remap rule, not a xacro argument.
            from robotmodel.rcl import RosArgsError, take_node_args

            try:
                ros, words = take_node_args(words, self.ros_node_name)
            except RosArgsError as exc:
                self.exit(2, f"{self.prog}: error: {exc}\n")
        mappings: dict[str, str] = {}
        if self.takes_mappings:
            try:
                from robotmodel.xacro import take_mappings

                mappings, words = take_mappings(words)
            except ValueError as exc:
                self.error(str(exc))
        parsed, extras = super().parse_known_args(words, namespace)
        if extras:
            self.error(f"unrecognized arguments: {' '.join(extras)}")
        if self.takes_mappings:
            parsed.mappings = mappings
        if ros is not None:
            from robotmodel.cli._node_args import settle

            from robotmodel.rcl import RosArgsError

            try:
                settle(parsed, ros)
            except RosArgsError as exc:  # one line, as the library's errors
                self.exit(2, f"{self.prog}: error: {exc}\n")
        return parsed, []

    def format_usage(self) -> str:
        """The usage line, with the ``name:=value`` words when the command takes them."""
        return self._with_mappings(super().format_usage())

    def format_help(self) -> str:
        """The help text, with the ``name:=value`` words in its usage line."""
        return self._with_mappings(super().format_help())

    def _with_mappings(self, text: str) -> str:
        if not self.takes_mappings:
            return text
        return text.replace(f"usage: {self.prog}", f"usage: {self.prog} [name:=value ...]", 1)

    def error(self, message: str) -> NoReturn:
        """Print the usage and ``robotmodel CMD: error: message``; exit 2 (as argparse and xacro)."""
        self.print_usage(sys.stderr)
        self.exit(2, f"{self.prog}: error: {message}\n")
