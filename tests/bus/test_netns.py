"""Two machines on one: robotmodel's tools in one network namespace, a peer in another, a veth pair between.

Each test makes its own pair of namespaces (``ip netns``, root only: elsewhere it skips with
one line), joined by a veth pair (10.77.0.1 in A, 10.77.0.2 in B) and nothing else, so what
arrives in B crossed that link as it would cross a network. Everything in the namespaces is
ended, then the namespaces deleted, when the test ends.

- DDS: robot_state_publisher and joint_state_publisher in A; in B the real rclpy (Jazzy, Fast
  DDS) receives /joint_states and lists the /tf publisher, and ``robotmodel tf2_echo`` prints
  the pose from /tf; once with ``ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET`` (multicast on the link),
  once with ``ROS_STATIC_PEERS`` naming the other host (discovery otherwise local).
- zenoh, as rmw_zenoh spans hosts: a router on each host, B's connecting to A's
  (``ZENOH_CONFIG_OVERRIDE``), every process meeting its own host's router; in B an rmw_zenoh
  client that is not ours (zenoh-ros2-sdk) receives /joint_states and tf2_echo prints the pose.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import secrets
import shutil
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

HERE = Path(__file__).resolve().parent
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(HERE.parents[1] / ".venv-rclpy" / "bin" / "python")))
RCLPY_PEER = HERE / "dds" / "rclpy_peer.py"
SDK_PEER = HERE / "zenoh_sdk_peer.py"
ARM = HERE.parents[1] / "urdf" / "arm.urdf.xacro"
ADDR_A, ADDR_B = "10.77.0.1", "10.77.0.2"
TRANSLATION = re.compile(r"^- Translation: \[(-?[\d.]+), (-?[\d.]+), (-?[\d.]+)\]$")
# Generous: discovery across the link plus process starts on a loaded 2-core machine.
DEADLINE_S = 40.0


def _ip(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["ip", *args], capture_output=True, text=True, timeout=30, check=False)


class Hosts:
    """The two namespaces: ``a(argv)`` and ``b(argv)`` are argv run inside them."""

    def __init__(self, a: str, b: str) -> None:
        self.names = (a, b)

    def a(self, *argv: str) -> list[str]:
        return ["ip", "netns", "exec", self.names[0], *argv]

    def b(self, *argv: str) -> list[str]:
        return ["ip", "netns", "exec", self.names[1], *argv]


@pytest.fixture
def hosts() -> Iterator[Hosts]:
    """Two fresh network namespaces joined by a veth pair; skips with one line where that cannot be made."""
    if os.geteuid() != 0:
        pytest.skip("two network namespaces need root (ip netns)")
    if shutil.which("ip") is None:
        pytest.skip("no `ip` (iproute2) to make network namespaces")
    tag = secrets.token_hex(3)
    a, b = f"rma{tag}", f"rmb{tag}"
    made: list[str] = []
    try:
        for ns in (a, b):
            done = _ip("netns", "add", ns)
            if done.returncode != 0:
                pytest.skip(f"ip netns add: {done.stderr.strip()}")
            made.append(ns)
        steps = [("link", "add", f"v{a}", "netns", a, "type", "veth", "peer", "name", f"v{b}", "netns", b)]
        for ns, addr in ((a, ADDR_A), (b, ADDR_B)):
            steps += [("-n", ns, "addr", "add", f"{addr}/24", "dev", f"v{ns}"), ("-n", ns, "link", "set", f"v{ns}", "up"),
                      ("-n", ns, "link", "set", "lo", "up"),
                      # DDS discovery's multicast leaves by the link (the namespace has no default route).
                      ("-n", ns, "route", "add", "224.0.0.0/4", "dev", f"v{ns}")]
        for step in steps:
            done = _ip(*step)
            assert done.returncode == 0, f"ip {' '.join(step)}: {done.stderr.strip()}"
        yield Hosts(a, b)
    finally:
        for ns in made:
            # Whatever still runs in them was started by this test.
            for pid in _ip("netns", "pids", ns).stdout.split():
                with contextlib.suppress(ProcessLookupError):
                    os.kill(int(pid), signal.SIGKILL)
            _ip("netns", "del", ns)


def cli(*args: str) -> list[str]:
    """``robotmodel ARGS`` with this interpreter."""
    return [sys.executable, "-m", "robotmodel.cli.main", *args]


def fk_palm_translation() -> tuple[str, ...]:
    """gripper_palm_link in world at the published joints, from robotmodel's FK, as tf2_echo rounds it."""
    state = KinematicState(KinematicModel(load(ARM))).update({"arm_shoulder_joint": 0.5})
    return tuple(f"{v:.3f}" for v in state.link_matrix("gripper_palm_link")[:3, 3])


