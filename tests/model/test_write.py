"""to_urdf: what it writes parses back to the same description, and urdfdom reads it the same way."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, ERD_ROBOTS, erd_urdfs, urdfdom_env
from hypothesis import given, settings
from hypothesis import strategies as st

from robotmodel.model import (
    Box,
    Collision,
    Cylinder,
    Dynamics,
    Inertia,
    Inertial,
    Joint,
    JointType,
    Limit,
    Link,
    Material,
    Mesh,
    Mimic,
    Pose,
    RobotDescription,
    SafetyController,
    Sphere,
    Visual,
    parse_urdf,
    to_urdf,
)

ROBOTS = [p for p in erd_urdfs() if p.name != "ur3.urdf"]


def _check(path: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                          env=urdfdom_env(), check=False)


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: str(p.relative_to(ERD_ROBOTS)))
def test_urdfdom_reads_what_we_write(path: Path, tmp_path: Path) -> None:
    written = tmp_path / "written.urdf"
    written.write_text(to_urdf(parse_urdf(path.read_text(encoding="utf-8"))), encoding="utf-8")
    ours, original = _check(written), _check(path)
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout == original.stdout


finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
nonzero = finite.filter(lambda v: v != 0.0)
names = st.text(st.characters(codec="utf-8", exclude_categories=("Cs", "Cc")), min_size=1, max_size=8)
vec3 = st.tuples(finite, finite, finite)
poses = st.builds(Pose, vec3, vec3)
geometries = st.one_of(
    st.builds(Box, vec3), st.builds(Cylinder, finite, finite), st.builds(Sphere, finite),
    st.builds(Mesh, names, vec3),
)
rgba = st.tuples(finite, finite, finite, finite)
materials = st.builds(Material, names, st.none() | rgba, st.none() | names)
inertias = st.builds(Inertia, finite, finite, finite, finite, finite, finite)
inertials = st.builds(Inertial, finite, inertias, poses)


@st.composite
def robots(draw: st.DrawFn) -> RobotDescription:
    link_names = draw(st.lists(names, min_size=1, max_size=6, unique=True))
    links = tuple(
        Link(n, tuple(draw(st.lists(st.builds(Visual, geometries, poses, st.none() | names,
                                             st.none() | materials), max_size=2))),
             tuple(draw(st.lists(st.builds(Collision, geometries, poses, st.none() | names), max_size=2))),
             draw(st.none() | inertials))
        for n in link_names
    )
    joints = []
    for i, child in enumerate(link_names[1:], start=1):
        jtype = draw(st.sampled_from(list(JointType)))
        limit = draw(st.builds(Limit, finite, finite, st.none() | finite, st.none() | finite))
        if jtype not in (JointType.REVOLUTE, JointType.PRISMATIC) and draw(st.booleans()):
            limit = None
        axis = (1.0, 0.0, 0.0) if jtype in (JointType.FIXED, JointType.FLOATING) else draw(
            st.tuples(nonzero, finite, finite))
        joints.append(Joint(
            f"j{i}", jtype, link_names[draw(st.integers(0, i - 1))], child, draw(poses), axis, limit,
            Mimic("j1", draw(finite), draw(finite)) if i > 1 and draw(st.booleans()) else None,
            draw(st.none() | st.builds(Dynamics, finite, finite)),
            draw(st.none() | st.builds(SafetyController, finite, finite, finite, finite)),
        ))
    mats = tuple({m.name: m for m in draw(st.lists(materials, max_size=3))}.values())
    return RobotDescription(draw(names), links, tuple(joints), mats)


@settings(max_examples=150, deadline=None)
@given(robots())
def test_round_trip_of_generated_robots(desc: RobotDescription) -> None:
    text = to_urdf(desc)
    assert parse_urdf(text) == desc
