"""robotmodel.rospy against real rospy on a private real roscore: the same program, only its import differs.

What is compared: every line on stdout and on stderr (rospy's log format, timestamps masked;
INFO on stdout, WARN/ERROR on stderr, DEBUG hidden by default), parameters read from and
written to the real parameter server (``_param:=`` words, ``~`` names, searchParam,
deleteParam, KeyError), ``__name:=``/``__ns:=``, wait_for_message's timeout text, a one-shot Timer's event, on_shutdown hooks.
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
    real.write_text(text.replace("from robotmodel import rospy", "import rospy")
                    .replace("from robotmodel.msgs.std_msgs.msg import String", "from std_msgs.msg import String"))
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


@pytest.mark.parametrize("variant", ["real", "robotmodel"])
def test_subscriber_latched_publisher_and_spin_returning_on_ctrl_c(ros1: Ros1World, tmp_path: Path,
                                                                   variant: str) -> None:
    source = HERE / "rospy_echo.py"
    if variant == "real":
        path = tmp_path / "real_echo.py"
        path.write_text(source.read_text().replace("from robotmodel import rospy", "import rospy")
                        .replace("from robotmodel.msgs.std_msgs.msg import String", "from std_msgs.msg import String"))
        argv = [SYSTEM_PYTHON, str(path)]
    else:
        argv = [sys.executable, str(source)]
    ros1.env["ROS_VERSION"] = "1"
    node = ros1.start(*argv)
    node.wait_line(r"^\[INFO\] \[\d+\.\d{6}\]: ready$", 60)
    # Latched, and built from its fields: a later real subscriber still gets it.
    echo = ros1.start("rostopic", "echo", "-n", "1", "/echoed")
    echo.wait_line(r'^data: "started"$', 60)
    talker = ros1.start("rostopic", "pub", "-r", "5", "/chatter", "std_msgs/String", "data: hi")
    node.wait_line(r"^\[INFO\] \[\d+\.\d{6}\]: heard hi$", 60)
    talker.kill()
    t0 = time.monotonic()
    os.killpg(node.popen.pid, signal.SIGINT)
    node.wait_line(r"^spin returned True$", 10)
    node.popen.wait(10)
    if variant == "robotmodel":  # real rospy's exit time is its own; only robotmodel's is held to 2 s
        assert time.monotonic() - t0 < 2.0
    assert node.popen.returncode == 0, "\n".join(node.lines)


def test_sim_time_and_rosout_as_real_rospy(ros1: Ros1World, tmp_path: Path) -> None:
    """/use_sim_time: sleeps, Rate, Timer, a backwards /clock and shutdown; each log line also on /rosout.

    The lines are printed in a ROSCONSOLE_FORMAT of their own (node, function, line).
    """
    ros1.tool("rosparam", "set", "/use_sim_time", "true")
    ros1.env["ROS_VERSION"] = "1"
    ros1.env["ROSCONSOLE_FORMAT"] = "${severity} [${time}] ${node} ${function}:${line}: ${message}"
    probe = ros1.start(SYSTEM_PYTHON, str(HERE / "rosout_probe.py"), "/clocked")
    probe.wait_line(r"^ready$", 60)
    source = HERE / "rospy_clock.py"
    real = tmp_path / "real" / source.name  # the same base name: /rosout carries it
    real.parent.mkdir()
    real.write_text(source.read_text().replace("from robotmodel import rospy", "import rospy")
                    .replace("from robotmodel.msgs.rosgraph_msgs.msg import Clock", "from rosgraph_msgs.msg import Clock"))
    outputs, logs = [], []
    for argv in ([SYSTEM_PYTHON, str(real)], [sys.executable, str(source)]):
        seen = len(probe.lines)
        node = ros1.start(*argv)
        node.wait_line(r": tick 3$", 60)
        deadline = time.monotonic() + 30
        while sum("|tick " in line for line in probe.lines[seen:]) < 3 and time.monotonic() < deadline:
            time.sleep(0.05)
        t0 = time.monotonic()
        os.killpg(node.popen.pid, signal.SIGINT)
        node.wait_line(r"^interrupted$", 10)
        node.popen.wait(10)
        if argv[0] == sys.executable:
            assert time.monotonic() - t0 < 2.0
        assert node.popen.returncode == 0, "\n".join(node.lines)
        outputs.append([re.sub(r"^(\w+) \[\d+\.\d{6}, \d+\.\d{6}\] ", r"\1 [W, S] ", line)
                        for line in node.lines if not re.search(r": tick \d+$", line)])
        logs.append({re.sub(r"tick \d+", "tick N", line) for line in probe.lines[seen:] if "|tick " in line
                     or "|once|" in line})
    assert outputs[1] == outputs[0]
    assert logs[1] == logs[0]
    # Checked independently of the real run.
    text = source.read_text().splitlines()
    sim, once = (next(n for n, line in enumerate(text, 1) if call in line)
                 for call in ('rospy.loginfo("sim time', 'rospy.logwarn_once("once")'))
    assert outputs[1] == ["before any /clock 0 0.0", "started True", f"INFO [W, S] /clocked <module>:{sim}: sim time True",
                          "slept True", "rate True", "timer 1 True", "moved back True True",
                          f"WARN [W, S] /clocked <module>:{once}: once", "interrupted"]
    lines = {n for n, text in enumerate(source.read_text().splitlines(), 1) if "tick %d" in text or '"once"' in text}
    assert {int(entry.split("|")[4]) for entry in logs[1]} == lines
    assert all(entry.split("|")[2:4] == ["rospy_clock.py", "<module>"] for entry in logs[1])
    assert {entry.split("|")[5] for entry in logs[1]} == {"/clock,/rosout"}
