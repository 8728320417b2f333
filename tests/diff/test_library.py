"""robotmodel.diff as a library: renames found through a whole renamed tree, the JSON's fixed shape, and the
renderings of equal descriptions."""

from __future__ import annotations

import json

import pytest
from diff.pairs import PANDA

import robotmodel
from robotmodel.diff import DEFAULT_TOLERANCE, diff_descriptions, diff_json, render_json, render_text


def _chain(n: int, link: str, joint: str, dz: float = 0.1) -> str:
    links = "".join(f'<link name="{link}{i}"/>' for i in range(n + 1))
    joints = "".join(
        f'<joint name="{joint}{i}" type="revolute"><parent link="{link}{i}"/><child link="{link}{i + 1}"/>'
        f'<origin xyz="0 0 {dz}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        for i in range(n))
    return f'<robot name="c">{links}{joints}</robot>'


def test_every_link_and_joint_of_a_long_chain_renamed() -> None:
    n = 400
    old = robotmodel.load(_chain(n, "l", "j"))
    new = robotmodel.load(_chain(n, "m", "k"))
    diff = diff_descriptions(old, new)
    assert diff.links.renamed == tuple((f"l{i}", f"m{i}") for i in range(n + 1))
    assert diff.joints.renamed == tuple((f"j{i}", f"k{i}") for i in range(n))
    assert not (diff.links.added or diff.links.removed or diff.links.changed or diff.joints.changed or diff.poses)


def test_renamed_chain_with_one_joint_moved_moves_the_rest_of_the_chain() -> None:
    n = 50
    old = robotmodel.load(_chain(n, "l", "j"))
    text = _chain(n, "m", "k").replace('<joint name="k20" type="revolute"><parent link="m20"/><child link="m21"/>'
                                       '<origin xyz="0 0 0.1"/>',
                                       '<joint name="k20" type="revolute"><parent link="m20"/><child link="m21"/>'
                                       '<origin xyz="0 0 0.15"/>')
    diff = diff_descriptions(old, robotmodel.load(text))
    assert [(c.old_name, c.new_name, [x.field for x in c.changes]) for c in diff.joints.changed] == [
        ("j20", "k20", ["origin.xyz"])]
    assert {p.link for p in diff.poses} == {f"m{i}" for i in range(21, n + 1)}
    assert all(p.translation_mm == pytest.approx(50.0) for p in diff.poses)


def test_equal_descriptions_render_as_nothing_and_json_says_equal() -> None:
    panda = robotmodel.load(PANDA)
    diff = diff_descriptions(panda, robotmodel.load(PANDA), old_label="a", new_label="b")
    assert diff.equal and diff.tolerance == DEFAULT_TOLERANCE == 1e-9
    assert render_text(diff) == ""
    report = json.loads(render_json(diff))
    assert report == diff_json(diff)
    assert list(report) == ["equal", "tolerance", "old", "new", "robot", "links", "joints", "materials", "poses"]
    assert report["old"] == {"source": "a", "robot": "panda", "root": "panda_link0"}
    for section in ("links", "joints", "materials"):
        assert report[section] == {"added": [], "removed": [], "renamed": [], "changed": []}


def test_robot_name_change_is_a_difference() -> None:
    panda = robotmodel.load(PANDA)
    other = robotmodel.load(PANDA.read_text().replace('<robot name="panda"', '<robot name="panda2"', 1))
    diff = diff_descriptions(panda, other)
    assert not diff.equal
    assert [(c.field, c.old, c.new) for c in diff.robot] == [("name", "panda", "panda2")]
    assert "robot name: panda → panda2" in render_text(diff)
