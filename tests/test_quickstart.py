"""The README's Quick start, as written, from a fresh clone's root with a non-editable install.

``pip install . && robotmodel demo`` into a plain venv (no system site, so nothing editable
can stand in for the installed copy), run with the clone's root as the current directory:
there the source folder ``robotmodel/`` (without ``cli/`` and ``robots/``, which only the
install maps into it) must not shadow the installed package in any process the demo starts.
The recording is read back with rosbags, not with robotmodel.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO
from procscan import assert_none_left
from rosbags.highlevel import AnyReader


@pytest.mark.slow
def test_quick_start_from_a_fresh_clone_root(tmp_path: Path) -> None:
    if not (REPO / ".git").exists():
        pytest.skip("not a git checkout: nothing to clone (the test clones HEAD, as a new user would)")
    clone, venv = tmp_path / "clone", tmp_path / "venv"
    subprocess.run(["git", "clone", "--quiet", str(REPO), str(clone)], check=True, timeout=120)
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=120)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONSAFEPATH")}
    env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PIP_NO_COMPILE"] = "1"  # no .pyc written at install (a fifth of its time); Python compiles what it imports
    # The README's first command, with the options a test needs (no browser, a short run).
    done = subprocess.run(["bash", "-c", "pip install -q . && robotmodel demo --no-browser --duration 5"],
                          cwd=clone, env=env, capture_output=True, text=True, timeout=900, check=False)
    out = done.stdout + done.stderr
    assert done.returncode == 0, out
    assert "Traceback" not in out and "No module named" not in out, out

    # The venv holds a real (non-editable) copy: the code that ran is not the clone's source folder.
    where = subprocess.run([str(venv / "bin" / "python"), "-c", "import robotmodel.cli.main as m; print(m.__file__)"],
                           cwd=tmp_path, env=env, capture_output=True, text=True, timeout=60, check=True).stdout
    assert where.startswith(str(venv)) and "site-packages" in where, where
    # From the clone's root Python imports the source folder, not the install: the bundled
    # robots and the command line are found there all the same, as the docs' examples need.
    here = subprocess.run([str(venv / "bin" / "python"), "-c",
                           "import robotmodel.robots, robotmodel.cli.main; print(robotmodel.robots.path('diffbot.urdf.xacro'))"],
                          cwd=clone, env=env, capture_output=True, text=True, timeout=60, check=False)
    assert here.returncode == 0 and here.stdout.strip().endswith("diffbot.urdf.xacro"), here.stdout + here.stderr

    port = re.search(r"private bus \(port (\d+),", done.stdout)
    assert port, out
    assert_none_left(port.group(1))
    folders = list(clone.glob("robotmodel-demo-*"))
    assert len(folders) == 1, out
    files = folders[0]
    assert (files / "frames.gv").read_text().startswith("digraph"), out
    assert {"record.log", "robot_state_publisher.log", "view.log"} <= {p.name for p in (files / "logs").iterdir()}
    with AnyReader([files / "demo.mcap"]) as reader:
        topics = {conn.topic for conn, _t, _raw in reader.messages()}
    assert {"/tf", "/tf_static", "/joint_states", "/robot_description", "/odom"} <= topics, topics
    # The offline answer from the recording, in tf2_echo's format.
    answer = done.stdout.split("offline, from the recording", 1)[-1]
    assert re.search(r"^- Translation: \[-?\d+\.\d{3}, -?\d+\.\d{3}, -?\d+\.\d{3}\]$", answer, re.M), out
