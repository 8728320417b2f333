"""The rospy tf2 tutorial programs, run twice on a real ROS 1 master: with real rospy/tf2_ros and with robotmodel's.

One source text per program (examples/rospy_tf2_broadcaster.py, examples/rospy_tf2_listener.py);
the real-ROS variant differs only in its import lines, and is run by Debian's /usr/bin/python3.
What is compared is what can be observed: the poses a real rospy tf2_ros listener
(tf_probe.py) receives, checked against the broadcaster's formula (a frame circling at 2 m,
one turn per 10 s, angle = stamp * pi / 5), the lines the listener prints (LookupException
caught first when started before the broadcaster, then the carrot's pose), and that each
of robotmodel's programs ends within 2 s of SIGINT with status 0 (SIGTERM and an uncaught exception:
test_ros1_tutorials.py).
"""

from __future__ import annotations

import itertools
import math
import re
import time
from pathlib import Path

import pytest
from ros1helpers import SYSTEM_PYTHON, GroupProc, Ros1World
from ros1programs import interrupt, program

PROBE = Path(__file__).resolve().parent / "tf_probe.py"


def start(ros1: Ros1World, argv: list[str]) -> GroupProc:
    # As a sourced ROS 1 shell runs things: robotmodel picks the ROS 1 wire from these, no flag.
    ros1.env["ROS_VERSION"] = "1"
    return ros1.start(*argv)


def carrot_pose(angle: float) -> tuple[float, ...]:
    """The broadcaster's pose at ``angle``, from the circle's definition (x, y, z, qx, qy, qz, qw)."""
    return (2.0 * math.cos(angle), 2.0 * math.sin(angle), 0.0, 0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2))


@pytest.mark.parametrize("variant", ["real", "robotmodel"])
def test_broadcaster_to_a_real_rospy_listener(ros1: Ros1World, tmp_path: Path, variant: str) -> None:
    probe = ros1.start(SYSTEM_PYTHON, str(PROBE), "world", "carrot")
    probe.wait_line(r"^ready$", 60)
    broadcaster = start(ros1, program("rospy_tf2_broadcaster.py", variant, tmp_path))
    probe.wait_line(r"^pose ", 60)
    deadline = time.monotonic() + 30
    while probe.count(r"^pose ") < 5 and time.monotonic() < deadline:
        time.sleep(0.05)
    poses = [line.split()[2:] for line in probe.lines if line.startswith("pose carrot ")]
    assert len(poses) >= 5, "\n".join(probe.lines)
    for words in poses:
        stamp_ns, values = int(words[0]), [float(v) for v in words[1:]]
        assert values == pytest.approx(carrot_pose(stamp_ns / 1e9 * math.pi / 5.0), abs=1e-6), words
    stamps = [int(words[0]) for words in poses]
    gaps = [(b - a) / 1e9 for a, b in itertools.pairwise(stamps)]
    assert all(0.05 < g < 1.0 for g in gaps), gaps  # a 10 Hz stream
    assert broadcaster.popen.poll() is None
    interrupt(broadcaster, variant)


@pytest.mark.parametrize("variant", ["real", "robotmodel"])
def test_listener_started_first_catches_lookup_exception_then_follows_the_real_broadcaster(
        ros1: Ros1World, tmp_path: Path, variant: str) -> None:
    listener = start(ros1, program("rospy_tf2_listener.py", variant, tmp_path))
    waiting = listener.wait_line(r"\[INFO\] \[[0-9.]+\]: no carrot yet: (\w+)$", 60)
    # tf2_ros's buffer raises the lookup's own error after the timeout: never TimeoutException.
    assert waiting.group(1) == "LookupException"
    broadcaster = start(ros1, program("rospy_tf2_broadcaster.py", "real", tmp_path))
    listener.wait_line(r"carrot -?\d", 60)
    deadline = time.monotonic() + 30
    while listener.count(r"carrot -?\d") < 5 and time.monotonic() < deadline:
        time.sleep(0.05)
    seen = [m for line in listener.lines if (m := re.search(r"\]: carrot (\S+) (\S+) (\S+) (\S+)$", line))]
    assert len(seen) >= 5, "\n".join(listener.lines)
    for m in seen:
        x, y, qz, qw = (float(v) for v in m.groups())
        angle = math.atan2(y, x)
        assert math.hypot(x, y) == pytest.approx(2.0, abs=1e-6)
        # The broadcaster's angle grows without bound: its half-angle quaternion is this one or its negation.
        sign = 1.0 if qw * math.cos(angle / 2) + qz * math.sin(angle / 2) > 0 else -1.0
        assert (qz, qw) == pytest.approx((sign * math.sin(angle / 2), sign * math.cos(angle / 2)), abs=1e-6)
    # The exceptions came before any pose, and only LookupException.
    first_pose = next(i for i, line in enumerate(listener.lines) if re.search(r"\]: carrot -?\d", line))
    caught = {m.group(1) for line in listener.lines[:first_pose] if (m := re.search(r"no carrot yet: (\w+)", line))}
    assert caught == {"LookupException"}
    interrupt(listener, variant)
    interrupt(broadcaster, "real")
