"""to_yourdfpy / trimesh_scene: the robot handed to yourdfpy and trimesh sits where our FK puts it.

Every link's pose from yourdfpy (its own FK over the URDF we hand it) is compared with
KinematicState's at the same joint values, over every loadable example robot (those with
non-unit prismatic axes included: the handed-over URDF carries unit axes), the bundled
xacro robots and a hand-written robot with a mimic, a continuous joint and a joint whose
default is the middle of its limits.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import BUNDLED, ERD_ROBOTS, erd_urdfs

from robotmodel.errors import JointValueError, UnknownJointError
from robotmodel.kinematics import KinematicModel, KinematicState, to_yourdfpy, trimesh_scene
from robotmodel.model import load, parse_urdf

ROBOTS = [p for p in erd_urdfs() if p.name != "ur3.urdf"] + sorted(BUNDLED.glob("*.urdf.xacro"))
TOL = 1e-9


def _configs(model: KinematicModel, n: int, seed: int) -> list[dict[str, float]]:
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    return [dict(zip(model.variables, row.tolist(), strict=True)) for row in rng.uniform(lo, hi, (n, model.nv))]


def _assert_same_poses(model: KinematicModel, positions: dict[str, float]) -> None:
    urdf = to_yourdfpy(model, positions)
    state = KinematicState(model)
    state.update(model.vector(positions))
    root = model.description.root
    for link in model.description.links:
        np.testing.assert_allclose(urdf.get_transform(link.name, root), state.link_matrix(link.name), atol=TOL,
                                   err_msg=link.name)


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.name)
def test_link_poses_equal_our_fk(path: Path) -> None:
    model = KinematicModel(load(path))
    for positions in [{}, *_configs(model, 2, seed=len(path.name))]:
        _assert_same_poses(model, positions)


SMALL = """<robot name="small">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="lift" type="prismatic"><parent link="base"/><child link="a"/><axis xyz="0 0 2"/>
    <origin xyz="0.1 0 0" rpy="0 0 0.3"/><limit lower="0.2" upper="0.6" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 1 1"/>
    <origin xyz="0 0.2 0"/></joint>
  <joint name="follow" type="revolute"><parent link="b"/><child link="c"/><axis xyz="1 0 0"/>
    <origin xyz="0 0 0.3"/><limit lower="-2" upper="2" effort="1" velocity="1"/>
    <mimic joint="spin" multiplier="-0.5" offset="0.2"/></joint>
  <joint name="tip" type="fixed"><parent link="c"/><child link="d"/><origin xyz="0.05 0 0"/></joint>
</robot>"""


def test_mimic_continuous_non_unit_axis_and_defaults() -> None:
    model = KinematicModel(parse_urdf(SMALL))
    urdf = to_yourdfpy(model)  # defaults: lift at the middle of [0.2, 0.6] (0 is outside), spin at 0
    # By hand: base -> a is the origin then 0.4 along the unit z axis (the written axis is 0 0 2).
    expected = np.eye(4)
    expected[:3, :3] = [[math.cos(0.3), -math.sin(0.3), 0], [math.sin(0.3), math.cos(0.3), 0], [0, 0, 1]]
    expected[:3, 3] = (0.1, 0, 0.4)
    np.testing.assert_allclose(urdf.get_transform("a", "base"), expected, atol=TOL)
    _assert_same_poses(model, {"lift": 0.55, "spin": 2.5})
    _assert_same_poses(model, {"spin": -7.0})  # a continuous joint takes any angle


def test_bad_positions_are_refused_as_everywhere() -> None:
    model = KinematicModel(parse_urdf(SMALL))
    with pytest.raises(UnknownJointError, match="unknown joint 'elbow'"):
        to_yourdfpy(model, {"elbow": 0.1})
    with pytest.raises(JointValueError):
        to_yourdfpy(model, {"spin": math.nan})


def test_trimesh_scene_holds_the_meshes_where_our_fk_puts_the_links() -> None:
    panda = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"
    model = KinematicModel(load(panda))
    positions = {"panda_joint2": -0.4, "panda_joint4": -2.0, "panda_finger_joint1": 0.03}
    scene = trimesh_scene(model, positions, package_paths=[ERD_ROBOTS.parent])
    assert len(scene.geometry) >= 10  # the links' .dae/.stl meshes, loaded through package:// URIs
    state = KinematicState(model)
    state.update(model.vector(positions))
    for link in ("panda_link4", "panda_hand", "panda_leftfinger", "panda_rightfinger"):
        matrix, _ = scene.graph.get(frame_to=link, frame_from=model.description.root)
        np.testing.assert_allclose(matrix, state.link_matrix(link), atol=TOL)
    collision = trimesh_scene(model, positions, collision=True, package_paths=[ERD_ROBOTS.parent])
    assert len(collision.geometry) >= 10
