"""Two robots in namespaces /r1 and /r2 on one bus, as real processes: separate joint states, one /tf.

As in ROS 2: robot_state_publisher and joint_state_publisher use relative topic names
(joint_states, robot_description, source_list topics), which land under the node's
namespace; /tf and /tf_static are absolute and shared, told apart by --frame-prefix.
"""

from __future__ import annotations

import math
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from robotmodel.bus import Node
from robotmodel.errors import TransformException
from robotmodel.msgs import Header, JointState, stamp
from robotmodel.tf import Buffer, Time
from robotmodel.tf_ros import TransformListener

Q1, Q2 = 0.3, -0.7


def tool_pose(q: float, x0: float = 0.0) -> tuple[tuple[float, float, float], tuple[float, float, float, float]]:
    """The tool in base_link (or in world, base_link at x0), from the robot's hand values (see conftest)."""
    return ((x0 + 0.25 * math.cos(q), 0.25 * math.sin(q), 0.5), (0.0, 0.0, math.sin(q / 2), math.cos(q / 2)))


def pose(buffer: Buffer, target: str, source: str):
    t = buffer.lookup_transform(target, source, Time()).transform
    return ((t.translation.x, t.translation.y, t.translation.z),
            (t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w))


def wait_pose(buffer: Buffer, target: str, source: str, expected, timeout: float = 40.0, tick=None):
    """Wait until ``source`` in ``target`` equals ``expected`` to 1e-9; fail with what was seen."""
    deadline = time.monotonic() + timeout
    last: object = None
    while time.monotonic() < deadline:
        if tick is not None:
            tick()
        try:
            last = pose(buffer, target, source)
        except TransformException as exc:
            last = exc
        else:
            if np.allclose(last[0], expected[0], atol=1e-9) and np.allclose(last[1], expected[1], atol=1e-9):
                return last
        time.sleep(0.05)
    pytest.fail(f"{target} <- {source}: expected {expected}, last seen {last}\n{buffer.all_frames_as_string()}")


def topic_list(live, expected: set[str], timeout: float = 40.0) -> set[str]:
    """``robotmodel topic list`` (a process) until it shows ``expected``; returns its last answer."""
    deadline = time.monotonic() + timeout
    while True:
        done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "list", "--spin-time", "1"],
                              env=live.env, capture_output=True, text=True, timeout=60, check=False)
        assert done.returncode == 0, done.stderr
        topics = set(done.stdout.split())
        if expected <= topics or time.monotonic() > deadline:
            return topics


def test_two_namespaced_robots_share_tf_but_not_joint_states(live, package: Path):
    xacro = str(package / "ns_probe" / "urdf" / "probe.urdf.xacro")
    # Both spellings: ROS 2's remap rule for /r1, the plain option for /r2.
    rsp1 = live.robotmodel("robot-state-publisher", xacro, "--frame-prefix", "r1/", "--ros-args", "-r", "__ns:=/r1")
    rsp2 = live.robotmodel("robot-state-publisher", xacro, "--frame-prefix", "r2/", "--namespace", "r2")
    jsp1 = live.robotmodel("joint-state-publisher", xacro, "--zeros", f"shoulder={Q1}", "--ros-args",
                           "-r", "__ns:=/r1")
    # No FILE: r2's robot comes from /r2/robot_description; its values from the relative source topic.
    jsp2 = live.robotmodel("joint-state-publisher", "--source-list", "commands", "--namespace", "r2")
    procs = [rsp1, rsp2, jsp1, jsp2]
    buffer = Buffer()
    with Node("ns_test") as node, TransformListener(buffer, node):
        commands = node.create_publisher(JointState, "/r2/commands", 10)

        def drive_r2() -> None:
            commands.publish(JointState(header=Header(stamp=stamp(time.time_ns())), name=["shoulder"],
                                        position=[Q2]))

        r1 = wait_pose(buffer, "r1/base_link", "r1/tool", tool_pose(Q1))
        r2 = wait_pose(buffer, "r2/base_link", "r2/tool", tool_pose(Q2), tick=drive_r2)
        assert not np.allclose(r1[0], r2[0])
        # r2's commands never reach r1, whose joint states are its own.
        wait_pose(buffer, "r1/base_link", "r1/tool", tool_pose(Q1), timeout=5)
        # The static tool_mount of each came over the shared /tf_static, with its prefix.
        assert np.allclose(pose(buffer, "r1/arm", "r1/tool")[0], (0.25, 0, 0), atol=1e-12)
        assert np.allclose(pose(buffer, "r2/arm", "r2/tool")[0], (0.25, 0, 0), atol=1e-12)
        nodes = set(node.get_node_names_and_namespaces())
        assert {("robot_state_publisher", "/r1"), ("robot_state_publisher", "/r2"),
                ("joint_state_publisher", "/r1"), ("joint_state_publisher", "/r2")} <= nodes
    expected = {"/r1/joint_states", "/r1/robot_description", "/r2/joint_states", "/r2/robot_description",
                "/r2/commands", "/tf", "/tf_static"}
    topics = topic_list(live, expected)
    assert expected <= topics, topics
    assert not {"/joint_states", "/robot_description", "/commands"} & topics, topics
    # A relative topic name given to topic echo resolves under its --namespace.
    echo = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "echo", "joint_states",
                           "--namespace", "r1", "--once", "--field", "position", "--timeout", "30",
                           "--spin-time", "3"],  # discovery's 0.5 s default is short for a loaded machine
                          env=live.env, capture_output=True, text=True, timeout=60, check=False)
    assert echo.returncode == 0, echo.stderr
    assert echo.stdout == f"- {Q1}\n---\n"
    for proc in procs:
        assert proc.stop(signal.SIGTERM) == 0, proc.err[-10:]


