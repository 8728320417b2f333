"""The DDS wire against the real ROS 2: Jazzy's rclpy on Fast DDS, in its own interpreter and process.

The other side is ``rclpy_peer.py`` run by the interpreter ``ROBOTMODEL_RCLPY_PYTHON`` names
(default ``.venv-rclpy/bin/python`` in the checkout, which ``.ci/rclpy-venv`` makes); without
it every test here skips with one line. Fast DDS there and Cyclone DDS here are two
independent DDS implementations, so what passes here is compatibility, not consistency.
Each test has its own ROS_DOMAIN_ID (``bus_env``) and reaps its processes (``procs``); every
wait has a deadline.
"""

from __future__ import annotations

import json
import logging
import re
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from rclpyside import DEADLINE_S, MISSING, ROOT
from viewerws import viewer_config

from robotmodel.bus import QOS_LATCHED, Context, EntityKind, Node, QoS, Reliability, typestore
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load
from robotmodel.xacro import expand

if MISSING:
    pytest.skip(MISSING, allow_module_level=True)

STRING = "std_msgs/msg/String"
JOINT_STATE = "sensor_msgs/msg/JointState"


@pytest.fixture
def ctx(bus_env: dict[str, str]) -> Iterator[Context]:
    """A DDS session in this test's domain."""
    with Context(backend="dds", domain_id=int(bus_env["ROS_DOMAIN_ID"])) as context:
        yield context


class Inbox:
    """What a subscription got, with a deadline wait."""

    def __init__(self) -> None:
        self.items: list[Any] = []
        self._cond = threading.Condition()

    def __call__(self, item: Any) -> None:
        with self._cond:
            self.items.append(item)
            self._cond.notify_all()

    def wait(self, predicate: Callable[[list[Any]], bool], what: str) -> list[Any]:
        with self._cond:
            if not self._cond.wait_for(lambda: predicate(self.items), DEADLINE_S):
                pytest.fail(f"{what}: not within {DEADLINE_S} s; got {self.items[:5]!r}")
            return list(self.items)


def _json_after(proc: Any, prefix: str) -> Any:
    return json.loads(proc.wait_line(prefix, timeout=DEADLINE_S)[len(prefix):])


def test_a_real_rclpy_talker_reaches_a_robotmodel_subscription(rclpy: Any, ctx: Context) -> None:
    rclpy("talker")
    got, raw = Inbox(), Inbox()
    node = Node("rm_listener", context=ctx)
    node.create_subscription(STRING, "/chatter", lambda m: got(m.data), QoS(10))
    node.create_raw_subscription("/chatter", raw)
    texts = got.wait(lambda items: len(items) >= 3, "rclpy's /chatter")
    numbers = [int(t.split()[1]) for t in texts[:3]]
    assert texts[0].startswith("hello ") and numbers == list(range(numbers[0], numbers[0] + 3))
    # Fast DDS's bytes are the CDR rosbags writes for the same message, header included, then
    # zeros up to a multiple of 4 (Fast DDS pads without recording it in the options).
    (first, *_) = raw.wait(lambda items: len(items) >= 1, "raw /chatter")
    text = typestore().deserialize_cdr(first.payload, STRING).data
    expected = bytes(typestore().serialize_cdr(typestore().types[STRING](data=text), STRING))
    assert first.payload == expected + b"\0" * (-len(expected) % 4)
    assert first.typename == STRING and len(first.info.gid) == 16


def test_robotmodel_joint_states_reach_a_real_rclpy_subscription(rclpy: Any, ctx: Context) -> None:
    listener = rclpy("joint_listener")
    JointState = typestore().types[JOINT_STATE]
    Header = typestore().types["std_msgs/msg/Header"]
    Time = typestore().types["builtin_interfaces/msg/Time"]
    msg = JointState(header=Header(stamp=Time(sec=1, nanosec=2), frame_id=""), name=["shoulder", "elbow"],
                     position=np.array([0.25, -1.5]), velocity=np.array([], dtype=np.float64),
                     effort=np.array([], dtype=np.float64))
    pub = Node("rm_joints", context=ctx).create_publisher(JOINT_STATE, "/joint_states", QoS(10))
    # Volatile: publish until the subscriber, once matched, has one.
    end = time.monotonic() + DEADLINE_S
    while not listener.wait_for(lambda lines: any(ln.startswith("got ") for ln in lines), 0.1):
        if listener.popen.poll() is not None or time.monotonic() > end:
            pytest.fail(f"no JointState reached rclpy in {DEADLINE_S} s: {listener.errors[-5:]}")
        pub.publish(msg)
    assert _json_after(listener, "got ") == [["shoulder", "elbow"], [0.25, -1.5]]


