"""The typed description against yourdfpy (an independent URDF parser) on real robots, plus round trips."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import robotmodel.robots
import yourdfpy
from conftest import BUNDLED, ERD_ROBOTS, erd_urdfs

import robotmodel
from robotmodel.errors import UnknownJointError, UnknownLinkError, URDFError
from robotmodel.model import JointType, Pose, RobotDescription, load, parse_urdf, to_urdf

ROBOTS = [p for p in erd_urdfs() if p.name != "ur3.urdf"]  # ur3.urdf is an empty, nameless robot


def _id(path: Path) -> str:
    return str(path.relative_to(ERD_ROBOTS))


def _matrix(pose: Pose) -> np.ndarray:
    # URDF rpy: R = Rz(yaw) Ry(pitch) Rx(roll), written out independently of the library.
    r, p, y = pose.rpy
    rx = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
    ry = np.array([[math.cos(p), 0, math.sin(p)], [0, 1, 0], [-math.sin(p), 0, math.cos(p)]])
    rz = np.array([[math.cos(y), -math.sin(y), 0], [math.sin(y), math.cos(y), 0], [0, 0, 1]])
    m = np.eye(4)
    m[:3, :3] = rz @ ry @ rx
    m[:3, 3] = pose.xyz
    return m


@pytest.mark.parametrize("path", ROBOTS, ids=_id)
def test_matches_yourdfpy(path: Path) -> None:
    desc = parse_urdf(path.read_text(encoding="utf-8"), source=str(path))
    ref = yourdfpy.URDF.load(str(path), build_scene_graph=True, load_meshes=False,
                             load_collision_meshes=False)
    assert desc.name == ref.robot.name
    assert desc.root == ref.base_link
    assert [link.name for link in desc.links] == [link.name for link in ref.robot.links]
    assert [j.name for j in desc.joints] == [j.name for j in ref.robot.joints]
    for ours, theirs in zip(desc.joints, ref.robot.joints, strict=True):
        assert (ours.type.value, ours.parent, ours.child) == (theirs.type, theirs.parent, theirs.child)
        expected = np.eye(4) if theirs.origin is None else theirs.origin
        np.testing.assert_allclose(_matrix(ours.origin), expected, atol=1e-12)
        if theirs.axis is not None and ours.type is not JointType.FIXED:
            np.testing.assert_allclose(ours.axis, theirs.axis)
        if theirs.limit is not None and ours.limit is not None:
            assert (ours.limit.effort, ours.limit.velocity) == (theirs.limit.effort, theirs.limit.velocity)
            assert ours.limit.lower == theirs.limit.lower or ours.limit.lower is None
        assert (ours.mimic is None) == (theirs.mimic is None)
        if ours.mimic is not None and theirs.mimic is not None:
            assert ours.mimic.joint == theirs.mimic.joint
            assert ours.mimic.multiplier == (theirs.mimic.multiplier or 1.0)
    for ours_link, theirs_link in zip(desc.links, ref.robot.links, strict=True):
        assert (ours_link.inertial is None) == (theirs_link.inertial is None)
        if ours_link.inertial is not None and theirs_link.inertial is not None:
            assert ours_link.inertial.mass == theirs_link.inertial.mass
        assert len(ours_link.visuals) == len(theirs_link.visuals)
        assert len(ours_link.collisions) == len(theirs_link.collisions)


@pytest.mark.parametrize("path", ROBOTS, ids=_id)
def test_round_trip(path: Path) -> None:
    desc = parse_urdf(path.read_text(encoding="utf-8"))
    again = parse_urdf(to_urdf(desc))
    assert again == desc
    assert to_urdf(again) == to_urdf(desc)


def _bundled() -> list[Path]:
    # Robots only: included macro files such as inertia_macros.xacro are not robots.
    return [BUNDLED / name for name in robotmodel.robots.names()]


@pytest.mark.parametrize("path", _bundled(), ids=lambda p: p.name)
def test_bundled_round_trip(path: Path) -> None:
    desc = load(path)
    assert parse_urdf(to_urdf(desc)) == desc


def test_tree_helpers_on_panda() -> None:
    desc = parse_urdf((ERD_ROBOTS / "panda_description/urdf/panda.urdf").read_text(encoding="utf-8"))
    assert desc.root == "panda_link0"
    assert desc.parent_joint("panda_link0") is None
    hand = desc.child_joints("panda_hand")
    assert [j.name for j in hand] == sorted(j.name for j in desc.joints if j.parent == "panda_hand")
    joint = desc.parent_joint("panda_leftfinger")
    assert joint is not None and joint.name == "panda_finger_joint1"
    assert desc.joint("panda_finger_joint2").mimic is not None
    assert desc.link("panda_hand").inertial is not None
    assert [j.name for j in desc.movable_joints] == [
        j.name for j in desc.joints if j.type is not JointType.FIXED
    ]
    walked = [j.name for _, j in desc.walk()]
    assert sorted(walked) == sorted(j.name for j in desc.joints)
    with pytest.raises(UnknownLinkError, match="no link 'nope'"):
        desc.link("nope")
    with pytest.raises(UnknownJointError, match="no joint 'nope'"):
        desc.joint("nope")


def test_children_ordered_by_joint_name_not_document_order() -> None:
    text = ('<robot name="r"><link name="base"/><link name="alpha"/><link name="zeta"/>'
            '<joint name="z_joint" type="fixed"><parent link="base"/><child link="alpha"/></joint>'
            '<joint name="a_joint" type="fixed"><parent link="base"/><child link="zeta"/></joint></robot>')
    desc = parse_urdf(text)
    assert [j.child for j in desc.child_joints("base")] == ["zeta", "alpha"]
    assert [j.name for j in desc.joints] == ["z_joint", "a_joint"]


def test_load_goes_through_xacro(tmp_path: Path) -> None:
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    '<xacro:arg name="prefix" default="p_"/>'
                    '<link name="$(arg prefix)base"/></robot>')
    assert load(path).root == "p_base"
    assert load(path, {"prefix": "q_"}).root == "q_base"
    assert load(str(path)).source == str(path)
    assert robotmodel.load(path.read_text(), {"prefix": "t_"}).root == "t_base"
    assert isinstance(robotmodel.load(path), RobotDescription)


def test_load_errors_name_the_file(tmp_path: Path) -> None:
    with pytest.raises(URDFError, match="no such file"):
        load(tmp_path / "missing.urdf")
    with pytest.raises(URDFError, match="is a directory"):
        load(tmp_path)
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a"/>\n\n  <link name="a"/>\n</robot>\n')
    with pytest.raises(URDFError, match=r"bad\.urdf:4: link 'a' is not unique\.$"):
        load(bad)
    # The line is that of the user's file, not of xacro's re-formatted output.
    bad.write_text('<robot name="r">\n<!-- c -->\n\n<link name="a"/><link name="b"/>\n'
                   '<joint name="j" type="revolute">\n<parent link="a"/><child link="b"/></joint>\n</robot>')
    with pytest.raises(URDFError, match=r"bad\.urdf:5: Joint \[j\] is of type REVOLUTE"):
        load(bad)
    # A name xacro made up is not in the source: no line rather than a wrong one.
    bad.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:property name="p" '
                   'value="x_"/><link name="${p}a"/><link name="${p}a"/></robot>')
    with pytest.raises(URDFError, match=r"bad\.urdf: link 'x_a' is not unique\.$"):
        load(bad)
