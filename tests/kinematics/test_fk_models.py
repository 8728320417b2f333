"""FK of the bundled seeds and the corpus entries vs hand-composed URDF math and yourdfpy (1e-9)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import robotmodel.robots
import yourdfpy
from conftest import CORPUS
from handfk import HandFK
from manifest import entries

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import parse_urdf
from robotmodel.xacro import expand

CASES = [(name, robotmodel.robots.path(name), {}) for name in robotmodel.robots.names()] + [
    (f"{e.number}-{Path(e.path).name}", CORPUS / e.path, e.args) for e in (entries(CORPUS) if CORPUS.is_dir() else [])
]


@pytest.mark.parametrize(("label", "path", "args"), CASES, ids=[c[0] for c in CASES])
def test_fk_matches_references(label: str, path: Path, args: dict[str, str], tmp_path: Path) -> None:
    text = expand(path, args)
    model = KinematicModel(parse_urdf(text))
    state = KinematicState(model)
    hand = HandFK(text)
    urdf_file = tmp_path / "robot.urdf"
    urdf_file.write_text(text, encoding="utf-8")
    yd = yourdfpy.URDF.load(str(urdf_file), load_meshes=False, build_collision_scene_graph=False,
                            load_collision_meshes=False)
    rng = np.random.default_rng(len(label))
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    for q in rng.uniform(lo, hi, (20, model.nv)):
        state.update(q)
        ours = state.link_matrices()
        values = dict(zip(model.variables, q, strict=True))
        reference = hand.poses(values)
        yd.update_cfg({n: values[n] for n in yd.actuated_joint_names if n in values})
        for i, link in enumerate(model.link_names):
            np.testing.assert_allclose(ours[i], reference[link], atol=1e-9, err_msg=f"{link} vs hand math")
            np.testing.assert_allclose(ours[i], yd.get_transform(link, yd.base_link), atol=1e-9,
                                       err_msg=f"{link} vs yourdfpy")
