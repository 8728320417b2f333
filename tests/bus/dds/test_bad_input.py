"""Bad input on the DDS wire (issue 20's must-show 7): one clear line each, ROS's text, and the service goes on.

- Garbage under the right type name: a writer whose ``tf2_msgs::msg::dds_::TFMessage_`` is not
  TFMessage (a plain Cyclone writer, as a broken or foreign implementation would be), and a real
  rclpy sending JointStates whose names and positions disagree.
- A type-name mismatch: a real rclpy publishing std_msgs/String on /joint_states.
- An incompatible QoS: a real rclpy subscribing /joint_states transient local, which a volatile
  joint_state_publisher cannot serve.

Each warning is rclcpp's/rclpy's text; the command keeps doing its job beside the bad peer.
A peer address Cyclone cannot use (``--connect``, ``ROS_STATIC_PEERS``) is one error line, not
Cyclone's abort of the process.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
from typing import Any

import pytest
from cyclonedds.idl import make_idl_struct
from cyclonedds.idl import types as t
from cyclonedds.pub import DataWriter
from cyclonedds.topic import Topic
from rclpyside import DEADLINE_S, ROOT

from robotmodel.bus import Context
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

ARM = ROOT / "urdf" / "arm.urdf.xacro"
TRANSLATION = re.compile(r"^- Translation: \[(-?[\d.]+), (-?[\d.]+), (-?[\d.]+)\]$")
STATE = {"arm_base_joint": 0.1, "arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.3, "arm_wrist_pitch_joint": 0.2,
         "arm_wrist_roll_joint": 0.25, "arm_wrist_yaw_joint": -0.4, "gripper_left_finger_joint": 0.01}


def palm() -> tuple[str, ...]:
    """tf2_echo's text of T_world_gripper_palm_link's translation at STATE, from robotmodel's FK."""
    matrix = KinematicState(KinematicModel(load(ARM))).update(dict(STATE)).link_matrix("gripper_palm_link")
    return tuple(f"{v:.3f}" for v in matrix[:3, 3])


def lines_with(proc: Any, text: str) -> list[str]:
    return [ln for ln in proc.errors if text in ln]


def translations(proc: Any) -> list[tuple[str, ...]]:
    return [m.groups() for ln in proc.lines if (m := TRANSLATION.match(ln))]


@pytest.fixture
def ctx(bus_env: dict[str, str]) -> Any:
    """A DDS session in this test's domain (the test's own Cyclone participant)."""
    with Context(backend="dds", domain_id=int(bus_env["ROS_DOMAIN_ID"])) as context:
        yield context


def test_a_foreign_definition_under_the_tf_type_name_is_one_line_and_tf2_echo_goes_on(procs: Any,
                                                                                       ctx: Context) -> None:
    echo = procs.cli("tf2_echo", "map", "odom")
    procs.cli("static_transform_publisher", "--x", "3", "--frame-id", "map", "--child-frame-id", "odom")
    # A writer on rt/tf whose TFMessage_ is a byte sequence: what it writes is garbage as a TFMessage.
    Garbage = make_idl_struct("Garbage", "tf2_msgs::msg::dds_::TFMessage_", {"data": t.sequence[t.uint8]})
    participant = ctx.backend.participant  # type: ignore[attr-defined]
    writer = DataWriter(participant, Topic(participant, "rt/tf", Garbage))
    warning = "Incompatible type on topic '/tf', no messages will be sent to it."
    end = time.monotonic() + DEADLINE_S
    while not lines_with(echo, warning):
        assert time.monotonic() < end and echo.popen.poll() is None, echo.errors[-5:]
        writer.write(Garbage(data=list(b"\xff\x00garbage")))
        time.sleep(0.05)
    # The service goes on: tf2_echo prints the static transform again after the warning.
    seen = len(translations(echo))
    assert echo.wait_for(lambda _: len(translations(echo)) > seen + 1, DEADLINE_S), echo.errors[-5:]
    assert set(translations(echo)) == {("3.000", "0.000", "0.000")}
    assert len(lines_with(echo, "Incompatible type")) == 1 and echo.popen.poll() is None
    assert not lines_with(echo, "Traceback")


