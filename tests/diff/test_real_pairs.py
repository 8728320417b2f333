"""robotmodel diff on real pairs of example-robot-data that differ (two Pandas, two UR5s, Solo and Solo-12,
...): the report must list exactly the differences an independent comparison of the two XML files finds,
and the pose changes yourdfpy computes."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest
from conftest import ERD_ROBOTS
from diff.pairs import (
    PANDA,
    PANDA_COLLISION,
    PENDULUM,
    PENDULUM_CONTINUOUS,
    UR5,
    UR5_LIMITED,
    pose_delta,
    run_json,
    zero_poses,
)

PAIRS = {
    "panda-collision": (PANDA, PANDA_COLLISION),
    "ur5-joint-limited": (UR5, UR5_LIMITED),
    "double-pendulum-continuous": (PENDULUM, PENDULUM_CONTINUOUS),
    "solo-solo12": (ERD_ROBOTS / "solo_description/robots/solo.urdf", ERD_ROBOTS / "solo_description/robots/solo12.urdf"),
    "iris-simple": (ERD_ROBOTS / "iris_description/robots/iris.urdf", ERD_ROBOTS / "iris_description/robots/iris_simple.urdf"),
    "talos-corrected": (ERD_ROBOTS / "talos_data/robots/talos_reduced.urdf",
                        ERD_ROBOTS / "talos_data/robots/talos_reduced_corrected.urdf"),
    "talos-box": (ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf",
                  ERD_ROBOTS / "talos_data/robots/talos_full_v2_box.urdf"),
}
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


def _expected(old: Path, new: Path) -> dict[str, Any]:
    a, b = ET.parse(old).getroot(), ET.parse(new).getroot()
    out: dict[str, Any] = {}
    for tag, fields in (("link", _link_fields), ("joint", _joint_fields)):
        ea, eb = _by_name(a, tag), _by_name(b, tag)
        out[tag] = {
            "added": sorted(set(eb) - set(ea)), "removed": sorted(set(ea) - set(eb)),
            "changed": {n: f for n in ea if n in eb for f in [fields(ea[n], eb[n])] if f},
        }
    ma, mb = _by_name(a, "material"), _by_name(b, "material")
    out["material"] = {"added": sorted(set(mb) - set(ma)), "removed": sorted(set(ma) - set(mb))}
    return out


@pytest.mark.parametrize("pair", PAIRS, ids=list(PAIRS))
def test_real_pair_reports_exactly_the_xml_differences(tmp_path: Path, pair: str) -> None:
    old, new = PAIRS[pair]
    expected = _expected(old, new)
    code, report = run_json(str(old), str(new), cwd=tmp_path)
    assert code == 1
    assert report["robot"] == []
    for tag, section in (("link", "links"), ("joint", "joints")):
        got = report[section]
        assert sorted(x["name"] for x in got["added"]) == expected[tag]["added"]
        assert sorted(x["name"] for x in got["removed"]) == expected[tag]["removed"]
        assert got["renamed"] == []
        assert {c["new"]: {x["field"] for x in c["changes"]} for c in got["changed"]} == expected[tag]["changed"]
    assert sorted(x["name"] for x in report["materials"]["added"]) == expected["material"]["added"]
    assert sorted(x["name"] for x in report["materials"]["removed"]) == expected["material"]["removed"]

    before, after = zero_poses(old.read_text()), zero_poses(new.read_text())
    moved = {}
    for link in set(before) & set(after):
        mm, deg = pose_delta(before[link], after[link])
        if mm > 1e-6 or deg > 1e-6:
            moved[link] = (mm, deg)
    assert {p["link"] for p in report["poses"]} == set(moved)
    for pose in report["poses"]:
        assert (pose["translation_mm"], pose["rotation_deg"]) == pytest.approx(moved[pose["link"]], abs=1e-6)


def test_known_differences_in_words(tmp_path: Path) -> None:
    """The two example-robot-data Pandas differ in collision geometry only: meshes became primitives."""
    code, report = run_json(str(PANDA), str(PANDA_COLLISION), cwd=tmp_path)
    assert code == 1
    assert report["joints"]["changed"] == [] and report["poses"] == []
    link0 = {c["field"]: c for c in next(x for x in report["links"]["changed"] if x["new"] == "panda_link0")["changes"]}
    assert link0["collision[0].geometry"]["old"] == {
        "type": "mesh", "filename": "package://example-robot-data/robots/panda_description/meshes/collision/link0.stl",
        "scale": [1.0, 1.0, 1.0]}
    assert link0["collision[0].geometry"]["new"] == {"type": "cylinder", "radius": 0.09, "length": 0.03}
    assert link0["collision[0].origin.xyz"]["new"] == [-75.0, 0.0, 60.0]
    assert link0["collision[0].origin.rpy"]["new"] == pytest.approx([0.0, 90.0, 0.0])
    assert link0["collision[1]"]["old"] is None
    assert link0["collision[1]"]["new"]["geometry"] == {"type": "sphere", "radius": 0.09}
    # UR5 against its joint-limited variant: ±2π became ±π on five joints (the elbow keeps ±π).
    code, report = run_json(str(UR5), str(UR5_LIMITED), cwd=tmp_path)
    limits = {c["new"]: {x["field"]: (x["old"], x["new"]) for x in c["changes"]} for c in report["joints"]["changed"]}
    assert set(limits) == {"shoulder_pan_joint", "shoulder_lift_joint", "wrist_1_joint", "wrist_2_joint",
                           "wrist_3_joint"}
    for fields in limits.values():
        assert fields == {"limit.lower": (-6.28318530718, -3.14159265359), "limit.upper": (6.28318530718, 3.14159265359)}
