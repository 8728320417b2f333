"""check-urdf and urdf-to-graphviz against urdfdom's own binaries on example-robot-data's 69 robots.

The reference output is produced in the same run by the real ``check_urdf`` and
``urdf_to_graphviz`` (cmeel-urdfdom); ours must match it byte for byte.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, ERD_ROBOTS, URDF_TO_GRAPHVIZ_BIN, erd_urdfs, urdfdom_env
from robotmodel.cli.main import main

from robotmodel.check import lint, to_graphviz
from robotmodel.model import Mesh, parse_urdf

ROBOTS = erd_urdfs()
# An empty <robot> without a name: urdfdom rejects it, so must we.
EMPTY_ROBOT = "ur_description/urdf/ur3.urdf"
# Its finger joints mimic joints that do not exist (index_q1, not Left_index_q1): urdfdom
# says nothing, RSP would silently drop them; we reject it on purpose.
MIMIC_MISSING = "alex_description/urdf/alex_psyonic_hands.urdf"
# Meshes given as file:///usr/Romeo/... absolute paths that the package does not ship.
ABSENT_MESHES = "romeo_description/urdf/romeo_laas_small.urdf"


def _id(path: Path) -> str:
    return str(path.relative_to(ERD_ROBOTS))


def test_all_robots_found() -> None:
    assert len(ROBOTS) == 69


@pytest.mark.parametrize("path", ROBOTS, ids=_id)
def test_check_urdf_matches_urdfdom(path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    ref = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                         env=urdfdom_env(), check=False)
    code = main(["check-urdf", str(path)])
    out, err = capsys.readouterr()
    if _id(path) == EMPTY_ROBOT:
        assert ref.returncode != 0
        assert "No name given for the robot." in ref.stderr
        assert code == 1
        assert out == ""
        assert err.count("\n") == 1 and "No name given for the robot." in err
    elif _id(path) == MIMIC_MISSING:
        assert ref.returncode == 0
        assert code == 1
        assert out == ""
        assert "[mimic-missing-joint] joint [Left_index_q2]: mimics joint [index_q1]" in err
    else:
        assert ref.returncode == 0, ref.stderr
        assert code == 0, err
        assert out == ref.stdout


@pytest.mark.parametrize("path", [p for p in ROBOTS if _id(p) != EMPTY_ROBOT], ids=_id)
def test_graphviz_matches_urdfdom(path: Path, tmp_path: Path) -> None:
    # Without `dot` on PATH urdfdom writes only the .gv (and fails to make the PDF quietly).
    env = urdfdom_env()
    env["PATH"] = "/nonexistent"
    subprocess.run([str(URDF_TO_GRAPHVIZ_BIN), str(path), "ref"], capture_output=True, env=env,
                   cwd=tmp_path, check=True)
    desc = parse_urdf(path.read_text(encoding="utf-8"))
    assert to_graphviz(desc) == (tmp_path / "ref.gv").read_text(encoding="utf-8")


@pytest.mark.parametrize("path", [p for p in ROBOTS if _id(p) not in (EMPTY_ROBOT, ABSENT_MESHES)], ids=_id)
def test_meshes_resolve(path: Path) -> None:
    desc = parse_urdf(path.read_text(encoding="utf-8"))
    missing = [str(f) for f in lint(desc, base_dir=path.parent) if f.code == "mesh-not-found"]
    assert missing == []


def test_absent_meshes_reported() -> None:
    path = ERD_ROBOTS / ABSENT_MESHES
    desc = parse_urdf(path.read_text(encoding="utf-8"))
    missing = [f for f in lint(desc, base_dir=path.parent) if f.code == "mesh-not-found"]
    uris = {v.geometry.filename for link in desc.links for v in link.visuals if isinstance(v.geometry, Mesh)}
    assert missing
    assert all(not Path(u.removeprefix("file://")).exists() for u in uris)


def test_urdfdom_material_warnings_are_our_findings() -> None:
    # urdfdom logs "link 'L' material 'M' undefined." (twice per visual); we report each once.
    path = ERD_ROBOTS / "talos_data/robots/talos_reduced_corrected.urdf"
    ref = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                         env=urdfdom_env(), check=False)
    theirs = {line.split("'")[1] for line in ref.stderr.splitlines() if "undefined" in line}
    desc = parse_urdf(path.read_text(encoding="utf-8"))
    findings = lint(desc, base_dir=path.parent)
    ours = {f.element[len("link [") : -1] for f in findings if f.code == "material-undefined"}
    assert theirs == ours == {"wrist_left_ft_tool_link", "wrist_right_ft_tool_link"}