def arm_in_a(procs: Any, hosts: Hosts, env: dict[str, str], robotmodel: Any = cli) -> None:
    procs.run(hosts.a(*robotmodel("robot_state_publisher", str(ARM))), env=env)
    procs.run(hosts.a(*robotmodel("joint_state_publisher", str(ARM), "--zeros", "arm_shoulder_joint=0.5")), env=env)


def assert_joint_states(listener: Any) -> None:
    names, positions = json.loads(listener.wait_line("got ", timeout=DEADLINE_S)[len("got "):])
    assert dict(zip(names, positions, strict=True))["arm_shoulder_joint"] == 0.5


def assert_pose(echo: Any) -> None:
    want = fk_palm_translation()

    def shown(lines: list[str]) -> bool:
        return any((m := TRANSLATION.match(line)) and m.groups() == want for line in lines)

    assert echo.wait_for(shown, DEADLINE_S), f"tf2_echo in B never printed {want}: {echo.lines[-8:]} {echo.errors[-5:]}"


@pytest.mark.parametrize("reach", ["SUBNET", "ROS_STATIC_PEERS"])
def test_dds_joint_states_and_tf_reach_a_real_rclpy_on_another_host(hosts: Hosts, procs: Any, bus_env: dict[str, str],
                                                                    tmp_path: Path, reach: str) -> None:
    if not RCLPY.exists():
        pytest.skip(f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)")
    base = {k: v for k, v in bus_env.items() if k not in ("ROS_LOCALHOST_ONLY", "ROS_STATIC_PEERS")}
    env_a, env_b = dict(base), dict(base)
    if reach == "SUBNET":
        for env in (env_a, env_b):
            env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "SUBNET"
    else:  # discovery stays on each host; the other host is named
        env_a["ROS_STATIC_PEERS"], env_b["ROS_STATIC_PEERS"] = ADDR_B, ADDR_A
    arm_in_a(procs, hosts, dict(env_a, RMW_IMPLEMENTATION="rmw_cyclonedds_cpp"), cli)
    rclpy_env = {k: v for k, v in env_b.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    rclpy_env.update(RMW_IMPLEMENTATION="rmw_fastrtps_cpp", ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / "log"),
                     PYTHONUNBUFFERED="1")
    listener = procs.run(hosts.b(str(RCLPY), str(RCLPY_PEER), "joint_listener"), env=rclpy_env)
    graph = procs.run(hosts.b(str(RCLPY), str(RCLPY_PEER), "graph", "robot_state_publisher", "/tf"), env=rclpy_env)
    echo = procs.run(hosts.b(*cli("tf2_echo", "world", "gripper_palm_link")),
                     env=dict(env_b, RMW_IMPLEMENTATION="rmw_cyclonedds_cpp"))
    assert_joint_states(listener)
    publishers = json.loads(graph.wait_line("publishers ", timeout=DEADLINE_S)[len("publishers "):])
    assert [(p["node"], p["type"]) for p in publishers] == [("robot_state_publisher", "tf2_msgs/msg/TFMessage")]
    assert_pose(echo)


def test_zenoh_joint_states_and_tf_cross_between_the_hosts_routers(hosts: Hosts, procs: Any,
                                                                    bus_env: dict[str, str]) -> None:
    pytest.importorskip("zenoh_ros2_sdk", reason="zenoh-ros2-sdk is not installed (a test extra)")
    # Each host's own 7447, as on two machines.
    env = {k: v for k, v in bus_env.items() if k not in ("ROBOTMODEL_ZENOH_PORT", "ZENOH_CONFIG_OVERRIDE")}
    env["RMW_IMPLEMENTATION"] = "rmw_zenoh_cpp"
    robot = procs.run(hosts.a(*cli("router", "--listen", "tcp/127.0.0.1:7447", "--listen", f"tcp/{ADDR_A}:7447")),
                      env=env)
    robot.wait_line("Started Zenoh router", timeout=DEADLINE_S)
    # rmw_zenoh's recipe for a second host: its router connects to the first's.
    laptop = procs.run(hosts.b(*cli("router")),
                       env=dict(env, ZENOH_CONFIG_OVERRIDE=f'connect/endpoints=["tcp/{ADDR_A}:7447"]'))
    laptop.wait_line("Started Zenoh router", timeout=DEADLINE_S)
    arm_in_a(procs, hosts, env)
    listener = procs.run(hosts.b(sys.executable, str(SDK_PEER), "joint_listener", "7447"), env=env)
    echo = procs.run(hosts.b(*cli("tf2_echo", "world", "gripper_palm_link")), env=env)
    assert_joint_states(listener)
    assert_pose(echo)
