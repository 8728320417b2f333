"""Euler axis sequences: the 24 names (``'sxyz'``, ``'rzyx'``, ...) and their tuple encodings.

A name is ``s`` (static, extrinsic: each rotation about a fixed world axis) or ``r``
(rotating, intrinsic: about the axes as already turned), then three axis letters. The
tuple encoding of ROS 1's transformations module is (inner axis, parity, repetition,
frame): a rotating sequence is the static one with its letters reversed, so ``'rzyx'`` and
``'sxyz'`` share (0, 0, 0) and differ in the frame bit.
"""

from __future__ import annotations

from typing import NamedTuple

__all__ = ["AXES", "Sequence3", "parse_axes"]

_LETTERS = "xyz"


class Sequence3(NamedTuple):
    """The static form of an axis sequence: axis indices, applied first to last, and whether it was rotating."""

    first: int
    second: int
    third: int
    rotating: bool


def _encode(name: str) -> tuple[int, int, int, int]:
    letters = name[1:] if name[0] == "s" else name[:0:-1]
    a, b, c = (_LETTERS.index(ch) for ch in letters)
    parity = 0 if b == (a + 1) % 3 else 1
    return a, parity, int(a == c), int(name[0] == "r")


def _names() -> dict[str, tuple[int, int, int, int]]:
    found: dict[str, tuple[int, int, int, int]] = {}
    for frame in "sr":
        for a in _LETTERS:
            for b in _LETTERS:
                for c in _LETTERS:
                    if b not in (a, c):
                        name = frame + a + b + c
                        found[name] = _encode(name)
    return found


#: Every axis sequence name with its tuple encoding (24 of each).
AXES: dict[str, tuple[int, int, int, int]] = _names()
_BY_TUPLE = {code: name for name, code in AXES.items()}


def parse_axes(axes: str | tuple[int, int, int, int]) -> Sequence3:
    """The static sequence an axes name or tuple stands for; ValueError names an unknown one."""
    if isinstance(axes, str):
        key = axes.lower()
        if key not in AXES:
            raise ValueError(f"unknown Euler axes '{axes}' (expected one of {', '.join(AXES)})")
        name = key
    else:
        code = tuple(int(v) for v in axes)
        if code not in _BY_TUPLE:
            raise ValueError(f"unknown Euler axes tuple {axes!r}")
        name = _BY_TUPLE[code]
    letters = name[1:] if name[0] == "s" else name[:0:-1]
    first, second, third = (_LETTERS.index(ch) for ch in letters)
    return Sequence3(first, second, third, name[0] == "r")
