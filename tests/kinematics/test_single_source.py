"""One source of truth and one error class per failure across every kinematics API.

- A description changed with ``dataclasses.replace`` moves every engine alike
  (KinematicState, batch FK, Jacobians), and by the amount the change says.
- robot_state_publisher's fast path (every joint given) and slow path (some joints
  given) publish the same quaternion, sign included.
- An unknown link, or a joint vector of the wrong length, raises one error type
  whatever API it reaches.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
from conftest import ERD_ROBOTS, erd_urdfs

from robotmodel.errors import JointValueError, UnknownJointError, UnknownLinkError
from robotmodel.kinematics import (
    PINOCCHIO_DATA_LIMIT,
    KinematicModel,
    KinematicState,
    batch_link_matrices,
    batch_link_poses,
    joint_transforms,
)
from robotmodel.model import JointType, Pose, RobotDescription, parse_urdf
from robotmodel.spatial import quats_canonical

PANDA = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"
PR2 = ERD_ROBOTS / "pr2_description" / "urdf" / "pr2.urdf"


def _random_q(model: KinematicModel, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    return rng.uniform(lo, hi, (n, model.nv))


def _descendants(desc: RobotDescription, link: str) -> set[str]:
    out = {link}
    stack = [link]
    while stack:
        for joint in desc.child_joints(stack.pop()):
            out.add(joint.child)
            stack.append(joint.child)
    return out


@pytest.fixture(scope="module")
def panda_desc() -> RobotDescription:
    return parse_urdf(PANDA.read_text(encoding="utf-8"))


def test_replaced_joint_origin_moves_every_engine(panda_desc: RobotDescription) -> None:
    # The first joint hangs off the root: moving its origin by 1 m along the root's x
    # moves exactly the links below it by (1, 0, 0), whatever the configuration.
    first = panda_desc.child_joints(panda_desc.root)[0]
    x, y, z = first.origin.xyz
    moved_joint = dataclasses.replace(first, origin=Pose((x + 1.0, y, z), first.origin.rpy))
    moved = dataclasses.replace(
        panda_desc, joints=tuple(moved_joint if j.name == first.name else j for j in panda_desc.joints))
    base_model, moved_model = KinematicModel(panda_desc), KinematicModel(moved)
    below = _descendants(panda_desc, first.child)
    shift = np.array([[1.0 if link in below else 0.0, 0.0, 0.0] for link in base_model.link_names])
    qs = _random_q(base_model, 5, 1)
    batch_base, batch_moved = batch_link_matrices(base_model, qs), batch_link_matrices(moved_model, qs)
    state = KinematicState(moved_model)
    for k, q in enumerate(qs):
        single = state.update(q).link_matrices()
        np.testing.assert_allclose(batch_moved[k], single, atol=1e-12)
        np.testing.assert_allclose(batch_moved[k][:, :3, 3], batch_base[k][:, :3, 3] + shift, atol=1e-12)
        np.testing.assert_allclose(batch_moved[k][:, :3, :3], batch_base[k][:, :3, :3], atol=1e-12)


def test_jacobian_follows_the_replaced_description(panda_desc: RobotDescription) -> None:
    # Lengthen one link in the middle of the arm: the Jacobian must be that of the
    # changed arm (finite differences of the poses), not of the text it was parsed from.
    j4 = panda_desc.joint("panda_joint4")
    x, y, z = j4.origin.xyz
    changed = dataclasses.replace(panda_desc, joints=tuple(
        dataclasses.replace(j, origin=Pose((x + 0.5, y, z), j.origin.rpy)) if j.name == j4.name else j
        for j in panda_desc.joints))
    model = KinematicModel(changed)
    state = KinematicState(model)
    q = _random_q(model, 1, 2)[0]
    jac = state.update(q).jacobian("panda_hand")
    base = state.link_matrix("panda_hand")[:3, 3].copy()
    eps = 1e-7
    for i in range(model.nv):
        dq = q.copy()
        dq[i] += eps
        moved = state.update(dq).link_matrix("panda_hand")[:3, 3]
        np.testing.assert_allclose(jac[:3, i], (moved - base) / eps, atol=1e-5)


def test_fast_and_slow_publisher_paths_give_the_same_quaternions() -> None:
    model = KinematicModel(parse_urdf(PR2.read_text(encoding="utf-8")))
    for k, q in enumerate(_random_q(model, 40, 3)):
        values = dict(zip(model.variables, q, strict=True))
        fast = joint_transforms(model, values)
        # Leaving one joint out takes the general path for the rest.
        partial = dict(values)
        del partial[model.variables[k % model.nv]]
        slow = joint_transforms(model, partial)
        by_joint = dict(zip(fast.joints, fast.rotations, strict=True))
        assert set(slow.joints) < set(fast.joints)
        for name, rotation in zip(slow.joints, slow.rotations, strict=True):
            np.testing.assert_allclose(rotation, by_joint[name], atol=1e-12, err_msg=name)
        for out in (fast, slow):
            # Already canonical: the round trip through tf2's kernel keeps it (to rounding).
            np.testing.assert_allclose(out.rotations, quats_canonical(out.rotations), atol=1e-15)


@pytest.fixture(scope="module")
def panda() -> KinematicModel:
    return KinematicModel(parse_urdf(PANDA.read_text(encoding="utf-8")))


def test_unknown_link_is_one_error_type(panda: KinematicModel) -> None:
    state = KinematicState(panda)
    for call in (lambda: state.link_pose("nope"), lambda: state.link_matrix("nope"),
                 lambda: state.jacobian("nope"), lambda: panda.description.link("nope")):
        with pytest.raises(UnknownLinkError, match="'nope'"):
            call()


def test_unknown_joint_is_one_error_type(panda: KinematicModel) -> None:
    state = KinematicState(panda)
    for call in (lambda: panda.vector({"nope": 0.0}), lambda: state.update({"nope": 0.0}),
                 lambda: state.update(None, extra={"nope": [0, 0, 0]}), lambda: panda.description.joint("nope")):
        with pytest.raises(UnknownJointError, match="'nope'"):
            call()


def test_wrong_length_joint_vector_is_one_error_type(panda: KinematicModel) -> None:
    state = KinematicState(panda)
    bad = np.zeros(panda.nv + 1)
    for call in (lambda: panda.vector(bad), lambda: state.update(bad),
                 lambda: batch_link_matrices(panda, bad[None, :]), lambda: batch_link_poses(panda, bad[None, :]),
                 lambda: batch_link_poses(panda, bad)):
        with pytest.raises(JointValueError, match=f"expected {panda.nv} joint values"):
            call()


def test_planar_and_floating_still_work_without_pinocchio_poses() -> None:
    # Regression guard for the own-FK path: floating and planar values given by name.
    text = """<robot name="pf">
      <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
      <joint name="slide" type="planar"><parent link="base"/><child link="a"/><origin xyz="1 0 0"/></joint>
      <joint name="free" type="floating"><parent link="a"/><child link="b"/><origin xyz="0 2 0"/></joint>
      <joint name="hinge" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint>
    </robot>"""
    model = KinematicModel(parse_urdf(text))
    assert {j.type for j in model.description.joints} >= {JointType.PLANAR, JointType.FLOATING}
    state = KinematicState(model).update(
        {"hinge": 0.5}, extra={"slide": [0.5, 0.25, np.pi / 2], "free": [0, 0, 1, 0, 0, np.sin(0.2), np.cos(0.2)]})
    # slide: T(1,0,0)·T(0.5,0.25)·Rz(π/2); free: T(0,2,0)·T(0,0,1)·Rz(0.4); hinge: Rz(0.5)
    expected_a = np.array([1.5, 0.25, 0.0])
    np.testing.assert_allclose(state.link_matrix("a")[:3, 3], expected_a, atol=1e-12)
    # (0, 2, 1) in a's frame, a turned by π/2 about z: (-2, 0, 1)
    np.testing.assert_allclose(state.link_matrix("b")[:3, 3], expected_a + np.array([-2.0, 0.0, 1.0]), atol=1e-12)
    angle = np.pi / 2 + 0.4 + 0.5
    np.testing.assert_allclose(state.link_matrix("c")[:2, :2],
                               [[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]], atol=1e-12)


ERD = [p for p in erd_urdfs() if p.name != "ur3.urdf"]  # ur3.urdf is an empty robot


@pytest.mark.parametrize("path", ERD, ids=lambda p: p.name)
def test_pinocchio_from_the_file_agrees_with_the_description(path: Path) -> None:
    # The description (through to_urdf) loses nothing kinematics needs: Pinocchio built
    # from the file's own text puts every link where our FK and our Pinocchio put it.
    text = path.read_text(encoding="utf-8")
    model = KinematicModel(parse_urdf(text))
    from_file = pin.buildModelFromXML(text)
    data = from_file.createData()
    frames = [from_file.getFrameId(name, pin.BODY) for name in model.link_names]
    state = KinematicState(model)
    for q in _random_q(model, 3, 5):
        config = model.pin_configuration(q)
        assert config.shape == (from_file.nq,)
        pin.framesForwardKinematics(from_file, data, config)
        ours = state.update(q).link_matrices()
        for i, frame in enumerate(frames):
            np.testing.assert_allclose(ours[i], data.oMf[frame].homogeneous, atol=1e-9,
                                       err_msg=model.link_names[i])
        if model.pinocchio_data_bytes < PINOCCHIO_DATA_LIMIT and model.nv:
            link = model.link_names[-1]
            theirs = pin.computeFrameJacobian(from_file, data, config, frames[-1], pin.LOCAL_WORLD_ALIGNED)
            if not model.mimics:
                np.testing.assert_allclose(state.jacobian(link), _fold(model, from_file, theirs), atol=1e-9)


def _fold(model: KinematicModel, pm: object, full: np.ndarray) -> np.ndarray:
    """Pinocchio's columns of one-DoF joints, in ``model.variables`` order."""
    cols = [pm.idx_vs[pm.getJointId(name)] for name in model.variables]  # type: ignore[attr-defined]
    return np.asarray(full).reshape(6, -1)[:, cols]
