"""Launch XML read into a small tree that remembers each element's line (for FILE:LINE errors)."""

from __future__ import annotations

import xml.parsers.expat
from dataclasses import dataclass, field
from pathlib import Path

from robotmodel.errors import LaunchError

__all__ = ["Element", "parse_file", "where"]


@dataclass
class Element:
    """One XML element: tag, attributes in document order, children, text and its line (1-based)."""

    tag: str
    attrib: dict[str, str]
    line: int
    children: list[Element] = field(default_factory=list)
    text: str = ""


def where(path: Path, line: int) -> str:
    """``FILE:LINE`` as the errors write it."""
    return f"{path}:{line}"


def parse_file(path: Path) -> Element:
    """Parse ``path``; unreadable or malformed XML raises LaunchError naming the file and line."""
    if path.name.endswith((".py", ".yaml", ".yml")):
        raise LaunchError(f"{path}: not an XML launch file (.launch, .launch.xml, .xml): Python and YAML launch "
                          "files are read on their own or from a Python launch file")
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise LaunchError(f"{path}: cannot read launch file: {exc.strerror or exc}") from None
    parser = xml.parsers.expat.ParserCreate()
    stack: list[Element] = []
    roots: list[Element] = []

    def start(tag: str, attrs: dict[str, str]) -> None:
        elem = Element(tag, dict(attrs), parser.CurrentLineNumber)
        (stack[-1].children if stack else roots).append(elem)
        stack.append(elem)

    def end(tag: str) -> None:
        del tag
        stack.pop()

    def chars(text: str) -> None:
        if stack:
            stack[-1].text += text

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as exc:
        reason = xml.parsers.expat.ErrorString(exc.code) if exc.code is not None else str(exc)
        raise LaunchError(f"{where(path, exc.lineno)}: invalid XML: {reason} (column {exc.offset + 1})") from None
    if not roots:
        raise LaunchError(f"{where(path, 1)}: invalid XML: no element found")
    root = roots[0]
    if root.tag != "launch":
        raise LaunchError(f"{where(path, root.line)}: the root element is <{root.tag}>, expected <launch>")
    return root