def test_a_late_real_rclpy_subscription_gets_the_latched_robot_description(rclpy: Any, ctx: Context) -> None:
    urdf = (Path(__file__).resolve().parents[3] / "urdf" / "arm.urdf.xacro").read_text()
    pub = Node("rm_description", context=ctx).create_publisher(STRING, "/robot_description", QOS_LATCHED)
    pub.publish(typestore().types[STRING](data=urdf))
    # Published before the subscriber exists: only DDS's transient-local history can deliver it.
    late = rclpy("description_listener")
    assert _json_after(late, "got ") == urdf


def test_real_rclpy_sees_robotmodels_node_and_publisher_qos(rclpy: Any, ctx: Context) -> None:
    node = Node("rm_talker", "/rm", context=ctx)
    node.create_publisher(JOINT_STATE, "/joint_states", QoS(5, Reliability.BEST_EFFORT))
    node.create_publisher(STRING, "/robot_description", QOS_LATCHED)
    observer = rclpy("graph", "rm_talker", "/joint_states")
    nodes = _json_after(observer, "nodes ")
    assert ["rm_talker", "/rm"] in nodes and ["rclpy_observer", "/"] in nodes
    (info,) = _json_after(observer, "publishers ")
    assert (info["node"], info["namespace"], info["type"]) == ("rm_talker", "/rm", JOINT_STATE)
    assert (info["reliability"], info["durability"]) == ("BEST_EFFORT", "VOLATILE")


def test_robotmodels_graph_lists_a_real_rclpy_node_and_its_topics(rclpy: Any, ctx: Context) -> None:
    rclpy("talker")
    observer = Node("rm_observer", context=ctx)
    graph = ctx.graph

    def shown(entities: list[Any]) -> bool:
        # rclpy announces each endpoint on ros_discovery_info after DDS discovery shows it, so
        # wait until both of its endpoints are attributed to its node.
        mine = {e.topic for e in entities if e.node_name == "rclpy_talker"}
        return any(e.kind is EntityKind.NODE and e.node_name == "rclpy_talker" for e in entities) and \
            {"/chatter", "/rclpy_in"} <= mine

    assert graph.wait_for(shown, DEADLINE_S), graph.entities()
    assert ("rclpy_talker", "/") in observer.get_node_names_and_namespaces()
    topics = dict(observer.get_topic_names_and_types())
    assert topics["/chatter"] == [STRING]
    assert topics["/rclpy_in"] == [JOINT_STATE]
    (pub,) = graph.endpoints("/chatter", EntityKind.PUBLISHER)
    assert pub.node_fqn == "/rclpy_talker"
    assert pub.qos is not None and pub.qos.reliability == Reliability.RELIABLE
    assert pub.type_hash.startswith("RIHS01_")
    (sub,) = graph.endpoints("/rclpy_in", EntityKind.SUBSCRIPTION)
    assert sub.node_name == "rclpy_talker"


def test_an_incompatible_real_rclpy_publisher_gives_rclpys_warning_here(rclpy: Any, ctx: Context) -> None:
    warned = Inbox()
    handler = logging.Handler(logging.WARNING)
    handler.emit = lambda record: warned(record.getMessage())  # type: ignore[method-assign]
    log = logging.getLogger("robotmodel.bus")
    log.addHandler(handler)
    try:
        rclpy("best_effort_talker")
        got = Inbox()
        sub = Node("rm_strict", context=ctx).create_subscription(STRING, "/qos_probe", got,
                                                                 QoS(10, Reliability.RELIABLE))
        (text, *_) = warned.wait(bool, "incompatible-QoS warning")
    finally:
        log.removeHandler(handler)
    assert text == ("New publisher discovered on topic '/qos_probe', offering incompatible QoS. "
                    "No messages will be received from it. Last incompatible policy: RELIABILITY")
    assert sub.incompatible_qos is not None and sub.incompatible_qos.last_policy == "RELIABILITY"
    assert got.items == []