def test_namespaced_logger_names_as_rcl(live, package: Path):
    xacro = str(package / "ns_probe" / "urdf" / "probe.urdf.xacro")
    rsp = live.robotmodel("robot-state-publisher", xacro, "--ros-args", "-r", "__ns:=/left/arm",
                          "-r", "__node:=rsp")
    rsp.wait_line(r"^\[INFO\] \[\d+\.\d+\] \[left\.arm\.rsp\]: Robot initialized$", stream="err")
    assert rsp.stop(signal.SIGINT) == 0


STARTED = re.compile(r"process\[(.+)\]: started with pid \[(\d+)\]")


def test_ros1_groups_launch_publishes_both_trees(live, package, two_robots):
    proc = live.start(sys.executable, "-m", "robotmodel.cli.main", "launch", "--no-browser", str(two_robots),
                      "--package-path", str(package))
    buffer = Buffer()
    with TransformListener(buffer):
        try:
            # Each robot's shoulder from its own namespace's joint_state_publisher; its base 1 m either side of world.
            wait_pose(buffer, "world", "r1_tool", tool_pose(0.3, 1.0))
            wait_pose(buffer, "world", "r2_tool", tool_pose(-0.7, -1.0))
        except pytest.fail.Exception:
            print("launch's output:", *proc.out[-20:], *proc.err[-40:], sep="\n")  # shown with the failure
            raise
    topics = topic_list(live, {"/r1/joint_states", "/r2/joint_states"})
    assert {"/r1/joint_states", "/r1/robot_description", "/r2/joint_states", "/r2/robot_description"} <= topics
    assert "/joint_states" not in topics
    labels = sorted(m.group(1) for line in proc.err if (m := STARTED.search(line)))
    assert labels == ["r1/jsp-2", "r1/mount-3", "r1/rsp-1", "r2/jsp-5", "r2/mount-6", "r2/rsp-4"]
    assert proc.stop(signal.SIGTERM) == 0


def test_viewer_and_sliders_use_their_namespace(live, package: Path):
    xacro = str(package / "ns_probe" / "urdf" / "probe.urdf.xacro")
    view = live.robotmodel("view", xacro, "--follow", "--port", "0", "--namespace", "r1")
    gui = live.robotmodel("joint-state-publisher-gui", xacro, "--joint", "shoulder=0.4", "--port", "0",
                          "--ros-args", "-r", "__ns:=/r2")
    for proc in (view, gui):
        proc.wait_line(r"^http://127\.0\.0\.1:\d+/", timeout=60)
    # The sliders publish on /r2/joint_states, nothing on the global topic.
    echo = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "echo", "/r2/joint_states",
                           "--once", "--field", "position", "--timeout", "30", "--spin-time", "3"],
                          env=live.env, capture_output=True, text=True, timeout=60, check=False)
    assert echo.returncode == 0, echo.stderr
    assert echo.stdout == "- 0.4\n---\n"
    with Node("ns_graph") as node:
        deadline = time.monotonic() + 30
        while True:
            nodes = set(node.get_node_names_and_namespaces())
            topics = {name for name, _ in node.get_topic_names_and_types()}
            if ({("robotmodel_view", "/r1"), ("joint_state_publisher_gui", "/r2")} <= nodes
                    and "/r1/joint_states" in topics) \
                    or time.monotonic() > deadline:
                break
            time.sleep(0.05)
    assert {("robotmodel_view", "/r1"), ("joint_state_publisher_gui", "/r2")} <= nodes  # the GUI named as ROS's
    assert "/r1/joint_states" in topics and "/joint_states" not in topics  # --follow's subscription
    for proc in (view, gui):
        assert proc.stop(signal.SIGINT) == 0, proc.err[-10:]
