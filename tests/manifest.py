"""Rows of the corpus's MANIFEST.md: its entry points and their verified results."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Entry:
    number: str
    path: str
    args: dict[str, str]
    root_line: str
    links: int
    joints: int
    robot: str
    plain: bool


@dataclass(frozen=True)
class Negative:
    path: str
    args: dict[str, str]
    xacro_fails: bool
    message: str


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|").split("|")]


def _args(cell: str) -> dict[str, str]:
    if cell.startswith("(none)"):
        return {}
    pairs = re.findall(r"`([^`]+)`", cell)
    return dict(p.split(":=", 1) for p in pairs)


def _section(text: str, heading: str) -> list[str]:
    start = text.index(heading)
    end = text.find("\n## ", start + len(heading))
    return text[start : end if end != -1 else len(text)].splitlines()


def entries(corpus: Path) -> list[Entry]:
    """Positive entry points (55 xacro expansions and 12 plain URDFs)."""
    text = (corpus / "MANIFEST.md").read_text(encoding="utf-8")
    rows = []
    for line in _section(text, "## Entry points and verification results"):
        cells = _cells(line)
        if len(cells) < 13 or not cells[0].isdigit():
            continue
        rows.append(Entry(
            number=cells[0], path=cells[1].strip("`"), args=_args(cells[2]),
            root_line=cells[7].strip("`"), links=int(cells[8]), joints=int(cells[9]),
            robot=cells[11], plain="plain URDF" in cells[5],
        ))
    return rows


def negatives(corpus: Path) -> list[Negative]:
    """Expected failures: at xacro time or at check time, with upstream's message."""
    text = (corpus / "MANIFEST.md").read_text(encoding="utf-8")
    rows = []
    for line in _section(text, "## Expected-failure cases"):
        cells = _cells(line)
        if len(cells) < 7 or not cells[0].startswith("`"):
            continue
        xacro_fails = cells[2].startswith("ERROR")
        raw = cells[2] if xacro_fails else cells[3]
        message = raw.split("`")[1].strip() if "`" in raw else raw
        rows.append(Negative(cells[0].strip("`"), _args(cells[1]), xacro_fails, message))
    return rows
