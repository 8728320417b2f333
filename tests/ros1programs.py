"""tests/standins: the tutorial programs of examples/ as robotmodel's and as real rospy's: the same text, only the imports differ.

:func:`program` gives the argv running ``examples/<name>`` either way. The real variant is
written under ``tmp_path/real/`` with the same base name (``/rosout`` and tracebacks carry it)
and is run by Debian's Python with the message packages Debian lacks (turtlesim, nav_msgs)
built by ros1_msggen.py on its path; :func:`real_variant` checks that nothing but import lines
changed. :func:`robotmodel_variant` is the other way round, for the rospy probes of this directory.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from ros1helpers import SYSTEM_PYTHON, GroupProc

HERE = Path(__file__).resolve().parent / "standins"
EXAMPLES = HERE.parent.parent / "examples"

_OURS_RX = [
    (re.compile(r"^from robotmodel import rospy, tf2_ros$", re.M), "import rospy\nimport tf2_ros"),
    (re.compile(r"^from robotmodel import rospy$", re.M), "import rospy"),
    (re.compile(r"^from robotmodel\.msgs\.(\w+)\.msg import ", re.M), r"from \1.msg import "),
]


def code_lines(text: str) -> list[str]:
    """The lines that are not imports."""
    return [line for line in text.splitlines() if not line.startswith(("import ", "from "))]


def real_variant(text: str) -> str:
    """The program with rospy's imports in place of robotmodel's; nothing else may differ."""
    real = text
    for rx, theirs in _OURS_RX:
        real = rx.sub(theirs, real)
    assert real != text and "robotmodel" not in "\n".join(
        line for line in real.splitlines() if line.startswith(("import ", "from "))), "imports left unported"
    assert code_lines(real) == code_lines(text), "only the import lines may differ"
    return real


def robotmodel_variant(text: str) -> str:
    """A real rospy program with robotmodel's imports instead."""
    ours = text.replace("import rospy\nimport tf2_ros\n", "from robotmodel import rospy, tf2_ros\n")
    ours = re.sub(r"^import rospy$", "from robotmodel import rospy", ours, flags=re.M)
    ours = re.sub(r"^from (\w+_msgs)\.msg import ", r"from robotmodel.msgs.\1.msg import ", ours, flags=re.M)
    assert code_lines(ours) == code_lines(text)
    return ours


def program(name: str, variant: str, tmp_path: Path, *args: str) -> list[str]:
    """The argv running ``examples/<name> ARGS`` as ``variant`` ("real" or "robotmodel")."""
    path = EXAMPLES / name
    if variant == "robotmodel":
        return [sys.executable, str(path), *args]
    out = tmp_path / "real" / name
    out.parent.mkdir(exist_ok=True)
    out.write_text(real_variant(path.read_text()))
    return [SYSTEM_PYTHON, str(out), *args]


def probe(name: str, variant: str, tmp_path: Path, *args: str) -> list[str]:
    """The argv of a rospy probe of this directory (written for real rospy) as ``variant``."""
    path = HERE / name
    if variant == "real":
        return [SYSTEM_PYTHON, str(path), *args]
    out = tmp_path / "ours" / name
    out.parent.mkdir(exist_ok=True)
    out.write_text(robotmodel_variant(path.read_text()))
    return [sys.executable, str(out), *args]


def interrupt(proc: GroupProc, variant: str) -> None:
    """SIGINT to the program (as Ctrl-C to its process group): robotmodel's must end, with status 0, within 2 s.

    Real rospy's are only reaped: its listener at times stays for more than 10 s after SIGINT
    (seen in about one run in five), which is rospy's own behaviour and not what is compared here.
    """
    t0 = time.monotonic()
    os.killpg(proc.popen.pid, signal.SIGINT)
    if variant == "real":
        proc.kill()
        return
    try:
        proc.popen.wait(10)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{proc.argv} still running 10 s after SIGINT:\n" + "\n".join(proc.lines[-20:]))
    assert time.monotonic() - t0 < 2.0, proc.argv
    assert proc.popen.returncode == 0, "\n".join(proc.lines)
