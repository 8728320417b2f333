"""Field-by-field comparison with one tolerance: numbers, vectors, names and rigid poses.

Origins are compared as poses, not as six numbers: the distance between the two
translations and the angle of the relative rotation, so two rpy triples naming one
rotation are equal, and a change is reported with how far it moved (mm) and turned (deg).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from robotmodel.diff._types import FieldChange, Json
from robotmodel.model import Pose
from robotmodel.spatial import FloatArray, rpy_to_matrix

__all__ = ["DEGREES", "Fields", "close", "in_units", "rotation_angle", "scaled"]

#: Degrees per radian.
DEGREES = 180.0 / math.pi
_DIGITS = 9  # rounding of values shown in mm/deg: 1e-12 m, far below any tolerance worth asking for


def close(a: float | None, b: float | None, tolerance: float) -> bool:
    """Whether two numbers are equal within ``tolerance`` (relative above 1, absolute below); None only equals None."""
    if a is None or b is None:
        return a is b
    if a == b:  # also infinities
        return True
    return abs(a - b) <= tolerance * max(1.0, abs(a), abs(b))


def scaled(value: float, scale: float) -> float:
    """``value`` times ``scale`` (1000 for mm, :data:`DEGREES` for degrees), rounded, never ``-0.0``."""
    return round(value * scale, _DIGITS) + 0.0


def in_units(values: Sequence[float], scale: float) -> list[Json]:
    """:func:`scaled` of each of ``values``, as a JSON list."""
    return [scaled(v, scale) for v in values]


def rotation_angle(a: FloatArray, b: FloatArray) -> float:
    """Angle (rad) of the rotation taking ``a`` to ``b``, accurate for tiny angles.

    ``||a - b||_F = 2·√2·sin(θ/2)`` for rotation matrices, which unlike ``acos`` of the
    trace keeps its precision near zero.
    """
    norm = float(np.linalg.norm(np.asarray(a) - np.asarray(b)))
    return 2.0 * math.asin(min(1.0, norm / (2.0 * math.sqrt(2.0))))


class Fields:
    """Collects the :class:`FieldChange` of one element, with one tolerance."""

    def __init__(self, tolerance: float) -> None:
        self.tolerance = tolerance
        self.changes: list[FieldChange] = []

    def add(self, change: FieldChange) -> None:
        """Record a change found elsewhere (a presence, a whole geometry)."""
        self.changes.append(change)

    def text(self, field: str, old: str | None, new: str | None) -> None:
        """Compare names, URIs and type spellings exactly."""
        if old != new:
            self.changes.append(FieldChange(field, old, new))

    def number(self, field: str, old: float | None, new: float | None, unit: str = "") -> None:
        """Compare two numbers (either may be None: absent)."""
        if not close(old, new, self.tolerance):
            self.changes.append(FieldChange(field, old, new, unit))

    def vector(self, field: str, old: Sequence[float] | None, new: Sequence[float] | None, unit: str = "") -> None:
        """Compare two vectors element-wise (either may be None: absent)."""
        if old is None or new is None:
            if old is not new:
                self.changes.append(FieldChange(field, _list(old), _list(new), unit))
            return
        if len(old) != len(new) or not all(close(a, b, self.tolerance) for a, b in zip(old, new, strict=True)):
            self.changes.append(FieldChange(field, list(old), list(new), unit))

    def pose(self, field: str, old: Pose, new: Pose) -> None:
        """Compare two origins as rigid poses; report ``.xyz`` in mm and ``.rpy`` in degrees with their deltas."""
        moved = math.dist(old.xyz, new.xyz)
        if moved > self.tolerance * max(1.0, math.hypot(*old.xyz), math.hypot(*new.xyz)):
            self.changes.append(FieldChange(f"{field}.xyz", in_units(old.xyz, 1000.0), in_units(new.xyz, 1000.0),
                                            "mm", scaled(moved, 1000.0), "mm"))
        turned = rotation_angle(rpy_to_matrix(old.rpy), rpy_to_matrix(new.rpy))
        if turned > self.tolerance:
            self.changes.append(FieldChange(f"{field}.rpy", in_units(old.rpy, DEGREES), in_units(new.rpy, DEGREES),
                                            "deg", scaled(turned, DEGREES), "deg"))


def _list(values: Sequence[float] | None) -> Json:
    return None if values is None else list(values)
