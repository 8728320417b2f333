"""Inputs that used to break forward kinematics: long chains, tiny axes, odd names.

The long-chain bound: ``robotmodel fk`` on a 3,000-joint serial chain must peak below
``FK_RSS_BOUND`` resident memory (measured: about 50 MiB, as fk never imports Pinocchio;
Pinocchio's Data for such a chain would need about 1.7 TB).
"""

from __future__ import annotations

import math
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from robotmodel.errors import KinematicsError
from robotmodel.kinematics import PINOCCHIO_DATA_LIMIT, KinematicModel, KinematicState, batch_link_matrices
from robotmodel.model import parse_urdf

FK_RSS_BOUND = 160 * 2**20


def chain_urdf(n: int) -> str:
    """A serial chain of ``n`` revolute joints, each 0.1 m up and turned 0.1 rad about x."""
    links = "".join(f'<link name="l{i}"/>' for i in range(n + 1))
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        '<origin xyz="0 0 0.1" rpy="0.1 0 0"/><axis xyz="0 0 1"/>'
        '<limit effort="1" velocity="1" lower="-3" upper="3"/></joint>'
        for i in range(n))
    return f'<robot name="chain">{links}{joints}</robot>'


def _peak_rss_of(argv: list[str]) -> tuple[int, subprocess.CompletedProcess[str]]:
    """Run ``argv`` from a fresh interpreter whose only child it is; its peak RSS in bytes."""
    probe = textwrap.dedent("""
        import json, resource, subprocess, sys
        # A ceiling on address space keeps a regression from exhausting the machine.
        limit = 6 * 2**30
        def cap():
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        r = subprocess.run(sys.argv[1:], capture_output=True, text=True, preexec_fn=cap)
        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
        print(json.dumps([peak, r.returncode, r.stdout[-2000:], r.stderr[-4000:]]))
    """)
    import json

    out = subprocess.run([sys.executable, "-c", probe, *argv], capture_output=True, text=True,
                         check=True, timeout=300)
    peak, code, stdout, stderr = json.loads(out.stdout)
    return peak, subprocess.CompletedProcess(argv, code, stdout, stderr)


def test_fk_command_on_a_3000_joint_chain_stays_in_bounded_memory(tmp_path: Path) -> None:
    path = tmp_path / "chain.urdf"
    path.write_text(chain_urdf(3000), encoding="utf-8")
    peak, result = _peak_rss_of([sys.executable, "-m", "robotmodel.cli.main", "fk", str(path),
                                 "--link", "l3000", "--joint", "j0=0.5"])
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    assert "l3000:" in result.stdout
    assert peak < FK_RSS_BOUND, f"peak RSS {peak / 2**20:.0f} MiB"


def test_long_chain_poses_agree_and_pinocchio_is_refused_by_name() -> None:
    n = 3000
    model = KinematicModel(parse_urdf(chain_urdf(n)))
    state = KinematicState(model)
    q = np.random.default_rng(4).uniform(-3, 3, model.nv)
    single = state.update(q).link_matrices()
    np.testing.assert_allclose(batch_link_matrices(model, q[None, :])[0], single, atol=1e-9)
    # With every joint at zero, link k sits at 0.1·Σ_{i<k} Rx(0.1·i)·ẑ = 0.1·Σ (0, -sin 0.1i, cos 0.1i).
    zero = state.update(np.zeros(n)).link_matrix("l1000")
    i = np.arange(1000) * 0.1
    expected = 0.1 * np.array([0.0, -np.sin(i).sum(), np.cos(i).sum()])
    np.testing.assert_allclose(zero[:3, 3], expected, atol=1e-9)
    with pytest.raises(KinematicsError, match=r"(?=.*Pinocchio)(?=.*3000)(?=.*MiB limit)"):
        state.jacobian("l10")
    assert model.pinocchio_data_bytes > PINOCCHIO_DATA_LIMIT


def test_small_models_keep_pinocchio_jacobians() -> None:
    model = KinematicModel(parse_urdf(chain_urdf(20)))
    assert model.pinocchio_data_bytes < PINOCCHIO_DATA_LIMIT
    assert KinematicState(model).jacobian("l20").shape == (6, 20)


@pytest.mark.parametrize("scale", [1e-300, 1e-320, 1e300])
def test_tiny_or_huge_axis_is_normalised_without_underflow(scale: float) -> None:
    text = (f'<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute">'
            f'<parent link="a"/><child link="b"/><axis xyz="0 {scale!r} {scale!r}"/>'
            '<limit effort="1" velocity="1" lower="-3" upper="3"/></joint></robot>')
    model = KinematicModel(parse_urdf(text))
    state = KinematicState(model).update({"j": 1.0})
    # Rotation by 1 rad about (0, 1, 1)/√2.
    axis = np.array([0.0, 1.0, 1.0]) / math.sqrt(2.0)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    expected = np.eye(3) + math.sin(1.0) * k + (1 - math.cos(1.0)) * k @ k
    np.testing.assert_allclose(state.link_matrix("b")[:3, :3], expected, atol=1e-12)
    np.testing.assert_allclose(batch_link_matrices(model, [[1.0]])[0, 1, :3, :3], expected, atol=1e-12)
    np.testing.assert_allclose(state.jacobian("b")[3:, 0], axis, atol=1e-12)


def test_tab_in_a_link_name_reaches_fk(tmp_path: Path) -> None:
    text = ('<robot name="r"><link name="a&#9;b"/><link name="c"/><joint name="j" type="revolute">'
            '<parent link="a&#9;b"/><child link="c"/><origin xyz="1 0 0"/>'
            '<limit effort="1" velocity="1" lower="-1" upper="1"/></joint></robot>')
    model = KinematicModel(parse_urdf(text))
    assert model.root == "a\tb"
    state = KinematicState(model)
    np.testing.assert_allclose(state.link_matrix("c")[:3, 3], [1, 0, 0])
    assert state.jacobian("c").shape == (6, 1)
    path = tmp_path / "tab.urdf"
    path.write_text(text, encoding="utf-8")
    result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "fk", str(path), "--format", "json"],
                            capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    assert '"a\\tb"' in result.stdout
