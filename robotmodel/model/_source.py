"""A command's robot source: a file path, or ``-`` for one XML document on stdin."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.model._load import load
from robotmodel.model._robot import RobotDescription
from robotmodel.xacro._stdin import read_stdin_document

__all__ = ["load_source", "read_stdin_document"]


def load_source(source: str | os.PathLike[str], args: Mapping[str, str] | None = None, *,
                package_paths: Sequence[str | os.PathLike[str]] = (),
                untrusted: bool = False) -> tuple[RobotDescription, Path]:
    """:func:`robotmodel.load` a path, or stdin for ``-``; returns the robot and the folder its paths start from.

    That folder is the file's, or the working directory for stdin (as check_urdf resolves them).
    """
    if str(source) == "-":
        return load(read_stdin_document(), args, package_paths=package_paths, untrusted=untrusted), Path.cwd()
    return load(source, args, package_paths=package_paths, untrusted=untrusted), Path(source).resolve().parent
