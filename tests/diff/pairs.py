"""Helpers of the diff tests: real robots expanded by upstream xacro, edited as XML, and an independent FK.

No expectation here comes from robotmodel: expansion is the xacro package's, edits are
ElementTree's, and the reference poses are yourdfpy's. ``run`` calls the console script's
``main`` in this process; ``run_process`` starts it.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import xacro
import yourdfpy
from conftest import BUNDLED, ERD_ROBOTS
from robotmodel.cli.main import main

PANDA = ERD_ROBOTS / "panda_description/urdf/panda.urdf"
PANDA_COLLISION = ERD_ROBOTS / "panda_description/urdf/panda_collision.urdf"
UR5 = ERD_ROBOTS / "ur_description/urdf/ur5_robot.urdf"
UR5_LIMITED = ERD_ROBOTS / "ur_description/urdf/ur5_joint_limited_robot.urdf"
PENDULUM = ERD_ROBOTS / "double_pendulum_description/urdf/double_pendulum.urdf"
PENDULUM_CONTINUOUS = ERD_ROBOTS / "double_pendulum_description/urdf/double_pendulum_continuous.urdf"


def expanded(name: str) -> str:
    """A bundled xacro robot expanded by the upstream xacro package."""
    return xacro.process_file(str(BUNDLED / name)).toxml()


def edited(text: str, change: Callable[[ET.Element], None]) -> str:
    """``text`` (URDF XML) after ``change`` edited its root element in place."""
    root = ET.fromstring(text)
    change(root)
    return ET.tostring(root, encoding="unicode")


def element(root: ET.Element, tag: str, name: str) -> ET.Element:
    """The ``<tag name="name">`` child of the robot."""
    found = root.find(f"{tag}[@name='{name}']")
    assert found is not None, f"no {tag} {name}"
    return found


def links_below(text: str, joint: str) -> set[str]:
    """The child link of ``joint`` and every link under it, from the XML's parent/child elements."""
    root = ET.fromstring(text)
    children: dict[str, list[str]] = {}
    for j in root.findall("joint"):
        children.setdefault(j.find("parent").get("link"), []).append(j.find("child").get("link"))  # type: ignore[union-attr]
    start = element(root, "joint", joint).find("child").get("link")  # type: ignore[union-attr]
    below, todo = set(), [start]
    while todo:
        link = todo.pop()
        below.add(link)
        todo.extend(children.get(link, []))
    return below


def zero_poses(text: str) -> dict[str, np.ndarray]:
    """yourdfpy's T_root_link (4x4) of every link with every actuated joint at 0."""
    robot = yourdfpy.URDF.load(io.BytesIO(text.encode()), load_meshes=False, build_collision_scene_graph=False,
                               load_collision_meshes=False)
    robot.update_cfg(np.zeros(robot.num_actuated_joints))
    return {name: robot.get_transform(name, robot.base_link) for name in robot.link_map}


def pose_delta(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    """(mm, deg) between two 4x4 poses: distance of the origins, angle of the relative rotation."""
    moved = float(np.linalg.norm(b[:3, 3] - a[:3, 3])) * 1000.0
    cos = (np.trace(a[:3, :3].T @ b[:3, :3]) - 1.0) / 2.0
    return moved, float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def write(folder: Path, name: str, text: str) -> Path:
    """Write ``text`` to ``folder/name``; returns the path."""
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def run_process(*args: str, cwd: Path, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    """``robotmodel diff ARGS`` as a process."""
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "diff", *args], capture_output=True,
                          text=True, cwd=cwd, input=stdin, check=False)


def run(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``robotmodel diff ARGS`` through the console script's ``main`` in this process (a process costs ~1 s
    of imports on a loaded machine; the exit code, stdout and stderr are the same)."""
    out, err = io.StringIO(), io.StringIO()
    here = Path.cwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = main(["diff", *args])
            except SystemExit as exc:  # argparse's usage errors and --help
                code = exc.code if isinstance(exc.code, int) else 2
    finally:
        os.chdir(here)
    return subprocess.CompletedProcess(["robotmodel", "diff", *args], code, out.getvalue(), err.getvalue())


def run_json(*args: str, cwd: Path) -> tuple[int, dict[str, Any]]:
    """``robotmodel diff ARGS --format json``: exit code and the parsed report."""
    done = run(*args, "--format", "json", cwd=cwd)
    assert done.returncode in (0, 1), done.stderr
    assert done.stderr == ""
    return done.returncode, json.loads(done.stdout)


def changes(report: dict[str, Any], section: str) -> dict[str, dict[str, dict[str, Any]]]:
    """``{new name: {field: change}}`` of a JSON report's section."""
    return {c["new"]: {x["field"]: x for x in c["changes"]} for c in report[section]["changed"]}


def only(report: dict[str, Any], *sections: str) -> None:
    """Assert every section of the report but ``sections`` is empty."""
    for name in ("links", "joints", "materials"):
        if name not in sections:
            assert report[name] == {"added": [], "removed": [], "renamed": [], "changed": []}, name
    if "poses" not in sections:
        assert report["poses"] == []
    if "robot" not in sections:
        assert report["robot"] == []
