"""Helpers shared by the subcommands: the subcommand parser, xacro-style arguments, input, output.

Kept free of heavy imports: every command module imports this at ``robotmodel --help`` time.
"""

from __future__ import annotations

import argparse
import dataclasses
import logging
import os
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn, TypeVar

from robotmodel.errors import RobotModelError

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription

__all__ = [
    "CommandParser",
    "add_mapping_arguments",
    "add_model_arguments",
    "add_model_options",
    "apply_verbose",
    "joint_values",
    "load_description",
    "options_from",
    "read_stdin_document",
    "split_mappings",
    "take_mappings",
    "write_atomic",
]

REMAP = ":="
T = TypeVar("T")


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
            from robotmodel.rcl import RosArgsError, take_ros_args

            try:
                ros, words = take_ros_args(words, self.ros_node_name)
            except RosArgsError as exc:
                self.exit(2, f"{self.prog}: error: {exc}\n")
        mappings: dict[str, str] = {}
        if self.takes_mappings:
            try:
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


def options_from(cls: type[T], args: argparse.Namespace) -> T:
    """A library options dataclass filled from the parsed arguments of the same names (others keep defaults)."""
    names = {f.name for f in dataclasses.fields(cls)}  # type: ignore[arg-type]
    return cls(**{k: v for k, v in vars(args).items() if k in names})


def take_mappings(words: Sequence[str]) -> tuple[dict[str, str], list[str]]:
    """Split xacro's ``name:=value`` words from the others, as the xacro command does.

    Any word containing ``:=`` is a mapping, wherever it stands. Surrounding blanks are
    stripped; a word with an empty name or value is dropped, and so is a ``_name`` key (a
    ROS parameter assignment). A word with two ``:=`` raises ValueError.
    """
    mappings: dict[str, str] = {}
    rest: list[str] = []
    for word in words:
        if REMAP not in word:
            rest.append(word)
            continue
        parts = [p.strip() for p in word.split(REMAP)]
        if len(parts) != 2:
            raise ValueError(f"invalid remapping argument '{word}'")
        name, value = parts
        if not name or not value or (len(name) > 1 and name[0] == "_" and name[1] != "_"):
            continue
        mappings[name] = value
    return mappings, rest


def split_mappings(words: Sequence[str]) -> dict[str, str]:
    """Parse ``name:=value`` words (see :func:`take_mappings`); a word without ``:=`` raises ValueError."""
    mappings, rest = take_mappings(words)
    if rest:
        raise ValueError(f"expected name:=value, got '{rest[0]}'")
    return mappings


def add_mapping_arguments(parser: argparse.ArgumentParser) -> None:
    """Make ``parser`` (a :class:`CommandParser`) take xacro's ``name:=value`` words anywhere."""
    if not isinstance(parser, CommandParser):
        raise TypeError("xacro arguments need a CommandParser (robotmodel.cli.main builds them)")
    parser.takes_mappings = True
    parser.set_defaults(mappings={})
    parser.epilog = "name:=value words (xacro arguments) may stand anywhere on the line."


def add_model_arguments(parser: argparse.ArgumentParser, *, file_help: str | None = None,
                        file_optional: bool = False) -> None:
    """Add the FILE, ``name:=value``, package-path, trust and ``--verbose`` arguments of model commands.

    ``file_optional`` makes FILE optional (``args.file`` is then None when omitted).
    """
    add_mapping_arguments(parser)
    parser.add_argument("file", metavar="FILE", nargs="?" if file_optional else None,
                        help=file_help or "a .urdf or .xacro file ('-' reads stdin)")
    add_model_options(parser)


def add_model_options(parser: argparse.ArgumentParser) -> None:
    """Add the package-path, trust and ``--verbose`` arguments of model commands (for their own FILEs).

    A command reading several files adds its positionals itself, calls
    :func:`add_mapping_arguments` and this, and loads each with ``load_description(args, file)``.
    """
    parser.add_argument(
        "--package-path", action="append", default=[], metavar="DIR",
        help="search DIR first for ROS packages ($(find pkg), package://); repeatable",
    )
    parser.add_argument(
        "--untrusted", action="store_true",
        help="refuse $(env), $(optenv) and reads outside the input's package roots",
    )
    parser.add_argument(
        "--verbose", action="store_true", help="say which copy of each ROS package was used, and why",
    )


def apply_verbose(args: argparse.Namespace) -> None:
    """With ``--verbose``, let the package search say which copy of each package it used."""
    if getattr(args, "verbose", False):
        logging.getLogger("robotmodel.resources").setLevel(logging.INFO)


def read_stdin_document() -> str:
    """Read a whole XML document from stdin; empty or non-XML input is a URDFParseError."""
    from robotmodel.errors import URDFParseError

    text = sys.stdin.read()
    if not text.lstrip("\ufeff \t\r\n").startswith("<"):
        raise URDFParseError("<stdin>: empty document or not XML")
    return text


def load_description(args: argparse.Namespace, file: str | None = None) -> tuple[RobotDescription, Path]:
    """Load the command's FILE, or ``file`` when given ('-': stdin); returns it and the folder paths start from."""
    from robotmodel.model import load

    apply_verbose(args)
    kwargs: dict[str, Any] = {"package_paths": args.package_path, "untrusted": args.untrusted}
    source = args.file if file is None else file
    if source == "-":
        return load(read_stdin_document(), args.mappings, **kwargs), Path.cwd()
    return load(source, args.mappings, **kwargs), Path(source).resolve().parent


def write_atomic(path: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` to ``path`` via a temporary file in the same folder, so no partial file is left."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent)
    # mkstemp creates 0600; give the file the mode a plain open() would.
    umask = os.umask(0)
    os.umask(umask)
    Path(tmp).chmod(0o666 & ~umask)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def joint_values(words: list[str]) -> dict[str, float]:
    """``--joint NAME=VALUE`` words to a dict, with one-line errors."""
    values: dict[str, float] = {}
    for word in words:
        name, sep, text = word.partition("=")
        if not sep or not name:
            raise RobotModelError(f"--joint expects NAME=VALUE, got '{word}'")
        try:
            values[name] = float(text)
        except ValueError:
            raise RobotModelError(f"--joint {name}: '{text}' is not a number") from None
    return values
