"""The rospy tutorial programs of examples/ on a real ROS 1 master, as robotmodel's and as real rospy's.

Each program is one text; its real variant differs only in its import lines (see
tests/ros1programs.py) and runs under Debian's rospy, with turtlesim and nav_msgs built by
genpy (ros1_msggen.py). Observed by real ROS 1 (rospy listeners, ``rostopic echo``) and by
robotmodel's listener, in mixed pairs: each test runs some programs one way and the others the
other way, so every program meets the real library on the other end. Expected values are
derived here from the programs' inputs (scipy for the rotation, the follow law from the
turtles' start poses, the arc for the diff drive), not from a run. robotmodel's programs must
end within 2 s of Ctrl-C (every test), of SIGTERM and of an uncaught exception (the last test).
"""

from __future__ import annotations

import math
import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest
from ros1helpers import GroupProc, Ros1World
from ros1programs import HERE, interrupt, probe, program
from scipy.spatial.transform import Rotation

STATIC_ARGS = ("1.0", "2.0", "3.0", "0.1", "0.2", "0.3")
TURTLES = "_turtles:=[[turtle1, 5.544445, 5.544445, 0.0], [turtle2, 4.0, 2.0, 0.0]]"


def start(ros1: Ros1World, argv: list[str]) -> GroupProc:
    return ros1.start(*argv)


@pytest.fixture
def world(ros1: Ros1World, ros1_msgs: Path) -> Ros1World:
    """The test's roscore, with ROS_VERSION=1 (robotmodel picks the ROS 1 wire) and the built messages."""
    ros1.env["ROS_VERSION"] = "1"
    ros1.env["PYTHONPATH"] = str(ros1_msgs)
    return ros1


def poses(proc: GroupProc, source: str) -> list[list[float]]:
    """``x y z qx qy qz qw`` of each ``pose SOURCE`` line a tf_probe printed."""
    return [[float(v) for v in line.split()[3:]] for line in list(proc.lines) if line.startswith(f"pose {source} ")]


def wait_poses(proc: GroupProc, source: str, count: int) -> list[list[float]]:
    deadline = time.monotonic() + 60
    while len(poses(proc, source)) < count and time.monotonic() < deadline:
        time.sleep(0.05)
    got = poses(proc, source)
    assert len(got) >= count, f"{source}: " + "\n".join(proc.lines[-20:])
    return got


def test_static_broadcaster(world: Ros1World, tmp_path: Path) -> None:
    """Real and robotmodel static broadcasters, each seen by a real and a robotmodel listener started after them."""
    ours = start(world, program("rospy_static_broadcaster.py", "robotmodel", tmp_path, "__name:=static_ours",
                                "static_ours", *STATIC_ARGS))
    real = start(world, program("rospy_static_broadcaster.py", "real", tmp_path, "__name:=static_real",
                                "static_real", *STATIC_ARGS))
    for proc in (ours, real):
        proc.wait_line(r"\]: spinning until shut down: world -> static_\w+$", 60)
    # Listeners that join late: /tf_static is latched.
    listeners = [start(world, probe("tf_probe.py", variant, tmp_path, "world", "static_real", "static_ours"))
                 for variant in ("real", "robotmodel")]
    expected = [1.0, 2.0, 3.0, *Rotation.from_euler("xyz", [0.1, 0.2, 0.3]).as_quat()]
    seen = [wait_poses(listener, source, 1)[0] for listener in listeners for source in ("static_real", "static_ours")]
    assert seen == [seen[0]] * 4  # the same arithmetic in both: the same bits
    assert seen[0] == pytest.approx(expected, abs=1e-12)
    for listener in listeners:
        listener.kill()
    interrupt(ours, "robotmodel")
    interrupt(real, "real")


def pose_rows(echo: GroupProc) -> list[list[float]]:
    """x, y, theta, linear_velocity, angular_velocity of each row ``rostopic echo -p`` printed."""
    return [[float(v) for v in line.split(",")[1:]] for line in list(echo.lines) if line[:1].isdigit()]


@pytest.mark.parametrize("sim", ["robotmodel", "real"])
def test_turtle_follow(world: Ros1World, tmp_path: Path, sim: str) -> None:
    """turtle2 follows turtle1: simulator, broadcasters and follower split between real rospy and robotmodel."""
    other = "real" if sim == "robotmodel" else "robotmodel"
    procs = [
        (sim, start(world, program("rospy_turtlesim.py", sim, tmp_path, TURTLES))),
        (other, start(world, program("rospy_turtle_tf2_broadcaster.py", other, tmp_path,
                                     "__name:=turtle1_tf2_broadcaster", "_turtle:=turtle1"))),
        (sim, start(world, program("rospy_turtle_tf2_broadcaster.py", sim, tmp_path,
                                   "__name:=turtle2_tf2_broadcaster", "_turtle:=turtle2"))),
    ]
    echo = world.start("rostopic", "echo", "-p", "/turtle2/pose")
    echo.wait_line(r"^\d+,4\.0,2\.0,0\.0,0\.0,0\.0$", 60)  # turtle2 waits at its start pose
    procs.append((other, start(world, program("rospy_turtle_tf2_listener.py", other, tmp_path))))
    # The follower's first command, from the start poses (float32, as turtlesim's Pose carries them).
    x1 = float(np.float32(5.544445))
    dx, dy = x1 - 4.0, x1 - 2.0
    first = [4.0, 2.0, 0.0, 0.5 * math.hypot(dx, dy), 4 * math.atan2(dy, dx)]
    deadline = time.monotonic() + 60
    while not any(row[3] for row in pose_rows(echo)) and time.monotonic() < deadline:
        time.sleep(0.05)
    moving = [row for row in pose_rows(echo) if row[3]]
    assert moving, "\n".join(echo.lines[-10:])
    # The first row with a command may already show the first step of it.
    assert moving[0][3:] == pytest.approx(first[3:], abs=1e-5)
    deadline = time.monotonic() + 60
    while math.dist(pose_rows(echo)[-1][:2], (x1, x1)) > 0.5 and time.monotonic() < deadline:
        time.sleep(0.1)
    assert math.dist(pose_rows(echo)[-1][:2], (x1, x1)) <= 0.5, "turtle2 did not reach turtle1"
    echo.kill()
    for variant, proc in reversed(procs):
        interrupt(proc, variant)