def test_joint_states_of_another_type_are_one_line_and_the_publisher_goes_on(rclpy: Any, procs: Any) -> None:
    rclpy("wrong_type_talker", "/joint_states")
    rsp = procs.cli("robot_state_publisher", str(ARM))
    procs.cli("joint_state_publisher", str(ARM), "--zeros", *[f"{k}={v}" for k, v in STATE.items()])
    echo = procs.cli("tf2_echo", "world", "gripper_palm_link")
    assert echo.wait_for(lambda _: palm() in translations(echo), DEADLINE_S), echo.errors[-5:]
    warning = "Incompatible type on topic '/joint_states', no messages will be sent to it."
    assert rsp.wait_for(lambda _: bool(lines_with(rsp, warning)), DEADLINE_S), rsp.errors[-5:]
    assert len(lines_with(rsp, "Incompatible type")) == 1 and rsp.popen.poll() is None


def test_invalid_joint_states_from_rclpy_are_one_line_and_valid_ones_still_move_the_robot(rclpy: Any,
                                                                                          procs: Any) -> None:
    rclpy("bad_joints", json.dumps(STATE))
    rsp = procs.cli("robot_state_publisher", str(ARM))
    echo = procs.cli("tf2_echo", "world", "gripper_palm_link")
    assert echo.wait_for(lambda _: palm() in translations(echo), DEADLINE_S), (echo.errors[-5:], rsp.errors[-5:])
    # robot_state_publisher's own text, once (its later ones are held back, not repeated per message).
    assert len(lines_with(rsp, "Robot state publisher ignored an invalid JointState message")) == 1, rsp.errors
    assert rsp.popen.poll() is None and not lines_with(rsp, "Traceback")


def test_an_incompatible_qos_is_rclpys_line_on_both_sides_and_publishing_goes_on(rclpy: Any, procs: Any) -> None:
    listener = rclpy("latched_joint_listener")
    jsp = procs.cli("joint_state_publisher", str(ARM))
    warning = ("New subscription discovered on topic '/joint_states', requesting incompatible QoS. "
               "No messages will be sent to it. Last incompatible policy: DURABILITY")
    assert jsp.wait_for(lambda _: bool(lines_with(jsp, warning)), DEADLINE_S), jsp.errors[-5:]
    assert listener.wait_line("event ", timeout=DEADLINE_S) == "event RMW_QOS_POLICY_DURABILITY"
    # jsp goes on publishing to those who can match: a volatile topic echo gets a state.
    done = procs.cli("topic", "echo", "/joint_states", "--once", "--field", "name", "--timeout", str(int(DEADLINE_S)))
    assert done.popen.wait(DEADLINE_S + 10) == 0, done.errors[-5:]
    done.wait_for(lambda lines: "- arm_shoulder_joint" in lines, 2)
    assert "- arm_shoulder_joint" in done.lines
    assert len(lines_with(jsp, "incompatible QoS")) == 1 and jsp.popen.poll() is None
    assert not [ln for ln in listener.lines if ln.startswith("got ")]


@pytest.mark.parametrize(("how", "peer", "text"), [
    ("--connect", "tcp/127.0.0.1:7447", "is not a host: the DDS wire takes host names or addresses"),
    ("--connect", "nonexistent.invalid", "is not a host name or IPv4 address this machine can resolve"),
    ("--connect", "[::1]", "is not a host name or IPv4 address this machine can resolve"),
    ("ROS_STATIC_PEERS", "nonexistent.invalid", "is not a host name or IPv4 address this machine can resolve"),
], ids=["zenoh-endpoint", "unresolvable", "ipv6", "static-peers"])
def test_a_peer_cyclone_cannot_use_is_one_line_not_an_abort(bus_env: dict[str, str], how: str, peer: str,
                                                           text: str) -> None:
    # Cyclone aborts the process (SIGABRT) on a peer address it cannot resolve.
    env = dict(bus_env, ROS_STATIC_PEERS=peer) if how == "ROS_STATIC_PEERS" else bus_env
    args = ["--connect", peer] if how == "--connect" else []
    done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "list", *args], env=env,
                          capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 1, (done.returncode, done.stderr)
    origin = "connect" if how == "--connect" else "ROS_STATIC_PEERS"
    assert done.stderr.splitlines() == [done.stderr.strip()] and done.stdout == ""
    assert f"robotmodel topic: error: DDS peer '{peer}' (from {origin}) {text}" in done.stderr
