"""The diff as text for a code review: grouped by section, ``-`` removed, ``+`` added, ``~`` changed.

In a section: removed elements, added ones, renamed ones (with their changes), then changed
ones, each in document order; added and removed shapes of a link are ``+``/``-`` lines too.

Example::

    --- old/arm.urdf.xacro (robot 'arm', root 'world')
    +++ new/arm.urdf.xacro (robot 'arm', root 'world')
    joints: 1 changed
      ~ joint arm_elbow_joint
          origin.xyz: [0, 0, 400] → [0, 0, 425] mm (moved 25 mm)
          limit.upper: 2.5 → 2 rad
    link poses at the zero configuration (T_root_link, largest change first): 4 changed
      ~ link arm_fore_link: moved 25 mm, turned 0 deg
          xyz [0, 0, 550] → [0, 0, 575] mm, rpy [0, 0, 0] → [0, 0, 0] deg

Numbers are shown with up to 10 significant digits; JSON (``render_json``) has them in full.
Equal descriptions render as the empty string, as ``diff`` prints nothing.
"""

from __future__ import annotations

from robotmodel.diff._compare import DEGREES, in_units
from robotmodel.diff._types import DescriptionDiff, FieldChange, Json, SectionDiff, Side

__all__ = ["render_text"]

_INDENT = "      "


def _num(value: float) -> str:
    return f"{value:.10g}"


def _value(value: Json) -> str:
    """A JSON value of a report as words: numbers short, vectors in brackets, geometry by kind."""
    if value is None:
        return "none"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int | float):
        return _num(value)
    if isinstance(value, str):
        return value
    if isinstance(value, list):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    if "geometry" in value:
        words = _value(value["geometry"])
        origin = value.get("origin")
        if isinstance(origin, dict):
            words += f" at xyz {_value(origin.get('xyz_mm'))} mm, rpy {_value(origin.get('rpy_deg'))} deg"
        if "material" in value:
            words += f", material {_value(value['material'])}"
        if "name" in value:
            words += f", name {_value(value['name'])}"
        return words
    if "type" in value:
        return _geometry(value)
    return ", ".join(f"{k} {_value(v)}" for k, v in value.items())


def _geometry(value: dict[str, Json]) -> str:
    kind = value["type"]
    if kind == "box":
        return f"box {_value(value['size'])} m"
    if kind == "cylinder":
        return f"cylinder radius {_value(value['radius'])} m, length {_value(value['length'])} m"
    if kind == "sphere":
        return f"sphere radius {_value(value['radius'])} m"
    scale = "" if value.get("scale") == [1.0, 1.0, 1.0] else f" scale {_value(value.get('scale'))}"
    return f"mesh {_value(value.get('filename'))}{scale}"


def _change(change: FieldChange) -> str:
    if change.old is None and change.new is not None and change.field.endswith("]"):
        return f"+ {change.field}: {_value(change.new)}"
    if change.new is None and change.old is not None and change.field.endswith("]"):
        return f"- {change.field}: {_value(change.old)}"
    unit = f" {change.unit}" if change.unit else ""
    line = f"{change.field}: {_value(change.old)} → {_value(change.new)}{unit}"
    if change.delta is not None:
        how = "moved" if change.delta_unit == "mm" else "turned"
        line += f" ({how} {_num(change.delta)} {change.delta_unit})"
    return line


def _counts(section: SectionDiff) -> str:
    parts = [(len(section.added), "added"), (len(section.removed), "removed"),
             (len(section.renamed), "renamed"), (len(section.changed), "changed")]
    return ", ".join(f"{n} {what}" for n, what in parts if n)


def _section(kind: str, title: str, section: SectionDiff) -> list[str]:
    if section.empty:
        return []
    lines = [f"{title}: {_counts(section)}"]
    for summary in section.removed:
        lines.append(f"  - {kind} {_summary(summary)}")
    for summary in section.added:
        lines.append(f"  + {kind} {_summary(summary)}")
    changed = {c.new_name: c for c in section.changed}
    renamed = {new: old for old, new in section.renamed}
    # Renamed elements first (with their changes, if any), then the other changed ones; each group in
    # the new description's order.
    order = [new for _, new in section.renamed] + [c.new_name for c in section.changed]
    for new in sorted(set(order), key=order.index):
        old = renamed.get(new, changed[new].old_name if new in changed else new)
        name = f"{old} → {new} (renamed)" if old != new else new
        lines.append(f"  ~ {kind} {name}")
        if new in changed:
            lines.extend(_INDENT + _change(c) for c in changed[new].changes)
    return lines


def _summary(summary: dict[str, Json]) -> str:
    name = _value(summary.get("name"))
    if "type" in summary:  # a joint
        return f"{name} ({_value(summary['type'])}, {_value(summary['parent'])} → {_value(summary['child'])})"
    if "color" in summary:  # a material
        return f"{name} (color {_value(summary['color'])}, texture {_value(summary['texture'])})"
    return name


def _side(marker: str, side: Side) -> str:
    return f"{marker} {side.label} (robot '{side.robot}', root '{side.root}')"


def render_text(diff: DescriptionDiff) -> str:
    """The diff as review text (see the module documentation); empty when the descriptions are equal."""
    if diff.equal:
        return ""
    lines = [_side("---", diff.old), _side("+++", diff.new)]
    lines.extend(f"robot {_change(c)}" for c in diff.robot)
    lines += _section("link", "links", diff.links)
    lines += _section("joint", "joints", diff.joints)
    lines += _section("material", "materials", diff.materials)
    if diff.poses:
        lines.append(f"link poses at the zero configuration (T_root_link, largest change first): "
                     f"{len(diff.poses)} changed")
        for pose in diff.poses:
            name = pose.link if pose.link == pose.old_link else f"{pose.old_link} → {pose.link}"
            lines.append(f"  ~ link {name}: moved {_num(pose.translation_mm)} mm, "
                         f"turned {_num(pose.rotation_deg)} deg")
            xyz = [_value(in_units(xyz, 1000.0)) for xyz in (pose.old_xyz, pose.new_xyz)]
            rpy = [_value(in_units(rpy, DEGREES)) for rpy in (pose.old_rpy, pose.new_rpy)]
            lines.append(f"{_INDENT}xyz {xyz[0]} → {xyz[1]} mm, rpy {rpy[0]} → {rpy[1]} deg")
    return "\n".join(lines) + "\n"
