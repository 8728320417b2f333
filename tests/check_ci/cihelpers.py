"""Reading check-urdf's CI formats back, independently of how robotmodel writes them."""

from __future__ import annotations

import re
from typing import NamedTuple

# GitHub's workflow command syntax: ::LEVEL key=value,key=value::data
_COMMAND = re.compile(r"^::(error|warning|notice) ([^:]*)::(.*)$")


class Annotation(NamedTuple):
    level: str
    file: str
    line: int | None
    title: str
    message: str


_CODES = {"%0D": "\r", "%0A": "\n", "%3A": ":", "%2C": ",", "%25": "%"}


def _unescape(text: str) -> str:
    # One pass, left to right, as GitHub decodes: "%253A" is the text "%3A", not ":".
    return re.sub(r"%0D|%0A|%3A|%2C|%25", lambda m: _CODES[m.group(0)], text)


def parse_github(output: str) -> list[Annotation]:
    """Every workflow command line of ``output`` as (level, file, line, title, message)."""
    found = []
    for raw in output.splitlines():
        match = _COMMAND.match(raw)
        assert match is not None, f"not a workflow command: {raw!r}"
        props = {}
        for item in match.group(2).split(","):
            key, _, value = item.partition("=")
            props[key] = _unescape(value)
        line = props.get("line")
        found.append(Annotation(match.group(1), props["file"], int(line) if line else None, props.get("title", ""),
                                _unescape(match.group(3))))
    return found
