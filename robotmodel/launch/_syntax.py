"""The syntax of substitutions: ``$(name arg ...)`` split into text and nested parts.

ROS 2 groups an argument with spaces in single (or double) quotes; ROS 1 has no quoting.
``$(eval ...)`` keeps its text raw up to the matching parenthesis.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from robotmodel.errors import LaunchError
from robotmodel.launch._model import Dialect

__all__ = ["Parts", "Sub", "SubstContext", "parse"]


@dataclass(frozen=True)
class Sub:
    """One ``$(name args)``: each argument a list of text and nested substitutions; ``raw`` for eval."""

    name: str
    args: tuple[tuple[str | Sub, ...], ...]
    raw: str


Parts = list["str | Sub"]


@dataclass
class SubstContext:
    """What substitutions see: the file, the line being read, the dialect and the arguments in scope.

    ``args`` maps names to values; None marks a ROS 1 arg declared without a value (an
    error only when used).
    """

    path: Path
    line: int
    dialect: Dialect
    args: Mapping[str, str | None]
    package_paths: Sequence[Path]
    # Every package a $(find) resolved, shared by the whole load: the viewer gets them, as it has
    # only the description's text and no file to find package:// URIs beside.
    found_packages: dict[Path, None] = field(default_factory=dict)

    def error(self, text: str) -> LaunchError:
        """A LaunchError starting with this file and line."""
        return LaunchError(f"{self.path}:{self.line}: {text}")


def parse(text: str, ctx: SubstContext) -> Parts:
    """Split ``text`` into literal text and substitutions; malformed syntax raises LaunchError."""
    try:
        parts, _ = _parse_text(text, 0, ctx, top=True)
    except RecursionError:
        raise ctx.error("substitutions nested too deep") from None
    return parts


def _parse_text(text: str, pos: int, ctx: SubstContext, *, top: bool) -> tuple[Parts, int]:
    parts: Parts = []
    buf: list[str] = []
    while pos < len(text):
        if text.startswith("$(", pos):
            if buf:
                parts.append("".join(buf))
                buf = []
            sub, pos = _parse_sub(text, pos, ctx)
            parts.append(sub)
            continue
        if not top:
            break
        buf.append(text[pos])
        pos += 1
    if buf:
        parts.append("".join(buf))
    return parts, pos


def _parse_sub(text: str, start: int, ctx: SubstContext) -> tuple[Sub, int]:
    pos = start + 2
    name_end = pos
    while name_end < len(text) and not text[name_end].isspace() and text[name_end] != ")":
        name_end += 1
    name = text[pos:name_end]
    if not name:
        raise ctx.error(f"empty substitution in '{text}'")
    raw_end = _matching_paren(text, name_end, ctx, text[start:])
    raw = text[name_end:raw_end].strip()
    if name == "eval":
        return Sub(name, (), raw), raw_end + 1
    args: list[tuple[str | Sub, ...]] = []
    pos = name_end
    quoting = ctx.dialect is Dialect.ROS2
    while True:
        while pos < raw_end and text[pos].isspace():
            pos += 1
        if pos >= raw_end:
            break
        arg: Parts = []
        buf: list[str] = []
        while pos < raw_end and not text[pos].isspace():
            ch = text[pos]
            if quoting and ch in "'\"":
                close = text.find(ch, pos + 1, raw_end)
                if close < 0:
                    raise ctx.error(f"unterminated quote in '{text[start:raw_end + 1]}'")
                inner = parse(text[pos + 1:close], ctx)
                if buf:
                    arg.append("".join(buf))
                    buf = []
                arg.extend(inner)
                pos = close + 1
            elif text.startswith("$(", pos):
                if buf:
                    arg.append("".join(buf))
                    buf = []
                sub, pos = _parse_sub(text, pos, ctx)
                arg.append(sub)
            else:
                buf.append(ch)
                pos += 1
        if buf:
            arg.append("".join(buf))
        args.append(tuple(arg))
    return Sub(name, tuple(args), raw), raw_end + 1


def _matching_paren(text: str, pos: int, ctx: SubstContext, shown: str) -> int:
    depth = 0
    quote = ""
    while pos < len(text):
        ch = text[pos]
        if quote:
            if ch == quote:
                quote = ""
        elif ch in "'\"" and ctx.dialect is Dialect.ROS2:
            quote = ch
        elif ch == "(":
            depth += 1
        elif ch == ")":
            if depth == 0:
                return pos
            depth -= 1
        pos += 1
    raise ctx.error(f"unterminated substitution '{shown}'")