def test_a_real_rclpy_subscription_reports_our_incompatible_publisher(rclpy: Any, ctx: Context) -> None:
    # A volatile publisher here, a transient-local subscription there: DDS refuses the pair on both sides.
    listener = rclpy("latched_listener")
    events: list[Any] = []
    pub = Node("rm_volatile", context=ctx).create_publisher(STRING, "/qos_probe", QoS(10),
                                                             on_incompatible_qos=events.append)
    assert listener.wait_line("event ", timeout=DEADLINE_S) == "event RMW_QOS_POLICY_DURABILITY"
    end = time.monotonic() + DEADLINE_S
    while not events and time.monotonic() < end:
        time.sleep(0.01)
    # One event per incompatible match DDS sees: a rediscovered peer (likely under load) adds one.
    assert events and {(e.last_policy, e.topic) for e in events} == {("DURABILITY", "/qos_probe")}
    pub.publish(typestore().types[STRING](data="never"))
    assert not pub.matched()
    assert not [ln for ln in listener.lines if ln.startswith("got ")]


# ----- the live commands against the real rclpy (issue 20's must-shows 1-3) -----------------------------------
ARM = ROOT / "urdf" / "arm.urdf.xacro"
# Every independent movable joint of the arm (robot_state_publisher moves only the joints a JointState names).
ARM_STATE = {"arm_base_joint": 0.1, "arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.3, "arm_wrist_pitch_joint": 0.2,
             "arm_wrist_roll_joint": 0.25, "arm_wrist_yaw_joint": -0.4, "gripper_left_finger_joint": 0.01}
TRANSLATION = re.compile(r"^- Translation: \[(-?[\d.]+), (-?[\d.]+), (-?[\d.]+)\]$")
TF = "tf2_msgs/msg/TFMessage"


def _palm_pose() -> np.ndarray:
    """T_world_gripper_palm_link at ARM_STATE, by robotmodel's FK."""
    return KinematicState(KinematicModel(load(ARM))).update(dict(ARM_STATE)).link_matrix("gripper_palm_link")


def test_real_rclpy_description_and_joints_drive_robotmodels_tools(rclpy: Any, procs: Any, ctx: Context,
                                                                   tmp_path: Path) -> None:
    """rclpy's URDF (latched) and JointState -> robot_state_publisher (no FILE) -> tf2_echo prints FK's pose;
    the viewer also takes the robot and its joints from rclpy alone.

    Without FILE or ``robot_description`` parameter robotmodel's robot_state_publisher takes
    the robot another node publishes on /robot_description (a stock ROS 2 RSP would stop with
    "robot_description parameter must not be empty", which an explicitly empty parameter still gives).
    """
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(expand(ARM))
    rclpy("describer", str(urdf), json.dumps(ARM_STATE))
    tf_raw = Inbox()
    Node("rm_tf_spy", context=ctx).create_raw_subscription("/tf", tf_raw)
    rsp = procs.cli("robot_state_publisher")
    view = procs.cli("view", "--follow", "--port", "0")
    echo = procs.cli("tf2_echo", "world", "gripper_palm_link")
    want = tuple(f"{v:.3f}" for v in _palm_pose()[:3, 3])

    def shown(lines: list[str]) -> bool:
        return any((m := TRANSLATION.match(ln)) and m.groups() == want for ln in lines)

    assert echo.wait_for(shown, DEADLINE_S), (want, echo.lines[-8:], echo.errors[-8:], rsp.errors[-8:])
    assert any("waiting for the robot on the robot_description topic" in ln for ln in rsp.errors), rsp.errors[-8:]
    # /tf as rmw writes it: every sample robot_state_publisher put on DDS is rosbags' CDR of
    # the message it holds (tf2_msgs has no wheel for the rclpy side to decode it itself).
    samples = tf_raw.wait(lambda items: any(s.typename == TF for s in items), "raw /tf")
    for sample in samples:
        assert sample.typename == TF
        assert sample.payload == bytes(typestore().serialize_cdr(typestore().deserialize_cdr(sample.payload, TF), TF))
    names = {t.child_frame_id for s in samples for t in typestore().deserialize_cdr(s.payload, TF).transforms}
    # Each joint rclpy's JointState names (and the mimic finger that follows one) moves its child link on /tf.
    moving = {j.child for j in load(ARM).joints if j.name in ARM_STATE or j.mimic is not None}
    assert names == moving
    # The viewer's robot and joint values: rclpy's description and rclpy's JointState.
    url = view.wait_line("http://127.0.0.1:", timeout=DEADLINE_S).split()[0]
    config = viewer_config(url, lambda c: all(
        abs({j["name"]: j["value"] for j in c["joints"]}.get(n, 9.0) - v) < 1e-9  # type: ignore[attr-defined]
        for n, v in ARM_STATE.items()))
    assert config["robot"] == "arm"
    values = {j["name"]: j["value"] for j in config["joints"]}  # type: ignore[attr-defined]
    assert {n: values[n] for n in ARM_STATE} == ARM_STATE


