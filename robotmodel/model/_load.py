"""The one entry point from a file or text to a :class:`RobotDescription`."""

from __future__ import annotations

import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import URDFError
from robotmodel.model._parse import parse_urdf
from robotmodel.model._types import RobotDescription
from robotmodel.xacro import expand, expand_string

__all__ = ["load"]

# A document with none of these is plain URDF: xacro would only reformat it.
_XACRO_MARKERS = re.compile(r"xacro|\$\{|\$\(")


def load(
    source: str | os.PathLike[str],
    args: Mapping[str, str] | None = None,
    *,
    package_paths: Sequence[str | os.PathLike[str]] = (),
    untrusted: bool = False,
) -> RobotDescription:
    """Load a robot from a ``.urdf``/``.xacro`` path, or from XML text (a str starting with ``<``).

    Documents using xacro (including ``.urdf`` files that are really xacro) are expanded
    with ``args`` (``name:=value`` mappings) first; see :func:`robotmodel.xacro.expand`.
    """
    if isinstance(source, str) and source.lstrip().startswith("<"):
        text = source
        if args or _XACRO_MARKERS.search(text):
            text = expand_string(text, args, package_paths=package_paths, untrusted=untrusted)
        return parse_urdf(text)
    path = Path(source)
    try:
        raw = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise URDFError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise URDFError(f"{path}: cannot read: {exc}") from None
    text = raw
    if args or _XACRO_MARKERS.search(raw):
        text = expand(path, args, package_paths=package_paths, untrusted=untrusted)
    return parse_urdf(text, source=str(path))
