"""robotmodel diff on pairs made here from real robots: each edit's expected report is derived in the test
(from the edit itself, the XML tree, and yourdfpy's FK of both files)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from diff.pairs import (
    PANDA,
    changes,
    edited,
    element,
    expanded,
    links_below,
    only,
    pose_delta,
    run,
    run_json,
    write,
    zero_poses,
)


def _origin(joint, xyz=None, rpy=None) -> None:
    origin = joint.find("origin")
    if xyz is not None:
        origin.set("xyz", " ".join(repr(v) for v in xyz))
    if rpy is not None:
        origin.set("rpy", " ".join(repr(v) for v in rpy))


def _vec(text: str) -> list[float]:
    return [float(v) for v in text.split()]


def _check_poses_against_yourdfpy(report, old_text: str, new_text: str, expected_links: set[str]) -> None:
    before, after = zero_poses(old_text), zero_poses(new_text)
    assert {p["link"] for p in report["poses"]} == expected_links
    for pose in report["poses"]:
        mm, deg = pose_delta(before[pose["old_link"]], after[pose["link"]])
        assert pose["translation_mm"] == pytest.approx(mm, abs=1e-6)
        assert pose["rotation_deg"] == pytest.approx(deg, abs=1e-5)
        assert pose["new"]["xyz"] == pytest.approx(list(after[pose["link"]][:3, 3]), abs=1e-12)
    keys = [(-p["translation_mm"], -p["rotation_deg"]) for p in report["poses"]]
    assert keys == sorted(keys), "largest change first"


def test_moved_joint_moves_every_link_below_it_by_as_much(tmp_path: Path) -> None:
    old = expanded("arm.urdf.xacro")
    dz = 0.025

    def move(root):
        joint = element(root, "joint", "arm_elbow_joint")
        xyz = _vec(joint.find("origin").get("xyz"))
        _origin(joint, xyz=[xyz[0], xyz[1], xyz[2] + dz])

    new = edited(old, move)
    old_z = _vec(element(ET.fromstring(old), "joint", "arm_elbow_joint").find("origin").get("xyz"))[2]
    code, report = run_json(str(write(tmp_path, "old.urdf", old)), str(write(tmp_path, "new.urdf", new)), cwd=tmp_path)
    assert code == 1 and report["equal"] is False
    only(report, "joints", "poses")
    origin = changes(report, "joints")["arm_elbow_joint"]
    assert list(origin) == ["origin.xyz"]
    assert origin["origin.xyz"]["old"] == [0.0, 0.0, pytest.approx(old_z * 1000)]
    assert origin["origin.xyz"]["new"] == [0.0, 0.0, pytest.approx((old_z + dz) * 1000)]
    assert origin["origin.xyz"]["delta"] == pytest.approx(25.0) and origin["origin.xyz"]["unit"] == "mm"
    below = links_below(old, "arm_elbow_joint")
    assert len(below) == 7  # fore, 3 wrist links, palm, 2 fingers
    _check_poses_against_yourdfpy(report, old, new, below)
    # At q = 0 every link below a translated joint moves by the translation, and none turns.
    assert all(p["translation_mm"] == pytest.approx(25.0) and p["rotation_deg"] == 0.0 for p in report["poses"])

    text = run(str(tmp_path / "old.urdf"), str(tmp_path / "new.urdf"), cwd=tmp_path)
    assert text.returncode == 1
    lines = text.stdout.splitlines()
    assert lines[0].startswith("--- ") and lines[1].startswith("+++ ")
    assert "joints: 1 changed" in lines and "  ~ joint arm_elbow_joint" in lines
    assert "      origin.xyz: [0, 0, 400] → [0, 0, 425] mm (moved 25 mm)" in lines
    assert "link poses at the zero configuration (T_root_link, largest change first): 7 changed" in lines
    assert "  ~ link gripper_palm_link: moved 25 mm, turned 0 deg" in lines


def test_turned_joint_turns_the_links_below_as_yourdfpy_computes(tmp_path: Path) -> None:
    old = PANDA.read_text()
    rpy = (0.1, -0.2, 0.3)

    def turn(root):
        joint = element(root, "joint", "panda_joint4")
        _origin(joint, xyz=[0.0825 + 0.01, 0.0, 0.0], rpy=rpy)

    new = edited(old, turn)
    code, report = run_json(str(PANDA), str(write(tmp_path, "new.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "joints", "poses")
    change = changes(report, "joints")["panda_joint4"]
    assert change["origin.rpy"]["new"] == pytest.approx([math.degrees(a) for a in rpy])
    origin = element(ET.fromstring(old), "joint", "panda_joint4").find("origin")
    assert change["origin.rpy"]["old"] == pytest.approx([math.degrees(a) for a in _vec(origin.get("rpy"))])
    assert change["origin.xyz"]["old"] == pytest.approx([v * 1000 for v in _vec(origin.get("xyz"))])
    assert change["origin.xyz"]["delta"] == pytest.approx(10.0)
    _check_poses_against_yourdfpy(report, old, new, links_below(old, "panda_joint4"))


def test_renamed_link_is_one_rename_and_nothing_else(tmp_path: Path) -> None:
    old = expanded("diffbot.urdf.xacro")

    def rename(root):
        element(root, "link", "left_wheel").set("name", "left_wheel_v2")
        element(root, "joint", "left_wheel_joint").find("child").set("link", "left_wheel_v2")

    new = edited(old, rename)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links")
    assert report["links"] == {"added": [], "removed": [], "renamed": [{"old": "left_wheel", "new": "left_wheel_v2"}],
                               "changed": []}
    text = run(str(tmp_path / "a.urdf"), str(tmp_path / "b.urdf"), cwd=tmp_path).stdout
    assert "links: 1 renamed\n  ~ link left_wheel → left_wheel_v2 (renamed)\n" in text


def test_renamed_joints_and_links_pair_up_by_tree_and_origin(tmp_path: Path) -> None:
    """Both wheels and both wheel joints renamed: same parent and type, told apart by their origins."""
    old = expanded("diffbot.urdf.xacro")
    names = {"left": ("wl", "jl"), "right": ("wr", "jr")}

    def rename(root):
        for side, (link, joint) in names.items():
            element(root, "link", f"{side}_wheel").set("name", link)
            j = element(root, "joint", f"{side}_wheel_joint")
            j.set("name", joint)
            j.find("child").set("link", link)

    new = edited(old, rename)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links", "joints")
    assert sorted((r["old"], r["new"]) for r in report["links"]["renamed"]) == [("left_wheel", "wl"),
                                                                               ("right_wheel", "wr")]
    assert sorted((r["old"], r["new"]) for r in report["joints"]["renamed"]) == [("left_wheel_joint", "jl"),
                                                                                ("right_wheel_joint", "jr")]
    assert report["links"]["changed"] == report["joints"]["changed"] == []


def test_renamed_mimic_master_is_not_a_mimic_change(tmp_path: Path) -> None:
    old = expanded("arm.urdf.xacro")

    def rename(root):
        element(root, "joint", "gripper_left_finger_joint").set("name", "gripper_l_joint")
        element(root, "joint", "gripper_right_finger_joint").find("mimic").set("joint", "gripper_l_joint")

    new = edited(old, rename)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "joints")
    assert report["joints"]["renamed"] == [{"old": "gripper_left_finger_joint", "new": "gripper_l_joint"}]
    assert report["joints"]["changed"] == []


@pytest.mark.parametrize(("lower", "upper"), [(-2.5, 2.0), (0.5, 1.0)], ids=["upper", "zero-outside"])
def test_changed_limit(tmp_path: Path, lower: float, upper: float) -> None:
    """A limit change is reported with its values; poses are taken at q = 0 even when 0 leaves the limits."""
    old = expanded("arm.urdf.xacro")
    new = edited(old, lambda root: element(root, "joint", "arm_elbow_joint").find("limit").attrib.update(
        lower=repr(lower), upper=repr(upper)))
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "joints")
    change = changes(report, "joints")["arm_elbow_joint"]
    expected = {"limit.upper": (2.5, upper)} if lower == -2.5 else {"limit.lower": (-2.5, lower),
                                                                    "limit.upper": (2.5, upper)}
    assert {k: (v["old"], v["new"]) for k, v in change.items()} == expected
    assert all(v["unit"] == "rad" for v in change.values())


def test_swapped_mesh(tmp_path: Path) -> None:
    old = PANDA.read_text()
    root = ET.fromstring(old)
    mesh3 = element(root, "link", "panda_link3").find("visual/geometry/mesh").get("filename")
    mesh4 = element(root, "link", "panda_link4").find("visual/geometry/mesh").get("filename")
    new = edited(old, lambda r: element(r, "link", "panda_link3").find("visual/geometry/mesh").set("filename", mesh4))
    code, report = run_json(str(PANDA), str(write(tmp_path, "new.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links")
    change = changes(report, "links")["panda_link3"]
    assert {k: (v["old"], v["new"]) for k, v in change.items()} == {"visual[0].geometry.filename": (mesh3, mesh4)}
    text = run(str(PANDA), str(tmp_path / "new.urdf"), cwd=tmp_path).stdout
    assert f"      visual[0].geometry.filename: {mesh3} → {mesh4}\n" in text


def test_removed_and_added_link(tmp_path: Path) -> None:
    old = expanded("diffbot.urdf.xacro")

    def swap(root):
        laser = element(root, "joint", "laser_joint")
        root.remove(element(root, "link", "laser_link"))
        laser.set("name", "sonar_joint")
        laser.set("type", "revolute")
        laser.find("child").set("link", "sonar_link")
        ET.SubElement(laser, "limit", lower="-1", upper="1", effort="1", velocity="1")
        ET.SubElement(root, "link", name="sonar_link")

    new = edited(old, swap)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links", "joints")
    assert report["links"]["removed"] == [{"name": "laser_link"}]
    assert report["links"]["added"] == [{"name": "sonar_link"}]
    assert report["joints"]["removed"] == [{"name": "laser_joint", "type": "fixed", "parent": "base_link",
                                            "child": "laser_link"}]
    assert report["joints"]["added"] == [{"name": "sonar_joint", "type": "revolute", "parent": "base_link",
                                          "child": "sonar_link"}]
    text = run(str(tmp_path / "a.urdf"), str(tmp_path / "b.urdf"), cwd=tmp_path).stdout
    assert "  - link laser_link\n" in text and "  + link sonar_link\n" in text
    assert "  + joint sonar_joint (revolute, base_link → sonar_link)\n" in text


def test_material_and_inertial_changes(tmp_path: Path) -> None:
    old = expanded("arm.urdf.xacro")

    def change(root):
        element(root, "material", "orange").find("color").set("rgba", "1 0.5 0 1")
        element(root, "link", "arm_upper_link").find("inertial/mass").set("value", "1.75")
        element(root, "link", "arm_base_link").find("visual/material").set("name", "blue")

    new = edited(old, change)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links", "materials")
    assert changes(report, "materials") == {"orange": {"color": {
        "field": "color", "old": [1.0, 0.45, 0.1, 1.0], "new": [1.0, 0.5, 0.0, 1.0], "unit": "rgba", "delta": None,
        "delta_unit": ""}}}
    links = changes(report, "links")
    # The colour of a material is reported once (in materials), not again at every visual using it.
    assert set(links) == {"arm_upper_link", "arm_base_link"}
    assert {k: (v["old"], v["new"]) for k, v in links["arm_upper_link"].items()} == {"inertial.mass": (1.5, 1.75)}
    assert {k: (v["old"], v["new"]) for k, v in links["arm_base_link"].items()} == {
        "visual[0].material": ("grey", "blue"), "visual[0].material.color": ([0.6, 0.6, 0.6, 1.0],
                                                                             [0.15, 0.3, 0.8, 1.0])}


@pytest.mark.parametrize(("shift", "equal"), [(1e-10, True), (1e-7, False)])
def test_tolerance(tmp_path: Path, shift: float, equal: bool) -> None:
    old = expanded("arm.urdf.xacro")

    def nudge(root):
        joint = element(root, "joint", "arm_elbow_joint")
        xyz = _vec(joint.find("origin").get("xyz"))
        _origin(joint, xyz=[xyz[0] + shift, xyz[1], xyz[2]])

    new = edited(old, nudge)
    done = run(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert done.returncode == (0 if equal else 1), done.stderr
    assert (done.stdout == "") is equal
    # A looser tolerance makes the 1e-7 m shift equal too.
    assert run(str(tmp_path / "a.urdf"), str(tmp_path / "b.urdf"), "--tolerance", "1e-6", cwd=tmp_path).returncode == 0


def test_same_rotation_written_differently_is_equal(tmp_path: Path) -> None:
    old = expanded("arm.urdf.xacro")
    a = edited(old, lambda r: _origin(element(r, "joint", "gripper_palm_joint"), rpy=[math.pi, 0.0, 0.0]))
    b = edited(old, lambda r: _origin(element(r, "joint", "gripper_palm_joint"), rpy=[-math.pi, 0.0, 0.0]))
    done = run(str(write(tmp_path, "a.urdf", a)), str(write(tmp_path, "b.urdf", b)), cwd=tmp_path)
    assert (done.returncode, done.stdout) == (0, ""), done.stdout


def test_renamed_root_with_renamed_child_joints(tmp_path: Path) -> None:
    old = expanded("arm.urdf.xacro")

    def rename(root):
        element(root, "link", "world").set("name", "world2")
        joint = element(root, "joint", "arm_mount_joint")
        joint.set("name", "mount")
        joint.find("parent").set("link", "world2")

    new = edited(old, rename)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links", "joints")
    assert report["links"]["renamed"] == [{"old": "world", "new": "world2"}]
    assert report["joints"]["renamed"] == [{"old": "arm_mount_joint", "new": "mount"}]
    assert report["links"]["changed"] == report["joints"]["changed"] == []


def test_removed_root_is_not_taken_for_the_renamed_link_below_it(tmp_path: Path) -> None:
    """world and its joint removed, arm_base_link renamed base (the new root): the tree below tells the rename."""
    old = expanded("arm.urdf.xacro")

    def change(root):
        root.remove(element(root, "link", "world"))
        root.remove(element(root, "joint", "arm_mount_joint"))
        element(root, "link", "arm_base_link").set("name", "base")
        element(root, "joint", "arm_base_joint").find("parent").set("link", "base")

    new = edited(old, change)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "links", "joints")
    assert report["new"]["root"] == "base"
    assert report["links"]["removed"] == [{"name": "world"}]
    assert report["links"]["renamed"] == [{"old": "arm_base_link", "new": "base"}]
    assert report["joints"]["removed"] == [{"name": "arm_mount_joint", "type": "fixed", "parent": "world",
                                            "child": "arm_base_link"}]
    assert report["links"]["added"] == report["joints"]["added"] == []


def test_mimic_and_dynamics_changes_and_the_offset_they_move(tmp_path: Path) -> None:
    """The right finger's mimic offset becomes 10 mm: at q = 0 it sits 10 mm along its axis (0 -1 0)."""
    old = expanded("arm.urdf.xacro")

    def change(root):
        element(root, "joint", "gripper_right_finger_joint").find("mimic").attrib.update(multiplier="-1", offset="0.01")
        element(root, "joint", "gripper_left_finger_joint").find("dynamics").set("damping", "0.2")

    new = edited(old, change)
    code, report = run_json(str(write(tmp_path, "a.urdf", old)), str(write(tmp_path, "b.urdf", new)), cwd=tmp_path)
    assert code == 1
    only(report, "joints", "poses")
    got = {name: {k: (v["old"], v["new"]) for k, v in fields.items()} for name, fields in changes(report, "joints").items()}
    assert got == {"gripper_right_finger_joint": {"mimic.multiplier": (1.0, -1.0), "mimic.offset": (0.0, 0.01)},
                   "gripper_left_finger_joint": {"dynamics.damping": (0.1, 0.2)}}
    _check_poses_against_yourdfpy(report, old, new, {"gripper_right_finger_link"})
    assert report["poses"][0]["translation_mm"] == pytest.approx(10.0)
    assert report["poses"][0]["new"]["xyz"][1] - report["poses"][0]["old"]["xyz"][1] == pytest.approx(-0.01)
