"""The values a semantic diff of two robot descriptions is made of.

Numbers keep the units the report names: ``FieldChange.unit`` says which (``mm`` and
``deg`` for origins, the URDF's own ``m``, ``rad``, ``kg``... elsewhere), so the text and
JSON renderings show the same numbers.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeAlias

__all__ = [
    "DEFAULT_TOLERANCE",
    "DescriptionDiff",
    "ElementChange",
    "FieldChange",
    "Json",
    "PoseChange",
    "SectionDiff",
    "Side",
]

#: Two numbers are equal when ``|a - b| <= tolerance * max(1, |a|, |b|)``: 1e-9 m and 1e-9 rad
#: for lengths and angles below one metre or radian. Origins compare as rigid poses (translation
#: distance, rotation angle), so rpy triples naming the same rotation are equal.
DEFAULT_TOLERANCE = 1e-9

#: A JSON-ready value: what a field held on one side.
Json: TypeAlias = bool | int | float | str | list["Json"] | dict[str, "Json"] | None


@dataclass(frozen=True, slots=True)
class FieldChange:
    """One field that differs: ``field`` is a dotted path (``origin.xyz``, ``visual[0].geometry``).

    ``old``/``new`` are None where the field is absent on that side (a limit added, a
    collision removed). ``delta`` is a magnitude in ``delta_unit`` when one is meaningful:
    how far an origin moved (mm) or turned (deg).
    """

    field: str
    old: Json
    new: Json
    unit: str = ""
    delta: float | None = None
    delta_unit: str = ""


@dataclass(frozen=True, slots=True)
class ElementChange:
    """A link, joint or material present on both sides (under ``old_name`` and ``new_name``) that differs."""

    old_name: str
    new_name: str
    changes: tuple[FieldChange, ...]

    @property
    def renamed(self) -> bool:
        """Whether the element has a new name."""
        return self.old_name != self.new_name


@dataclass(frozen=True, slots=True)
class SectionDiff:
    """Links, joints or materials: which were added, removed, renamed and changed.

    ``added``/``removed`` hold one summary dict per element (name first); ``renamed`` is
    (old name, new name) pairs; ``changed`` the matched elements whose fields differ
    (renamed ones included when their fields differ too). Order: new document order,
    removed ones in old document order.
    """

    added: tuple[dict[str, Json], ...] = ()
    removed: tuple[dict[str, Json], ...] = ()
    renamed: tuple[tuple[str, str], ...] = ()
    changed: tuple[ElementChange, ...] = ()

    @property
    def empty(self) -> bool:
        """Whether nothing differs in this section."""
        return not (self.added or self.removed or self.renamed or self.changed)


@dataclass(frozen=True, slots=True)
class PoseChange:
    """How a link present on both sides moved at the zero configuration (T_root_link before → after).

    Poses are ``(x, y, z)`` in metres and ``(roll, pitch, yaw)`` in radians; the deltas are
    the distance between the two origins (mm) and the angle of the relative rotation (deg).
    """

    link: str
    old_link: str
    old_xyz: tuple[float, float, float]
    old_rpy: tuple[float, float, float]
    new_xyz: tuple[float, float, float]
    new_rpy: tuple[float, float, float]
    translation_mm: float
    rotation_deg: float


@dataclass(frozen=True, slots=True)
class Side:
    """One of the two descriptions compared: where it came from, its robot name and root link."""

    label: str
    robot: str
    root: str


@dataclass(frozen=True, slots=True)
class DescriptionDiff:
    """The semantic difference between two robot descriptions; ``equal`` when nothing differs."""

    old: Side
    new: Side
    tolerance: float
    robot: tuple[FieldChange, ...]
    links: SectionDiff
    joints: SectionDiff
    materials: SectionDiff
    poses: tuple[PoseChange, ...]

    @property
    def equal(self) -> bool:
        """Whether the two descriptions are the same within the tolerance."""
        return not self.robot and self.links.empty and self.joints.empty and self.materials.empty \
            and not self.poses
