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
import os
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from robotmodel.bus import QOS_LATCHED, Context, EntityKind, Node, QoS, Reliability, typestore

ROOT = Path(__file__).resolve().parents[3]
PEER = Path(__file__).with_name("rclpy_peer.py")
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(ROOT / ".venv-rclpy" / "bin" / "python")))
# Generous for a loaded 2-core machine (Fast DDS and Cyclone each discover in about a second).
DEADLINE_S = 30.0

if not RCLPY.exists():
    pytest.skip(f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)", allow_module_level=True)

STRING = "std_msgs/msg/String"
JOINT_STATE = "sensor_msgs/msg/JointState"


@pytest.fixture
def rclpy(procs: Any, bus_env: dict[str, str], tmp_path: Path) -> Callable[..., Any]:
    """Start a role of rclpy_peer.py on Fast DDS in this test's domain, kept on this machine."""
    env = {k: v for k, v in bus_env.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    env.update(RMW_IMPLEMENTATION="rmw_fastrtps_cpp", ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / "log"), PYTHONUNBUFFERED="1")
    env.pop("ROS_LOCALHOST_ONLY", None)

    def start(*args: str) -> Any:
        proc = procs.run([str(RCLPY), str(PEER), *args], env=env)
        proc.wait_line("ready", timeout=DEADLINE_S)
        return proc

    return start


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
    import numpy as np

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
