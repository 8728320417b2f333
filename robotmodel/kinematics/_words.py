"""Joint values written as words: ``NAME=VALUE`` (the ``--joint`` option of fk and view)."""

from __future__ import annotations

from collections.abc import Iterable

from robotmodel.errors import RobotModelError

__all__ = ["parse_joint_words"]


def parse_joint_words(words: Iterable[str]) -> dict[str, float]:
    """``--joint NAME=VALUE`` words to a dict, with one-line errors."""
    values: dict[str, float] = {}
    for word in words:
        name, sep, text = word.partition("=")
        if not sep or not name:
            raise RobotModelError(f"--joint expects NAME=VALUE, got '{word}'")
        try:
            values[name] = float(text)
        except ValueError:
            raise RobotModelError(f"--joint {name}: '{text}' is not a number") from None
    return values
