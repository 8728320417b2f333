"""Find the line of the element an error message names, in the text the user wrote."""

from __future__ import annotations

import re

__all__ = ["locate"]

# (pattern in our messages, element tag, which occurrence: 0 = first, 1 = the duplicate)
_NAMED = (
    (re.compile(r"\b(joint|link|material) '([^']+)' is not unique"), 1),
    (re.compile(r"\b[Jj](oint) \[([^\]]+)\]"), 0),
    (re.compile(r"\b(link) \[([^\]]+)\]"), 0),
)


def locate(text: str, message: str) -> int | None:
    """The 1-based line in ``text`` of the element ``message`` names, when it can be found.

    Names made by xacro (``${prefix}base``) are not in the source text; then None.
    """
    for pattern, occurrence in _NAMED:
        match = pattern.search(message)
        if match is None:
            continue
        tag = "joint" if match.group(1) == "oint" else match.group(1)
        element = re.compile(rf"<{tag}\b[^>]*?\bname\s*=\s*[\"']{re.escape(match.group(2))}[\"']")
        hits = list(element.finditer(text))
        if len(hits) > occurrence:
            return text.count("\n", 0, hits[occurrence].start()) + 1
        return None
    return None
