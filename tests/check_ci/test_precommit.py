"""The repository's pre-commit hook, installed by pre-commit itself, in a temporary robot repository.

pre-commit builds a virtualenv and pip-installs this repository (its committed HEAD) into it,
which takes minutes: one test, marked slow. The hook is run twice from the same revision, so
the second run reuses the environment: it fails on a broken URDF, then passes once fixed.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO

BROKEN = """<robot name="r">
  <link name="a"/>
  <link name="b"/>
  <link name="c"/>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
</robot>
"""
FIXED = BROKEN.replace('</robot>', '<joint name="k" type="fixed"><parent link="b"/><child link="c"/></joint>\n</robot>')
MACROS = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="arm" params="prefix">
    <link name="${prefix}base"/>
    <link name="${prefix}tool"><inertial><mass value="1"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
    <joint name="${prefix}joint" type="revolute"><parent link="${prefix}base"/><child link="${prefix}tool"/>
      <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  </xacro:macro>
</robot>
"""
ENTRY = """<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:include filename="macros.xacro"/>
  <xacro:arm prefix="$(arg prefix)"/>
</robot>
"""
CONFIG = """[[entry]]
file = "urdf/arm.urdf.xacro"
args = { prefix = "left_" }
"""


def _git(cwd: Path, *words: str) -> str:
    return subprocess.run(["git", *words], cwd=cwd, capture_output=True, text=True, check=True).stdout.strip()


@pytest.mark.slow
def test_hook_fails_on_a_broken_urdf_and_passes_once_fixed(tmp_path: Path) -> None:
    if shutil.which("git") is None or not (REPO / ".git").exists():
        pytest.skip("needs git and a git checkout of robotmodel")
    pytest.importorskip("pre_commit")
    rev = _git(REPO, "rev-parse", "HEAD")
    if not _git(REPO, "ls-tree", "--name-only", rev, ".pre-commit-hooks.yaml"):
        pytest.skip("HEAD does not hold .pre-commit-hooks.yaml yet (the hook is installed from a commit)")
    robot = tmp_path / "robot"
    (robot / "urdf").mkdir(parents=True)
    (robot / "urdf" / "r.urdf").write_text(BROKEN)
    (robot / "urdf" / "macros.xacro").write_text(MACROS)
    (robot / "urdf" / "arm.urdf.xacro").write_text(ENTRY)
    (robot / "robotmodel.toml").write_text(CONFIG)
    (robot / "README.md").write_text("not a robot\n")
    _git(robot, "init", "-q")
    _git(robot, "add", ".")
    # PIP_NO_COMPILE: pip skips writing .pyc files for every installed package (a fifth of the
    # install's time); what the hook runs is the same.
    env = {**os.environ, "PRE_COMMIT_HOME": str(tmp_path / "pre-commit-home"), "PRE_COMMIT_COLOR": "never",
           "PIP_NO_COMPILE": "1"}
    env.pop("VIRTUAL_ENV", None)
    command = [sys.executable, "-m", "pre_commit", "try-repo", str(REPO), "robotmodel-check-urdf",
               "--ref", rev, "--all-files", "--verbose"]

    broken = subprocess.run(command, cwd=robot, env=env, capture_output=True, text=True, timeout=1800, check=False)
    assert broken.returncode == 1, broken.stdout + broken.stderr
    assert "robotmodel check-urdf: error: urdf/r.urdf: Failed to find root link: Two root links found: [a] and [c]" \
        in broken.stdout, broken.stdout
    # The macro-only file went through its entry point with the configured prefix; README.md was not passed.
    assert "robot name is: arm" in broken.stdout and "left_base" in broken.stdout
    assert "2 files checked: 1 passed, 1 failed (1 error, 0 warnings)" in broken.stdout
    assert "macro-only" not in broken.stdout

    (robot / "urdf" / "r.urdf").write_text(FIXED)
    _git(robot, "add", ".")
    fixed = subprocess.run(command, cwd=robot, env=env, capture_output=True, text=True, timeout=1800, check=False)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert "2 files checked: 2 passed, 0 failed (0 errors, 0 warnings)" in fixed.stdout