def test_robotmodels_joint_state_publisher_reaches_a_real_rclpy_subscriber(rclpy: Any, procs: Any) -> None:
    listener = rclpy("joint_listener")
    procs.cli("joint_state_publisher", str(ARM), "--zeros", "arm_shoulder_joint=0.5", "arm_elbow_joint=-0.3")
    names, positions = _json_after(listener, "got ")
    state = dict(zip(names, positions, strict=True))
    assert state["arm_shoulder_joint"] == 0.5 and state["arm_elbow_joint"] == -0.3
    assert set(names) == {j.name for j in load(ARM).joints if j.type.value in ("revolute", "prismatic")}


def test_a_late_real_rclpy_subscriber_gets_robot_state_publishers_description(rclpy: Any, procs: Any,
                                                                              ctx: Context) -> None:
    rsp = procs.cli("robot_state_publisher", str(ARM))
    graph = ctx.graph
    # Started only once robot_state_publisher's latched writer is on the graph: transient local
    # durability, not a race, must carry the description to it.
    assert graph.wait_for(lambda es: any(e.topic == "/robot_description" and e.kind is EntityKind.PUBLISHER
                                         for e in es), DEADLINE_S), rsp.errors[-5:]
    late = rclpy("description_listener")
    assert _json_after(late, "got ") == expand(ARM)


def test_real_rclpy_sees_robot_state_publishers_node_and_qos(rclpy: Any, procs: Any) -> None:
    procs.cli("robot_state_publisher", str(ARM))
    observer = rclpy("graph", "robot_state_publisher", "/robot_description")
    nodes = _json_after(observer, "nodes ")
    assert ["robot_state_publisher", "/"] in nodes
    (info,) = _json_after(observer, "publishers ")
    assert (info["node"], info["namespace"], info["type"]) == ("robot_state_publisher", "/", STRING)
    # DDS discovery carries no history depth: rmw reports a remote endpoint's as 0.
    assert (info["reliability"], info["durability"]) == ("RELIABLE", "TRANSIENT_LOCAL")


def test_topic_list_shows_a_real_rclpy_nodes_topics_with_types(rclpy: Any, procs: Any) -> None:
    rclpy("talker")
    end = time.monotonic() + DEADLINE_S
    while True:
        lister = procs.cli("topic", "list", "-t", "--spin-time", "1")
        assert lister.popen.wait(DEADLINE_S) == 0, lister.errors[-5:]
        lister.wait_for(lambda _: False, 0.1)  # the readers' last lines
        if {"/chatter [std_msgs/msg/String]", "/rclpy_in [sensor_msgs/msg/JointState]"} <= set(lister.lines) \
                or time.monotonic() > end:
            break
    assert "/chatter [std_msgs/msg/String]" in lister.lines, lister.lines
    assert "/rclpy_in [sensor_msgs/msg/JointState]" in lister.lines
