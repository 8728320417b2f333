"""The semantic diff of two robot descriptions: match, compare every pair, and the pose changes."""

from __future__ import annotations

from collections.abc import Mapping

from robotmodel.diff._elements import compare_joint, compare_link, compare_material, joint_json, material_json
from robotmodel.diff._match import match
from robotmodel.diff._poses import pose_changes
from robotmodel.diff._types import (
    DEFAULT_TOLERANCE,
    DescriptionDiff,
    ElementChange,
    FieldChange,
    Json,
    SectionDiff,
    Side,
)
from robotmodel.model import RobotDescription

__all__ = ["diff_descriptions"]

Summaries = Mapping[str, dict[str, Json]]


def _section(
    old_names: list[str], new_names: list[str], pairs: dict[str, str],
    changes: dict[str, tuple[FieldChange, ...]], summaries: tuple[Summaries, Summaries],
) -> SectionDiff:
    back = {new: old for old, new in pairs.items()}
    return SectionDiff(
        added=tuple(summaries[1][n] for n in new_names if n not in back),
        removed=tuple(summaries[0][n] for n in old_names if n not in pairs),
        renamed=tuple((back[n], n) for n in new_names if n in back and back[n] != n),
        changed=tuple(ElementChange(back[n], n, changes[back[n]]) for n in new_names
                      if n in back and changes[back[n]]),
    )


def diff_descriptions(
    old: RobotDescription, new: RobotDescription, *, tolerance: float = DEFAULT_TOLERANCE,
    old_label: str | None = None, new_label: str | None = None,
) -> DescriptionDiff:
    """Compare two robot descriptions, ``old`` before and ``new`` after a change.

    Reports links, joints and materials added, removed, renamed and changed, and how every
    link present in both moved at the zero configuration.

    Renames are found from the tree (see :mod:`robotmodel.diff._match`); numbers are equal
    within ``tolerance`` (see :data:`DEFAULT_TOLERANCE`). ``old_label``/``new_label`` name
    the two sides in reports (default: each description's ``source``, else its robot name).
    """
    pairs = match(old, new, tolerance)
    named = ({m.name: m for m in old.materials}, {m.name: m for m in new.materials})
    link_changes = {o: compare_link(old.link(o), new.link(n), tolerance, named) for o, n in pairs.links.items()}
    joint_changes = {o: compare_joint(old.joint(o), new.joint(n), tolerance, pairs.links, pairs.joints)
                     for o, n in pairs.joints.items()}
    material_pairs = {name: name for name in named[0] if name in named[1]}
    material_changes = {n: compare_material(named[0][n], named[1][n], tolerance) for n in material_pairs}
    robot = () if old.name == new.name else (FieldChange("name", old.name, new.name),)
    return DescriptionDiff(
        old=Side(old_label or old.source or old.name, old.name, old.root),
        new=Side(new_label or new.source or new.name, new.name, new.root),
        tolerance=tolerance,
        robot=robot,
        links=_section([x.name for x in old.links], [x.name for x in new.links], pairs.links, link_changes,
                       ({x.name: {"name": x.name} for x in old.links}, {x.name: {"name": x.name} for x in new.links})),
        joints=_section([x.name for x in old.joints], [x.name for x in new.joints], pairs.joints, joint_changes,
                        ({x.name: joint_json(x) for x in old.joints}, {x.name: joint_json(x) for x in new.joints})),
        materials=_section(list(named[0]), list(named[1]), material_pairs, material_changes,
                           ({k: material_json(v) for k, v in named[0].items()},
                            {k: material_json(v) for k, v in named[1].items()})),
        poses=pose_changes(old, new, pairs.links, tolerance),
    )
