"""xacro's ``name:=value`` command-line words, split from the others as the ``xacro`` command splits them."""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["split_mappings", "take_mappings"]

REMAP = ":="


def take_mappings(words: Sequence[str]) -> tuple[dict[str, str], list[str]]:
    """Split xacro's ``name:=value`` words from the others, as the xacro command does.

    Any word containing ``:=`` is a mapping, wherever it stands. Surrounding blanks are
    stripped; a word with an empty name or value is dropped, and so is a ``_name`` key (a
    ROS parameter assignment). A word with two ``:=`` raises ValueError.
    """
    mappings: dict[str, str] = {}
    rest: list[str] = []
    for word in words:
        if REMAP not in word:
            rest.append(word)
            continue
        parts = [p.strip() for p in word.split(REMAP)]
        if len(parts) != 2:
            raise ValueError(f"invalid remapping argument '{word}'")
        name, value = parts
        if not name or not value or (len(name) > 1 and name[0] == "_" and name[1] != "_"):
            continue
        mappings[name] = value
    return mappings, rest


def split_mappings(words: Sequence[str]) -> dict[str, str]:
    """Parse ``name:=value`` words (see :func:`take_mappings`); a word without ``:=`` raises ValueError."""
    mappings, rest = take_mappings(words)
    if rest:
        raise ValueError(f"expected name:=value, got '{rest[0]}'")
    return mappings