def on_arc(pose: list[float], radius: float) -> list[float]:
    """The pose the exact arc gives for this pose's heading: x = r·sin(yaw), y = r·(1 - cos(yaw))."""
    yaw = 2 * math.atan2(pose[5], pose[6])
    return [radius * math.sin(yaw), radius * (1 - math.cos(yaw)), 0.0, 0.0, 0.0, pose[5], pose[6]]


def test_odometry_to_tf(world: Ros1World, tmp_path: Path) -> None:
    """A diff drive's odometry as TF: robotmodel's simulator to real rospy's odom_to_tf, and the other way round."""
    procs = []
    for suffix, sim, relay in (("a", "robotmodel", "real"), ("b", "real", "robotmodel")):
        procs.append((sim, start(world, program("rospy_diff_drive.py", sim, tmp_path, f"__name:=diff_drive_{suffix}",
                                                f"odom:=odom_{suffix}", f"_base_frame:=base_{suffix}",
                                                "_linear:=0.5", "_angular:=0.25"))))
        procs.append((relay, start(world, program("rospy_odom_to_tf.py", relay, tmp_path,
                                                  f"__name:=odom_to_tf_{suffix}", f"odom:=odom_{suffix}"))))
    listener = start(world, probe("tf_probe.py", "real", tmp_path, "odom", "base_a", "base_b"))
    for source in ("base_a", "base_b"):
        seen = wait_poses(listener, source, 5)
        for pose in seen:
            assert pose == pytest.approx(on_arc(pose, 0.5 / 0.25), abs=1e-9), source
        assert 2 * math.atan2(seen[-1][5], seen[-1][6]) > 0  # it drives the arc forward (counter-clockwise)
    listener.kill()
    for variant, proc in reversed(procs):
        interrupt(proc, variant)


# Each program, the node it registers and a registration that shows its main loop is near.
PROGRAMS = [
    ("rospy_tf2_broadcaster.py", (), "/carrot_broadcaster", "pub /tf"),
    ("rospy_tf2_listener.py", (), "/carrot_listener", "sub /tf"),
    ("rospy_static_broadcaster.py", ("frame", *STATIC_ARGS), "/static_tf2_broadcaster", "pub /tf_static"),
    ("rospy_turtlesim.py", (TURTLES,), "/turtlesim", "pub /turtle2/pose"),
    ("rospy_turtle_tf2_broadcaster.py", ("_turtle:=turtle1",), "/tf2_turtle_broadcaster", "sub /turtle1/pose"),
    ("rospy_turtle_tf2_listener.py", (), "/tf2_turtle_listener", "pub /turtle2/cmd_vel"),
    ("rospy_diff_drive.py", ("_linear:=0.5",), "/diff_drive", "pub /odom"),
    ("rospy_odom_to_tf.py", (), "/odom_to_tf", "sub /odom"),
]


@pytest.mark.parametrize("ending", ["exception", "SIGTERM"])
def test_every_program_ends_within_2_s(world: Ros1World, tmp_path: Path, ending: str) -> None:
    """All programs running together (listeners live, peers connected); each is ended alone and must go in 2 s."""
    running = []
    for name, args, node, registration in PROGRAMS:
        argv = program(name, "robotmodel", tmp_path, *args)
        if ending == "exception":
            argv.insert(1, str(HERE / "raise_on_usr1.py"))
        running.append((start(world, argv), node, registration))
    deadline = time.monotonic() + 90
    for proc, node, registration in running:
        while registration not in world.registrations_of(node) and time.monotonic() < deadline:
            assert proc.popen.poll() is None, "\n".join(proc.lines)
            time.sleep(0.1)
        assert registration in world.registrations_of(node), (node, world.registrations_of(node))
    for proc, node, _ in running:
        t0 = time.monotonic()
        os.killpg(proc.popen.pid, signal.SIGUSR1 if ending == "exception" else signal.SIGTERM)
        try:
            proc.popen.wait(10)
        except subprocess.TimeoutExpired:
            pytest.fail(f"{node} still running 10 s after the {ending}:\n" + "\n".join(proc.lines[-20:]))
        took = time.monotonic() - t0
        assert took < 2.0, f"{node}: {took:.2f} s\n" + "\n".join(proc.lines[-20:])
        if ending == "exception":
            assert proc.popen.returncode == 1
            proc.wait_line(r"^RuntimeError: injected$", 5)
        else:
            assert proc.popen.returncode == 0, "\n".join(proc.lines)
