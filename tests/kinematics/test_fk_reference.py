"""FK agrees (≤1e-9) with yourdfpy and with hand-composed URDF math on real robots."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yourdfpy
from conftest import ERD_ROBOTS, erd_urdfs
from handfk import HandFK

from robotmodel.kinematics import KinematicModel, KinematicState, batch_link_matrices
from robotmodel.model import JointType, RobotDescription, parse_urdf

ROBOTS = [p for p in erd_urdfs() if p.name != "ur3.urdf"]  # ur3.urdf is an empty robot
TOL = 1e-9


def _random_configs(model: KinematicModel, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    return rng.uniform(lo, hi, (n, model.nv))


def _unnormalized_prismatic(desc: RobotDescription) -> bool:
    return any(j.type is JointType.PRISMATIC and abs(np.linalg.norm(j.axis) - 1.0) > 1e-12 for j in desc.joints)


def test_all_loadable_example_robots_are_compared() -> None:
    assert len(ROBOTS) == 68


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.name)
def test_fk_matches_yourdfpy_and_hand_math(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    desc = parse_urdf(text, source=str(path))
    model = KinematicModel(desc)
    state = KinematicState(model)
    hand = HandFK(text)
    yd = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False,
                            load_collision_meshes=False)
    use_yourdfpy = not _unnormalized_prismatic(desc)  # yourdfpy does not normalize prismatic axes
    configs = _random_configs(model, 20, seed=sum(path.name.encode()))
    for i, name in enumerate(model.variables):
        mimic = desc.joint(name).mimic
        if mimic is not None:
            # A mimic of a missing joint (alex_psyonic_hands): we keep it an independent
            # joint; yourdfpy pins it to 0 + offset. Compare where both agree.
            configs[:, i] = mimic.offset
    batch = batch_link_matrices(model, configs)
    for k, q in enumerate(configs):
        state.update(q)
        ours = state.link_matrices()
        values = dict(zip(model.variables, q, strict=True))
        reference = hand.poses(values)
        if use_yourdfpy:
            yd.update_cfg({n: values[n] for n in yd.actuated_joint_names if n in values})
        for i, link in enumerate(model.link_names):
            np.testing.assert_allclose(ours[i], reference[link], atol=TOL, err_msg=f"{link} vs hand math")
            np.testing.assert_allclose(batch[k, i], ours[i], atol=TOL, err_msg=f"{link} batch vs single")
            if use_yourdfpy:
                theirs = yd.get_transform(link, yd.base_link)
                np.testing.assert_allclose(ours[i], theirs, atol=TOL, err_msg=f"{link} vs yourdfpy")


def test_mimic_chain_with_later_master_is_respected() -> None:
    # romeo's finger masters come after their mimics in the tree: Pinocchio's mimic=True fails here.
    path = ERD_ROBOTS / "romeo_description" / "urdf" / "romeo.urdf"
    model = KinematicModel(parse_urdf(path.read_text(encoding="utf-8")))
    assert len(model.mimics) > 0
    q = _random_configs(model, 1, seed=3)[0]
    full = model.joint_values(q)
    for rule in model.mimics.values():
        master = full[model.table.names.index(rule.master)]
        mimic = full[model.table.names.index(rule.joint)]
        assert mimic == pytest.approx(rule.multiplier * master + rule.offset)
