"""Helpers shared by the subcommands: xacro-style arguments and atomic output files."""

from __future__ import annotations

import argparse
import os
import tempfile
from collections.abc import Sequence
from pathlib import Path

from robotmodel.errors import RobotModelError

__all__ = ["add_model_arguments", "split_mappings", "write_atomic"]


def add_model_arguments(parser: argparse.ArgumentParser) -> None:
    """Add the FILE, ``name:=value`` and package-path arguments every model command takes."""
    parser.add_argument("file", metavar="FILE", help="a .urdf or .xacro file ('-' reads stdin)")
    parser.add_argument("mappings", nargs="*", metavar="name:=value", help="xacro arguments")
    parser.add_argument(
        "--package-path", action="append", default=[], metavar="DIR",
        help="search DIR first for ROS packages ($(find pkg), package://); repeatable",
    )
    parser.add_argument(
        "--untrusted", action="store_true",
        help="refuse $(env), $(optenv) and reads outside the input's package roots",
    )


def split_mappings(words: Sequence[str]) -> dict[str, str]:
    """Parse xacro's ``name:=value`` words; like xacro, ``_name`` keys are ROS parameters and dropped."""
    mappings: dict[str, str] = {}
    for word in words:
        name, sep, value = word.partition(":=")
        if not sep or not name:
            raise RobotModelError(f"expected name:=value, got '{word}'")
        if name.startswith("_") and not name.startswith("__"):
            continue
        mappings[name] = value
    return mappings


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
