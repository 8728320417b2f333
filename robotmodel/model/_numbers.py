"""Numbers in URDF attributes, read as urdfdom reads them.

urdfdom parses with a C++ stream in the classic locale: leading C whitespace is skipped,
anything after the number (trailing whitespace included) rejects the value, and vector
components are separated by spaces only. Python's ``float`` is more lenient (``1_000``,
non-ASCII digits, surrounding whitespace), so every number goes through a pattern first.
"""

from __future__ import annotations

import math
import re

from robotmodel.errors import URDFParseError
from robotmodel.model._types import Vec3

__all__ = ["num", "shown", "vec", "vec3"]

# Python's float() also takes "1_000" and non-ASCII digits, which no C++ URDF parser does.
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|[+-]?(?:nan|inf|infinity)",
                     re.IGNORECASE | re.ASCII)
_C_SPACE = " \t\n\v\f\r"


def _float(text: str) -> float:
    number = text.lstrip(_C_SPACE)
    if not _NUMBER.fullmatch(number):
        raise ValueError(text)
    return float(number)


def shown(text: str) -> str:
    """``text`` for a one-line message: control characters escaped, as in a Python literal."""
    return "".join(c if c.isprintable() or c == " " else repr(c)[1:-1] for c in text)


def num(text: str, what: str) -> float:
    """One finite number; errors say ``what`` it was for."""
    try:
        value = _float(text)
    except ValueError:
        raise URDFParseError(f"{what}: unable to parse [{shown(text)}] as a number") from None
    if not math.isfinite(value):
        raise URDFParseError(f"{what}: value [{shown(text)}] is not a finite number")
    return value


def vec(text: str, n: int, what: str) -> tuple[float, ...]:
    """``n`` finite numbers separated by spaces; errors use urdfdom's sentences."""
    # As urdfdom: components are separated by spaces only (a tab or newline between two
    # numbers makes one malformed component), and each is parsed before the count is checked.
    parts = [part for part in text.split(" ") if part]
    values = []
    for part in parts:
        try:
            values.append(_float(part))
        except ValueError:
            raise URDFParseError(
                f"{what}: Unable to parse component [{shown(part)}] to a double (while parsing a vector value)"
            ) from None
    if len(parts) != n:
        raise URDFParseError(
            f"{what}: Parser found {len(parts)} elements but {n} expected while parsing vector [{shown(text)}]"
        )
    for part, value in zip(parts, values, strict=True):
        if not math.isfinite(value):
            raise URDFParseError(f"{what}: value [{shown(part)}] is not a finite number")
    return tuple(values)


def vec3(text: str, what: str) -> Vec3:
    """Three finite numbers (xyz, rpy, scale, size)."""
    x, y, z = vec(text, 3, what)
    return (x, y, z)
