"""The diff as JSON for scripts: every key always present, lists in a fixed order (see :func:`diff_json`)."""

from __future__ import annotations

import json

from robotmodel.diff._types import DescriptionDiff, FieldChange, Json, PoseChange, SectionDiff, Side

__all__ = ["diff_json", "render_json"]


def _change(change: FieldChange) -> dict[str, Json]:
    return {"field": change.field, "old": change.old, "new": change.new, "unit": change.unit,
            "delta": change.delta, "delta_unit": change.delta_unit}


def _section(section: SectionDiff) -> dict[str, Json]:
    return {
        "added": list(section.added),
        "removed": list(section.removed),
        "renamed": [{"old": old, "new": new} for old, new in section.renamed],
        "changed": [{"old": c.old_name, "new": c.new_name, "changes": [_change(x) for x in c.changes]}
                    for c in section.changed],
    }


def _side(side: Side) -> dict[str, Json]:
    return {"source": side.label, "robot": side.robot, "root": side.root}


def _pose(pose: PoseChange) -> dict[str, Json]:
    return {
        "link": pose.link, "old_link": pose.old_link,
        "translation_mm": pose.translation_mm, "rotation_deg": pose.rotation_deg,
        "old": {"xyz": list(pose.old_xyz), "rpy": list(pose.old_rpy)},
        "new": {"xyz": list(pose.new_xyz), "rpy": list(pose.new_rpy)},
    }


def diff_json(diff: DescriptionDiff) -> dict[str, Json]:
    """The diff as a JSON-ready dict: every key always present, lists in a fixed order.

    Shape::

        {"equal": bool, "tolerance": float,
         "old": {"source", "robot", "root"}, "new": {...},
         "robot": [change...],                       # the robot's name, when it changed
         "links" | "joints" | "materials": {
             "added": [summary...], "removed": [summary...],
             "renamed": [{"old", "new"}...],
             "changed": [{"old", "new", "changes": [change...]}...]},
         "poses": [{"link", "old_link", "translation_mm", "rotation_deg",
                    "old": {"xyz", "rpy"}, "new": {"xyz", "rpy"}}...]}

    A change is ``{"field", "old", "new", "unit", "delta", "delta_unit"}`` (``old``/``new``
    null where absent, ``delta`` null when no magnitude applies). Summaries: links
    ``{"name"}``, joints ``{"name", "type", "parent", "child"}``, materials
    ``{"name", "color", "texture"}``. Pose ``xyz`` is in metres and ``rpy`` in radians, as
    ``robotmodel fk --format json`` gives them.
    """
    return {
        "equal": diff.equal,
        "tolerance": diff.tolerance,
        "old": _side(diff.old),
        "new": _side(diff.new),
        "robot": [_change(c) for c in diff.robot],
        "links": _section(diff.links),
        "joints": _section(diff.joints),
        "materials": _section(diff.materials),
        "poses": [_pose(p) for p in diff.poses],
    }


def render_json(diff: DescriptionDiff) -> str:
    """The diff as indented JSON text, ending in a newline."""
    return json.dumps(diff_json(diff), indent=2, ensure_ascii=False) + "\n"
