"""An independent reading of two URDF XML texts: which fields differ, in the diff report's field names,
and a check of a JSON report against it (and against yourdfpy's poses at q = 0)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

import pytest
from diff.pairs import pose_delta, zero_poses

MOVABLE_AXIS = {"revolute", "continuous", "prismatic", "planar"}


# An independent reading of the XML: which fields differ, by the report's field names.

def _floats(text: str | None, default: list[float]) -> list[float]:
    return default if text is None else [float(v) for v in text.split()]


def _differ(a: list[float], b: list[float]) -> bool:
    return len(a) != len(b) or any(not math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-9) for x, y in zip(a, b, strict=True))


def _origin(parent: ET.Element | None, prefix: str, other: ET.Element | None, out: set[str]) -> None:
    a = parent.find("origin") if parent is not None else None
    b = other.find("origin") if other is not None else None
    for key in ("xyz", "rpy"):
        va = _floats(a.get(key) if a is not None else None, [0.0] * 3)
        vb = _floats(b.get(key) if b is not None else None, [0.0] * 3)
        if _differ(va, vb):
            out.add(f"{prefix}.{key}")


def _attrs(a: ET.Element | None, b: ET.Element | None, prefix: str, keys: tuple[str, ...], out: set[str]) -> None:
    for key in keys:
        va = None if a is None else a.get(key)
        vb = None if b is None else b.get(key)
        if (va is None) != (vb is None) or (va is not None and _differ(_floats(va, []), _floats(vb, []))):
            out.add(f"{prefix}.{key}")


def _joint_fields(a: ET.Element, b: ET.Element) -> set[str]:
    out: set[str] = set()
    if a.get("type") != b.get("type"):
        out.add("type")
    for end in ("parent", "child"):
        if a.find(end).get("link") != b.find(end).get("link"):
            out.add(end)
    _origin(a, "origin", b, out)
    if a.get("type") in MOVABLE_AXIS and b.get("type") in MOVABLE_AXIS:
        axis_a, axis_b = a.find("axis"), b.find("axis")
        if _differ(_floats(axis_a.get("xyz") if axis_a is not None else None, [1.0, 0.0, 0.0]),
                   _floats(axis_b.get("xyz") if axis_b is not None else None, [1.0, 0.0, 0.0])):
            out.add("axis")
    _attrs(a.find("limit"), b.find("limit"), "limit", ("lower", "upper", "effort", "velocity"), out)
    _attrs(a.find("dynamics"), b.find("dynamics"), "dynamics", ("damping", "friction"), out)
    return out


def _geometry(a: ET.Element, b: ET.Element, prefix: str, out: set[str]) -> None:
    ga, gb = a.find("geometry")[0], b.find("geometry")[0]
    if ga.tag != gb.tag:
        out.add(f"{prefix}.geometry")
    elif ga.tag == "mesh":
        if ga.get("filename") != gb.get("filename"):
            out.add(f"{prefix}.geometry.filename")
        if _differ(_floats(ga.get("scale"), [1.0] * 3), _floats(gb.get("scale"), [1.0] * 3)):
            out.add(f"{prefix}.geometry.scale")
    else:
        _attrs(ga, gb, f"{prefix}.geometry", tuple(ga.attrib), out)


def _link_fields(a: ET.Element, b: ET.Element) -> set[str]:
    out: set[str] = set()
    ia, ib = a.find("inertial"), b.find("inertial")
    if (ia is None) != (ib is None):
        out.add("inertial")
    elif ia is not None:
        _attrs(ia.find("mass"), ib.find("mass"), "inertial", ("value",), out)
        out = {"inertial.mass" if f == "inertial.value" else f for f in out}
        _origin(ia, "inertial.origin", ib, out)
        _attrs(ia.find("inertia"), ib.find("inertia"), "inertial.inertia", ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"), out)
    for kind in ("visual", "collision"):
        la, lb = a.findall(kind), b.findall(kind)
        for i, (sa, sb) in enumerate(zip(la, lb, strict=False)):
            _geometry(sa, sb, f"{kind}[{i}]", out)
            _origin(sa, f"{kind}[{i}].origin", sb, out)
            ma, mb = sa.find("material"), sb.find("material")
            names = (None if ma is None else ma.get("name"), None if mb is None else mb.get("name"))
            if kind == "visual" and names[0] != names[1]:
                out.add(f"{kind}[{i}].material")
        out |= {f"{kind}[{i}]" for i in range(min(len(la), len(lb)), max(len(la), len(lb)))}
    return out


def _by_name(root: ET.Element, tag: str) -> dict[str, ET.Element]:
    return {e.get("name"): e for e in root.findall(tag)}


def _renamed(root: ET.Element, rename: Callable[[str], str]) -> None:
    for element in [*root.findall("link"), *root.findall("joint")]:
        element.set("name", rename(element.get("name")))
    for joint in root.findall("joint"):
        for end in ("parent", "child"):
            joint.find(end).set("link", rename(joint.find(end).get("link")))
        mimic = joint.find("mimic")
        if mimic is not None:
            mimic.set("joint", rename(mimic.get("joint")))


def _where_present(rename: Callable[[str], str], new: ET.Element) -> Callable[[str], str]:
    """``rename``, where the new name exists in ``new`` (a prefix leaves a link it does not own alone)."""
    present = {e.get("name") for tag in ("link", "joint") for e in new.findall(tag)}
    return lambda name: rename(name) if rename(name) in present else name


def expected(old_text: str, new_text: str, rename: Callable[[str], str] = str) -> dict[str, Any]:
    """Per tag: added/removed names, renamed (old, new) pairs, and {new name: changed fields}."""
    a, b = ET.fromstring(old_text), ET.fromstring(new_text)
    names = {tag: [e.get("name") for e in a.findall(tag)] for tag in ("link", "joint")}
    rename = _where_present(rename, b)
    _renamed(a, rename)
    out: dict[str, Any] = {}
    for tag, fields in (("link", _link_fields), ("joint", _joint_fields)):
        ea, eb = _by_name(a, tag), _by_name(b, tag)
        out[tag] = {
            "added": sorted(set(eb) - set(ea)), "removed": sorted(set(ea) - set(eb)),
            "renamed": sorted((n, rename(n)) for n in names[tag] if rename(n) != n and rename(n) in eb),
            "changed": {n: f for n in ea if n in eb for f in [fields(ea[n], eb[n])] if f},
        }
    ma, mb = _by_name(a, "material"), _by_name(b, "material")
    out["material"] = {"added": sorted(set(mb) - set(ma)), "removed": sorted(set(ma) - set(mb))}
    return out


def check_report(report: dict[str, Any], old_text: str, new_text: str, rename: Callable[[str], str] = str) -> None:
    """Assert a JSON report lists exactly what the XML comparison finds, and yourdfpy's pose changes."""
    want = expected(old_text, new_text, rename)
    robots = ET.fromstring(old_text).get("name"), ET.fromstring(new_text).get("name")
    assert [(c["field"], c["old"], c["new"]) for c in report["robot"]] == (
        [] if robots[0] == robots[1] else [("name", *robots)])
    for tag, section in (("link", "links"), ("joint", "joints")):
        got = report[section]
        assert sorted(x["name"] for x in got["added"]) == want[tag]["added"], section
        assert sorted(x["name"] for x in got["removed"]) == want[tag]["removed"], section
        assert sorted((r["old"], r["new"]) for r in got["renamed"]) == want[tag]["renamed"], section
        assert {c["new"]: {x["field"] for x in c["changes"]} for c in got["changed"]} == want[tag]["changed"]
    assert sorted(x["name"] for x in report["materials"]["added"]) == want["material"]["added"]
    assert sorted(x["name"] for x in report["materials"]["removed"]) == want["material"]["removed"]

    rename = _where_present(rename, ET.fromstring(new_text))
    before, after = zero_poses(old_text), zero_poses(new_text)
    moved = {}
    for link in before:
        if rename(link) in after:
            mm, deg = pose_delta(before[link], after[rename(link)])
            if mm > 1e-6 or deg > 1e-6:
                moved[rename(link)] = (mm, deg)
    assert {p["link"] for p in report["poses"]} == set(moved)
    for pose in report["poses"]:
        assert (pose["translation_mm"], pose["rotation_deg"]) == pytest.approx(moved[pose["link"]], abs=1e-6)
