"""Kinematics API: robot_state_publisher semantics, bad input, Jacobians, the fk command."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest
from conftest import ERD_ROBOTS
from handfk import HandFK

from robotmodel.errors import JointValueError
from robotmodel.kinematics import (
    KinematicModel,
    KinematicState,
    joint_transforms,
    static_transforms,
)
from robotmodel.model import parse_urdf

PANDA = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"
PR2 = ERD_ROBOTS / "pr2_description" / "urdf" / "pr2.urdf"

PLANAR_FLOATING = """<robot name="pf">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="slide" type="planar"><parent link="base"/><child link="a"/><origin xyz="1 0 0"/></joint>
  <joint name="free" type="floating"><parent link="a"/><child link="b"/><origin xyz="0 2 0"/></joint>
  <joint name="hinge" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint>
</robot>"""


@pytest.fixture(scope="module")
def panda() -> KinematicModel:
    return KinematicModel(parse_urdf(PANDA.read_text(encoding="utf-8")))


def test_joint_transforms_compose_to_link_poses() -> None:
    text = PR2.read_text(encoding="utf-8")
    model = KinematicModel(parse_urdf(text))
    rng = np.random.default_rng(7)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    values = dict(zip(model.variables, rng.uniform(lo, hi), strict=True))
    moving = joint_transforms(model, values)
    fixed = static_transforms(model)
    reference = HandFK(text).poses(values)
    # Every movable joint is published (mimics from their masters), every fixed one is static.
    published = set(moving.joints) | set(fixed.joints)
    assert published == {j.name for j in model.description.joints}
    for group in (moving, fixed):
        for k, (parent, child) in enumerate(zip(group.parents, group.children, strict=True)):
            expected = np.linalg.inv(reference[parent]) @ reference[child]
            np.testing.assert_allclose(group.matrices()[k], expected, atol=1e-9, err_msg=group.joints[k])


def test_rsp_publishes_only_given_joints_and_their_mimics() -> None:
    model = KinematicModel(parse_urdf(PR2.read_text(encoding="utf-8")))
    master = next(iter(model.mimics.values())).master
    out = joint_transforms(model, {master: 0.1})
    mimics_of_master = {r.joint for r in model.mimics.values() if r.master == master}
    assert set(out.joints) == {master} | mimics_of_master


def test_planar_is_static_and_floating_gets_no_transform() -> None:
    model = KinematicModel(parse_urdf(PLANAR_FLOATING))
    assert static_transforms(model).joints == ("slide",)
    np.testing.assert_allclose(static_transforms(model).translations[0], [1, 0, 0])
    assert joint_transforms(model, {"slide": 1.0, "free": 2.0, "hinge": 0.3}).joints == ("hinge",)
    # Through the API, floating and planar joints can be given values.
    state = KinematicState(model).update({"hinge": 0.0}, extra={"slide": [0.5, 0.0, 0.0],
                                                                "free": [0, 0, 1, 0, 0, 0, 1]})
    np.testing.assert_allclose(state.link_matrix("c")[:3, 3], [1.5, 2.0, 1.0], atol=1e-12)


@pytest.mark.parametrize(
    ("values", "needle"),
    [
        ({"nope": 0.0}, "unknown joint 'nope'"),
        ({"panda_joint1": float("nan")}, "joint 'panda_joint1': value nan is not finite"),
        ({"panda_joint2": 3.0}, r"joint 'panda_joint2': value 3 is outside its limits \[-1.7628, 1.7628\]"),
    ],
)
def test_bad_joint_values_name_the_joint(panda: KinematicModel, values: dict[str, float], needle: str) -> None:
    with pytest.raises(JointValueError, match=needle):
        panda.vector(values)


def test_wrong_length_and_clamp(panda: KinematicModel) -> None:
    with pytest.raises(JointValueError, match="expected 8 joint values"):
        panda.vector(np.zeros(3))
    clamped = panda.vector({"panda_joint2": 3.0}, clamp=True)
    assert clamped[panda.variables.index("panda_joint2")] == pytest.approx(1.7628)


def test_defaults_follow_joint_state_publisher(panda: KinematicModel) -> None:
    defaults = panda.default_positions()
    j4 = panda.description.joint("panda_joint4").limit
    assert j4 is not None and j4.upper is not None and j4.lower is not None and j4.upper < 0.0
    assert defaults["panda_joint4"] == pytest.approx((j4.lower + j4.upper) / 2)  # 0 is out of range
    assert defaults["panda_joint1"] == 0.0


def test_jacobian_matches_finite_differences(panda: KinematicModel) -> None:
    state = KinematicState(panda)
    q = panda.vector({"panda_joint2": 0.3, "panda_joint4": -1.2, "panda_joint6": 1.0})
    jac = state.update(q).jacobian("panda_hand")
    eps = 1e-7
    base = state.update(q).link_matrix("panda_hand")
    for i in range(panda.nv):
        dq = q.copy()
        dq[i] += eps
        moved = state.update(dq).link_matrix("panda_hand")
        np.testing.assert_allclose(jac[:3, i], (moved[:3, 3] - base[:3, 3]) / eps, atol=1e-5)
        # Angular part: skew part of dR·Rᵀ.
        w = (moved[:3, :3] - base[:3, :3]) / eps @ base[:3, :3].T
        np.testing.assert_allclose(jac[3:, i], [w[2, 1], w[0, 2], w[1, 0]], atol=1e-5)


def test_fk_command_json_matches_hand_math() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "robotmodel.cli.main", "fk", str(PANDA), "--joint", "panda_joint1=0.5",
         "--joint", "panda_joint4=-1.5", "--format", "json"], capture_output=True, text=True, check=True)
    report = json.loads(result.stdout)
    assert report["root"] == "panda_link0"
    reference = HandFK(PANDA.read_text(encoding="utf-8")).poses(
        {"panda_joint1": 0.5, "panda_joint4": -1.5, "panda_joint6": 0.0})
    for link, pose in report["links"].items():
        np.testing.assert_allclose(pose["xyz"], reference[link][:3, 3], atol=1e-9)
        x, y, z, w = pose["quat_xyzw"]
        rot = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
        np.testing.assert_allclose(rot, reference[link][:3, :3], atol=1e-9)


def test_fk_command_errors_are_one_line() -> None:
    result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "fk", str(PANDA), "--joint",
                             "panda_joint1=9"], capture_output=True, text=True, check=False)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "panda_joint1" in result.stderr
