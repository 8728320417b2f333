"""The one entry point from a file or text to a :class:`RobotDescription` (``robotmodel.load``).

It composes the two steps at the top: xacro expansion (only for documents that are xacro)
and URDF parsing. The plain-URDF rule, as check_urdf reads files:

- a document with a ``xacro:`` element or attribute (``<xacro:include>``,
  ``xacro:targetNamespace=``; the ``xmlns:xacro`` declaration alone does not count, as
  ROS 1 xacro left it in its output) is xacro;
- else a document holding ``$(`` or ``${`` is xacro, except a file named ``*.urdf`` that
  does not declare the xacro namespace: there they stay literal, as urdfdom leaves them;
- else it is URDF.

A URDF document is parsed directly: no xacro child process, no xacro import.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.errors import URDFError, URDFParseError
from robotmodel.model._parse import parse_located, parse_urdf
from robotmodel.model._robot import RobotDescription

__all__ = ["is_xacro", "load"]

_XACRO_TAG = re.compile(r"<xacro:|\sxacro:[\w.-]+\s*=")
_XACRO_DECLARED = re.compile(r"\sxmlns:xacro\s*=")


def is_xacro(text: str, filename: str | os.PathLike[str] | None = None) -> bool:
    """Whether :func:`load` expands ``text`` (named ``filename``, if a file) with xacro; see the module rule."""
    if _XACRO_TAG.search(text):
        return True
    if "$(" not in text and "${" not in text:
        return False
    plain_file = filename is not None and os.fspath(filename).endswith(".urdf")
    return not plain_file or _XACRO_DECLARED.search(text) is not None


def _markers(data: bytes) -> str:
    """Text good enough to look for the ASCII markers of :func:`is_xacro` in file bytes."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return data.decode("utf-16", errors="replace")
    return data.decode("latin-1")


def load(
    source: str | os.PathLike[str],
    args: Mapping[str, str] | None = None,
    *,
    package_paths: Sequence[str | os.PathLike[str]] = (),
    untrusted: bool = False,
) -> RobotDescription:
    """Load a robot from a ``.urdf``/``.xacro`` path, or from XML text (a str starting with ``<``).

    A xacro document (see the module's plain-URDF rule) goes through
    :func:`robotmodel.xacro.expand` with ``args`` (``name:=value`` mappings), then
    :func:`parse_urdf`; a URDF document is parsed directly and ``args`` are unused.
    Relative includes in XML text resolve against the working directory. Raises
    :class:`robotmodel.errors.XacroError` if expansion fails and
    :class:`robotmodel.errors.URDFError` if the result is not a valid robot.
    """
    if isinstance(source, str) and source.lstrip("\ufeff \t\r\n").startswith("<"):
        if not is_xacro(source):
            return parse_urdf(source)
        from robotmodel.xacro import expand_string

        text = expand_string(source, args, package_paths=package_paths, untrusted=untrusted)
        return parse_urdf(text)
    path = Path(source)
    if path.is_dir():
        raise URDFError(f"{path}: is a directory, not a URDF file")
    if not path.exists():
        raise URDFError(f"{path}: no such file")
    try:
        # Not only regular files: /dev/null, /dev/stdin and a shell's <(...) pipe are read too.
        data = path.read_bytes()
    except OSError as exc:
        raise URDFError(f"{path}: cannot read: {exc.strerror}") from None
    if not data.strip(b"\xef\xbb\xbf \t\r\n"):
        # urdfdom's check_urdf: "Error=XML_ERROR_EMPTY_DOCUMENT", then "Model Parsing the xml failed".
        raise URDFParseError(f"{path}: empty file: no XML document (XML_ERROR_EMPTY_DOCUMENT)")
    if not is_xacro(_markers(data), path.name):
        return parse_urdf(data, source=str(path))
    if not path.is_file():  # a pipe cannot be read twice: expand the text read
        from robotmodel.xacro import expand_string

        return parse_urdf(expand_string(data.decode("utf-8", errors="replace"), args, package_paths=package_paths,
                                        untrusted=untrusted, name=str(path)), source=str(path))
    from robotmodel.xacro import expand

    text = expand(path, args, package_paths=package_paths, untrusted=untrusted)
    try:
        original = data.decode("utf-8")
    except UnicodeDecodeError:
        original = ""
    return parse_located(text, source=str(path), original=original)
