"""Helpers shared by the subcommands: xacro-style and model arguments, options handed to the library.

Kept free of heavy imports: every command module imports this at ``robotmodel --help`` time.
"""

from __future__ import annotations

import argparse
import dataclasses
import logging
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from robotmodel.cli._parser import CommandParser

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription

__all__ = [
    "CommandParser",
    "add_mapping_arguments",
    "add_model_arguments",
    "add_model_options",
    "apply_verbose",
    "load_description",
    "options_from",
]

T = TypeVar("T")


def options_from(cls: type[T], args: argparse.Namespace) -> T:
    """A library options dataclass filled from the parsed arguments of the same names (others keep defaults)."""
    names = {f.name for f in dataclasses.fields(cls)}  # type: ignore[arg-type]
    return cls(**{k: v for k, v in vars(args).items() if k in names})


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


def load_description(args: argparse.Namespace, file: str | None = None) -> tuple[RobotDescription, Path]:
    """:func:`robotmodel.model.load_source` on the command's FILE (or ``file``), with its model options."""
    from robotmodel.model import load_source

    apply_verbose(args)
    return load_source(args.file if file is None else file, args.mappings, package_paths=args.package_path,
                       untrusted=args.untrusted)
