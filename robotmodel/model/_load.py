"""The one entry point from a file or text to a :class:`RobotDescription`."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import URDFError
from robotmodel.model._parse import parse_located, parse_urdf
from robotmodel.model._types import RobotDescription
from robotmodel.xacro import expand, expand_string

__all__ = ["load"]


def load(
    source: str | os.PathLike[str],
    args: Mapping[str, str] | None = None,
    *,
    package_paths: Sequence[str | os.PathLike[str]] = (),
    untrusted: bool = False,
) -> RobotDescription:
    """Load a robot from a ``.urdf``/``.xacro`` path, or from XML text (a str starting with ``<``).

    The document always goes through :func:`robotmodel.xacro.expand` (many ``.urdf``
    files are really xacro documents) with ``args`` (``name:=value`` mappings), then
    :func:`parse_urdf`. Relative includes in XML text resolve against the working
    directory. Raises :class:`robotmodel.errors.XacroError` if expansion fails and
    :class:`robotmodel.errors.URDFError` if the result is not a valid robot.
    """
    if isinstance(source, str) and source.lstrip("\ufeff \t\r\n").startswith("<"):
        text = expand_string(source, args, package_paths=package_paths, untrusted=untrusted)
        return parse_urdf(text)
    path = Path(source)
    if not path.is_file():
        what = "is a directory, not a URDF file" if path.is_dir() else "no such file"
        raise URDFError(f"{path}: {what}")
    text = expand(path, args, package_paths=package_paths, untrusted=untrusted)
    try:
        original = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        original = ""
    return parse_located(text, source=str(path), original=original)
