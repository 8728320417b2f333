"""robotmodel.rospy against real rospy on a private real roscore: the same program, only its import differs.

What is compared: every line on stdout and on stderr (rospy's log format, timestamps masked;
INFO on stdout, WARN/ERROR on stderr, DEBUG hidden by default), parameters read from and
written to the real parameter server (``_param:=`` words, ``~`` names, searchParam,
deleteParam, KeyError), ``__name:=``/``__ns:=``, on_shutdown hooks.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from ros1helpers import SYSTEM_PYTHON, Ros1World

HERE = Path(__file__).resolve().parent
PROGRAM = HERE / "rospy_basics.py"
WORDS = ["__name:=renamed", "__ns:=/r1", "_rate:=20"]


def run(ros1: Ros1World, argv: list[str]) -> tuple[list[str], list[str]]:
    env = dict(ros1.env, ROS_VERSION="1")
    done = subprocess.run([*argv, *WORDS], env=env, capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 0, done.stdout + done.stderr

    def masked(text: str) -> list[str]:
        return [re.sub(r"^\[(\w+)\] \[\d+\.\d{6}\]: ", r"[\1] [T]: ", line) for line in text.splitlines()]

    return masked(done.stdout), masked(done.stderr)


def test_same_program_same_output_and_parameter_server(ros1: Ros1World, tmp_path: Path) -> None:
    subprocess.run(["rosparam", "set", "/r1/shared", "3"], env=ros1.env, check=True, timeout=60)
    real = tmp_path / "real_basics.py"
    text = PROGRAM.read_text()
    real.write_text(text.replace("from robotmodel import rospy", "import rospy"))
    theirs = run(ros1, [SYSTEM_PYTHON, str(real)])
    got = subprocess.run(["rosparam", "get", "/r1/renamed/rate"], env=ros1.env, capture_output=True, text=True,
                         timeout=60, check=True).stdout.strip()
    assert got == "20"
    subprocess.run(["rosparam", "delete", "/r1/renamed/rate"], env=ros1.env, check=True, timeout=60)
    ours = run(ros1, [sys.executable, str(PROGRAM)])
    assert ours == theirs
    # Checked independently of the real run, so that a shared mistake cannot pass.
    assert ours[0][:2] == ["name /r1/renamed", "private 20"]
    assert "[INFO] [T]: info 1" in ours[0]
    assert ours[1] == ["[WARN] [T]: warn", "[ERROR] [T]: err"]
    # Ours wrote the private parameter to the real parameter server too.
    got = subprocess.run(["rosparam", "get", "/r1/renamed/rate"], env=ros1.env, capture_output=True, text=True,
                         timeout=60, check=True).stdout.strip()
    assert got == "20"
