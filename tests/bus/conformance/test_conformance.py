"""What every wire must do (the backend seam's contract), checked on each wire of ``conftest.WIRES``.

Each case uses only the node API (Context, Node, Graph), never a wire's own module, so a
new wire passes or fails it as it is. Sessions in this process talk through the wire
itself (sockets on zenoh); the latched, graph and killed-peer cases put the other side in
a child process on wires with processes. Every wait has a deadline; nothing sleeps a fixed
time.
"""

from __future__ import annotations

import string
import threading
import time
from collections.abc import Callable
from typing import Any

import pytest
from bus.conformance.conftest import WIRES

from robotmodel.bus import (
    QOS_TF,
    Context,
    Durability,
    EntityKind,
    History,
    Node,
    QoS,
    QoSEvent,
    RawMessage,
    Reliability,
    incompatible_policy,
    typestore,
)
from robotmodel.errors import BusError
from robotmodel.msgs import TFMessage

STRING = "std_msgs/msg/String"
String = typestore().types[STRING]
# Generous for a loaded 2-core machine; met in milliseconds when all is well.
DELIVERY_S = 30.0


class Inbox:
    """Collects what a callback gets, thread-safe, with waits that have deadlines."""

    def __init__(self) -> None:
        self.items: list[Any] = []
        self._cond = threading.Condition()

    def __call__(self, item: Any) -> None:
        with self._cond:
            self.items.append(item)
            self._cond.notify_all()

    def wait(self, predicate: Callable[[list[Any]], bool], timeout: float = DELIVERY_S, what: str = "") -> list[Any]:
        with self._cond:
            if not self._cond.wait_for(lambda: predicate(self.items), timeout):
                pytest.fail(f"{what or 'inbox'}: not within {timeout} s; got {self.items[:5]!r}"
                            f"{'...' if len(self.items) > 5 else ''}")
            return list(self.items)

    def arrival(self, seen: int, timeout: float) -> bool:
        """Wait up to ``timeout`` for more than ``seen`` items; no failure at the deadline."""
        with self._cond:
            return self._cond.wait_for(lambda: len(self.items) > seen, timeout)

    def snapshot(self) -> list[Any]:
        with self._cond:
            return list(self.items)


def until(condition: Callable[[], bool], timeout: float, what: str) -> None:
    end = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > end:
            pytest.fail(f"{what}: not within {timeout} s")
        time.sleep(0.005)


def datas(msgs: list[Any]) -> list[str]:
    return [m.data for m in msgs]


def publish_until(pub: Any, inbox: Inbox, make: Callable[[int], Any], enough: Callable[[list[Any]], bool],
                  what: str) -> None:
    """Publish until ``enough(inbox items)`` (best effort may lose some), waiting up to 20 ms for each to land."""
    end = time.monotonic() + DELIVERY_S
    i = 0
    while not enough(inbox.snapshot()):
        if time.monotonic() > end:
            pytest.fail(f"{what}: not within {DELIVERY_S} s; got {inbox.snapshot()[:5]!r}")
        count = len(inbox.snapshot())
        pub.publish(make(i))
        i += 1
        inbox.arrival(count, 0.02)


def matched(pub: Any, wire: Any) -> None:
    until(pub.matched, wire.spec.graph_deadline_s, f"publisher on {pub.topic_name} matched")


# --- durability ---------------------------------------------------------------------------

def test_latched_samples_reach_a_late_transient_local_subscription(wire: Any) -> None:
    # Published before the subscription exists, by a publisher elsewhere keeping the last 2.
    wire.peer("latched", "/conformance/latched", "3", "2")
    node = Node("late", context=wire.context())
    got = Inbox()
    node.create_subscription(STRING, "/conformance/latched", got, QoS(10, durability=Durability.TRANSIENT_LOCAL))
    expected = ["m2"] if wire.spec.latches_last_only else ["m1", "m2"]
    assert datas(got.wait(lambda items: len(items) >= len(expected), what="latched history")) == expected


@pytest.mark.parametrize("durability", [Durability.VOLATILE, Durability.TRANSIENT_LOCAL], ids=lambda d: d.name.lower())
def test_a_volatile_late_joiner_gets_nothing_old(wire: Any, durability: Durability) -> None:
    talker = Node("talker", context=wire.context())
    pub = talker.create_publisher(STRING, "/conformance/volatile", QoS(10, durability=durability))
    pub.publish(String(data="old"))
    listener = Node("listener", context=wire.context())
    got = Inbox()
    listener.create_subscription(STRING, "/conformance/volatile", got, QoS(10))
    matched(pub, wire)
    pub.publish(String(data="new"))
    expected = ["old", "new"] if durability is Durability.TRANSIENT_LOCAL and wire.spec.volatile_gets_latched \
        else ["new"]
    assert datas(got.wait(lambda items: len(items) >= len(expected), what="new sample")) == expected


# --- QoS compatibility --------------------------------------------------------------------

MISMATCHES = [
    pytest.param(QoS(10, Reliability.BEST_EFFORT), QoS(10, Reliability.RELIABLE), "RELIABILITY",
                 id="best_effort_pub-reliable_sub"),
    pytest.param(QoS(10), QoS(10, durability=Durability.TRANSIENT_LOCAL), "DURABILITY",
                 id="volatile_pub-transient_local_sub"),
]


@pytest.mark.parametrize(("pub_qos", "sub_qos", "dds_policy"), MISMATCHES)
def test_qos_mismatch_as_the_wires_ros_matches(wire: Any, pub_qos: QoS, sub_qos: QoS, dds_policy: str) -> None:
    ctx_pub, ctx_sub = wire.context(), wire.context()
    # The wire's verdict is its ROS's: rmw_dds_common's rules (DDS, in-process), or none (rmw_zenoh, ROS 1).
    verdict = ctx_sub.qos_incompatibility(pub_qos, sub_qos)
    assert verdict == (dds_policy if wire.spec.qos_rules == "dds" else "")
    assert incompatible_policy(pub_qos, sub_qos) == dds_policy

    pub_events: list[QoSEvent] = []
    sub_events: list[QoSEvent] = []
    talker = Node("talker", context=ctx_pub)
    pub = talker.create_publisher(STRING, "/conformance/qos", pub_qos, on_incompatible_qos=pub_events.append)
    listener = Node("listener", context=ctx_sub)
    got = Inbox()
    listener.create_subscription(STRING, "/conformance/qos", got, sub_qos, on_incompatible_qos=sub_events.append)
    # A compatible subscription next to it (on a node of its own: ROS 1 merges one node's
    # subscriptions of a topic): what it gets, the other would have got if matched.
    witness = Inbox()
    Node("witness", context=ctx_sub).create_subscription(STRING, "/conformance/qos", witness,
                                                         QoS(10, Reliability.BEST_EFFORT))
    graph = ctx_sub.graph
    # Either way the graph shows both endpoints with their own QoS, as ROS shows them.
    assert graph.wait_for(lambda es: len([e for e in es if e.topic == "/conformance/qos"]) == 3,
                          wire.spec.graph_deadline_s)
    pubs = graph.endpoints("/conformance/qos", EntityKind.PUBLISHER)
    if wire.spec.endpoint_qos:
        assert [(p.qos.reliability, p.qos.durability) for p in pubs if p.qos] == [(pub_qos.reliability,
                                                                                    pub_qos.durability)]
    else:
        assert [p.qos for p in pubs] == [None]
    if verdict:
        until(lambda: bool(pub_events and sub_events), DELIVERY_S, "incompatible-QoS events on both sides")
        assert [(e.last_policy, e.total_count, e.topic) for e in pub_events] == [(verdict, 1, "/conformance/qos")]
        assert [(e.last_policy, e.total_count, e.topic) for e in sub_events] == [(verdict, 1, "/conformance/qos")]
        publish_until(pub, witness, lambda i: String(data=f"x{i}"), lambda items: len(items) >= 3,
                      "witness samples")
        assert got.snapshot() == [], "an incompatible subscription received samples"
    else:
        publish_until(pub, got, lambda i: String(data=f"x{i}"), lambda items: len(items) >= 3,
                      "samples on a compatible pair")
        assert pub_events == [] and sub_events == []


def test_a_subscription_of_another_type_gets_nothing(wire: Any) -> None:
    ctx = wire.context()
    talker = Node("talker", context=wire.context())
    pub = talker.create_publisher(STRING, "/conformance/typed", QoS(10))
    # Each on a node of its own: ROS 1 refuses two types of one topic in one node.
    wrong = Inbox()
    Node("listener", context=ctx).create_subscription(TFMessage, "/conformance/typed", wrong, QoS(10))
    witness = Inbox()
    Node("witness", context=ctx).create_subscription(STRING, "/conformance/typed", witness, QoS(10))
    publish_until(pub, witness, lambda i: String(data=f"x{i}"), lambda items: len(items) >= 3, "witness samples")
    assert wrong.snapshot() == []


# --- the graph ----------------------------------------------------------------------------

def test_graph_names_nodes_namespaces_topics_types_and_endpoint_qos(wire: Any) -> None:
    observer = Node("observer", context=wire.context())
    graph = observer.context.graph
    peer = wire.peer("talker", "talker", "/conformance/ns")

    def shown(entities: list[Any]) -> bool:
        return any(e.kind is EntityKind.NODE and e.node_name == "talker" for e in entities) and \
            len([e for e in entities if e.node_name == "talker" and e.kind is not EntityKind.NODE
                 and e.topic not in wire.spec.implicit_topics]) == 2

    assert graph.wait_for(shown, wire.spec.graph_deadline_s), graph.entities()
    assert ("talker", "/conformance/ns") in observer.get_node_names_and_namespaces()
    topics = dict(observer.get_topic_names_and_types())
    assert topics["/conformance/ns/chatter"] == [STRING]
    assert topics["/tf"] == ["tf2_msgs/msg/TFMessage"]
    (pub,) = graph.endpoints("/conformance/ns/chatter", EntityKind.PUBLISHER)
    assert (pub.node_name, pub.namespace, pub.node_fqn) == ("talker", "/conformance/ns", "/conformance/ns/talker")
    (sub,) = [e for e in graph.endpoints("/tf", EntityKind.SUBSCRIPTION) if e.node_name == "talker"]
    if wire.spec.endpoint_qos:
        assert pub.qos is not None and (pub.qos.reliability, pub.qos.depth) == (Reliability.BEST_EFFORT, 7)
        assert sub.qos is not None and (sub.qos.reliability, sub.qos.depth) == (QOS_TF.reliability, QOS_TF.depth)
    else:
        assert (pub.qos, sub.qos) == (None, None)
    assert observer.count_publishers("/conformance/ns/chatter") == 1
    # A node that ends cleanly leaves the graph, with its endpoints.
    peer.stop()
    assert graph.wait_for(lambda es: not [e for e in es if e.node_name == "talker"], wire.spec.graph_deadline_s)
    assert "/conformance/ns/chatter" not in dict(observer.get_topic_names_and_types())


def test_a_killed_peer_leaves_the_graph(wire: Any) -> None:
    observer = Node("observer", context=wire.context())
    graph = observer.context.graph
    peer = wire.peer("talker", "doomed", "/")
    assert graph.wait_for(lambda es: any(e.node_name == "doomed" for e in es), wire.spec.graph_deadline_s)
    peer.kill()  # -9 on wires with processes: no goodbye
    if not wire.spec.killed_peer_leaves:
        # As ROS 1's master: the registrations stay until cleaned up.
        assert ("doomed", "/") in observer.get_node_names_and_namespaces()
        return
    started = time.monotonic()
    assert graph.wait_for(lambda es: not [e for e in es if e.node_name == "doomed"], wire.spec.graph_deadline_s), \
        [e for e in graph.entities() if e.node_name == "doomed"]
    assert ("doomed", "/") not in observer.get_node_names_and_namespaces()
    assert time.monotonic() - started < wire.spec.graph_deadline_s


def test_sample_info_names_the_publisher_in_the_graph(wire: Any) -> None:
    talker = Node("talker", "/conformance", context=wire.context())
    pub = talker.create_publisher(STRING, "chatter", QoS(10))
    listener = Node("listener", context=wire.context())
    got = Inbox()
    listener.create_raw_subscription("/conformance/chatter", got)
    matched(pub, wire)
    before = time.time_ns()
    pub.publish(String(data="a"))
    pub.publish(String(data="b"))
    raws: list[RawMessage] = got.wait(lambda items: len(items) >= 2, what="raw samples")
    after = time.time_ns()
    assert [r.typename for r in raws] == [STRING, STRING]
    seqs = [r.info.sequence_number for r in raws]
    assert seqs[1] == seqs[0] + 1
    assert all(before <= r.info.source_timestamp_ns <= after for r in raws)
    assert {r.info.gid for r in raws} == {pub.gid}
    graph = listener.context.graph
    assert graph.wait_for(lambda es: graph.by_gid(pub.gid) is not None, wire.spec.graph_deadline_s)
    entity = graph.by_gid(pub.gid)
    assert entity is not None and (entity.node_fqn, entity.topic) == ("/conformance/talker", "/conformance/chatter")
    codec = listener.context.encoding
    assert all(r.encoding == codec for r in raws)


# --- names --------------------------------------------------------------------------------

def test_remaps_rename_topics_and_nodes(wire: Any) -> None:
    observer = Node("observer", context=wire.context())
    got = Inbox()
    observer.create_subscription(STRING, "/remapped/chatter", got, QoS(10))
    talker = Node("talker", "/r1", context=wire.context(),
                  remappings=["chatter:=/remapped/chatter", "__node:=renamed", "talker:__ns:=/moved"])
    assert (talker.get_name(), talker.get_namespace()) == ("renamed", "/moved")
    pub = talker.create_publisher(STRING, "chatter", QoS(10))
    assert pub.topic_name == "/remapped/chatter"
    matched(pub, wire)
    pub.publish(String(data="hi"))
    assert datas(got.wait(lambda items: len(items) >= 1, what="remapped sample")) == ["hi"]
    graph = observer.context.graph
    # The publisher's own entry, not only the node's: on DDS a node (ros_discovery_info) and its
    # endpoints (DDS discovery) arrive separately.
    assert graph.wait_for(lambda es: any(e.node_name == "renamed" and e.kind is EntityKind.PUBLISHER
                                         and e.topic == "/remapped/chatter" for e in es),
                          wire.spec.graph_deadline_s)
    assert ("renamed", "/moved") in observer.get_node_names_and_namespaces()
    assert ("talker", "/r1") not in observer.get_node_names_and_namespaces()
    (endpoint,) = graph.endpoints("/remapped/chatter", EntityKind.PUBLISHER)
    assert endpoint.node_fqn == "/moved/renamed"


def test_namespaces_expand_relative_and_private_names(wire: Any) -> None:
    observer = Node("observer", context=wire.context())
    relative, private = Inbox(), Inbox()
    observer.create_subscription(STRING, "/a/b/x", relative, QoS(10))
    observer.create_subscription(STRING, "/a/b/n/y", private, QoS(10))
    node = Node("n", "/a/b", context=wire.context())
    pub_x = node.create_publisher(STRING, "x", QoS(10))
    pub_y = node.create_publisher(STRING, "~/y", QoS(10))
    assert (pub_x.topic_name, pub_y.topic_name) == ("/a/b/x", "/a/b/n/y")
    matched(pub_x, wire)
    matched(pub_y, wire)
    pub_x.publish(String(data="x"))
    pub_y.publish(String(data="y"))
    assert datas(relative.wait(lambda items: len(items) >= 1)) == ["x"]
    assert datas(private.wait(lambda items: len(items) >= 1)) == ["y"]
    graph = observer.context.graph
    # The node and each of its publishers are discovered one by one (on DDS the node from
    # ros_discovery_info, its endpoints from DDS's built-in topics): wait for all three.
    assert graph.wait_for(lambda es: any(e.node_name == "n" and e.namespace == "/a/b" for e in es)
                          and {"/a/b/x", "/a/b/n/y"} <= {e.topic for e in es if e.kind is EntityKind.PUBLISHER},
                          wire.spec.graph_deadline_s)
    topics = dict(observer.get_topic_names_and_types())
    assert topics["/a/b/x"] == [STRING] and topics["/a/b/n/y"] == [STRING]


# --- payloads -----------------------------------------------------------------------------

def test_a_five_megabyte_message_arrives_whole(wire: Any) -> None:
    # Reliable keep-all: the profile that never drops (rmw_zenoh sends keep-last with congestion
    # control DROP, which may drop a message this large on a busy machine, as it may in ROS).
    talker = Node("talker", context=wire.context())
    pub = talker.create_publisher(STRING, "/conformance/large", QoS(0, history=History.KEEP_ALL))
    listener = Node("listener", context=wire.context())
    got = Inbox()
    listener.create_subscription(STRING, "/conformance/large", got, QoS(0, history=History.KEEP_ALL))
    matched(pub, wire)
    size = 5 * 1024 * 1024
    big = (string.ascii_lowercase * (size // 26 + 1))[:size]
    pub.publish(String(data=big))
    (msg,) = got.wait(lambda items: len(items) >= 1, what="5 MB message")
    assert len(msg.data) == len(big) and msg.data == big


def test_a_thousand_messages_in_order_on_reliable_keep_all(wire: Any) -> None:
    talker = Node("talker", context=wire.context())
    pub = talker.create_publisher(STRING, "/conformance/order", QoS(0, history=History.KEEP_ALL))
    listener = Node("listener", context=wire.context())
    got = Inbox()
    listener.create_subscription(STRING, "/conformance/order", got, QoS(0, history=History.KEEP_ALL))
    matched(pub, wire)
    for i in range(1000):
        pub.publish(String(data=str(i)))
    received = got.wait(lambda items: len(items) >= 1000, what="1000 messages")
    assert datas(received) == [str(i) for i in range(1000)]


# --- parameters ---------------------------------------------------------------------------

def test_parameters_hook(wire: Any) -> None:
    ctx = wire.context()
    a, b = Node("a", context=ctx), Node("b", context=ctx)
    a.parameters.set("robot_description", "<robot name='r'/>")
    a.parameters.set("rate", 50)
    assert a.parameters.get("rate") == 50 and a.parameters.has("robot_description")
    assert a.parameters.search("rate") == "rate" and a.parameters.search("missing") is None
    if wire.spec.parameters == "node":
        assert a.parameters.names() == ["rate", "robot_description"]
    else:  # the server also holds what others set (roscore: rosdistro, run_id, ...)
        assert {"rate", "robot_description"} <= set(a.parameters.names())
    a.parameters.delete("rate")
    assert not a.parameters.has("rate")
    with pytest.raises(KeyError):
        a.parameters.get("rate")
    if wire.spec.parameters == "node":
        # rclpy's parameters belong to their node.
        assert not b.parameters.has("robot_description")
    else:
        assert b.parameters.has("robot_description")


def test_closing_a_session_withdraws_all_it_declared(wire: Any) -> None:
    observer = Node("observer", context=wire.context())
    graph = observer.context.graph
    ctx: Context = wire.context()
    Node("short", context=ctx).create_publisher(STRING, "/conformance/short", QoS(10))
    assert graph.wait_for(lambda es: any(e.node_name == "short" for e in es), wire.spec.graph_deadline_s)
    ctx.close()
    assert graph.wait_for(lambda es: not [e for e in es if e.node_name == "short"], wire.spec.graph_deadline_s)


# --- services -----------------------------------------------------------------------------

ADD = "example_interfaces/srv/AddTwoInts"


def test_service_requests_get_their_own_responses(wire: Any) -> None:
    if not wire.spec.services:
        with pytest.raises(BusError, match="no ROS 2 services"):
            Node("server", context=wire.context()).create_service(ADD, "add", lambda *_: None)
        return
    types = typestore().types
    server_node = Node("server", "/conformance", context=wire.context())
    held: list[Any] = []

    def on_request(request: Any, respond: Any, request_id: Any) -> None:
        # Answer out of order: the second request first, from another thread, as executors do.
        held.append((request, respond, request_id))
        if len(held) == 2:
            for req, resp, _rid in reversed(held):
                threading.Thread(target=resp, args=(types[ADD + "_Response"](sum=req.a + req.b),)).start()

    client_node = Node("client", context=wire.context())
    a = client_node.create_client(ADD, "/conformance/add")
    b = Node("client2", context=wire.context()).create_client(ADD, "/conformance/add")
    assert not a.service_is_ready()
    server = server_node.create_service(ADD, "add", on_request)  # relative: /conformance/add
    assert a.wait_for_service(wire.spec.graph_deadline_s) and b.wait_for_service(wire.spec.graph_deadline_s)
    got_a, got_b = Inbox(), Inbox()
    seq_a = a.call_async(types[ADD + "_Request"](a=1, b=2), got_a)
    seq_b = b.call_async(types[ADD + "_Request"](a=40, b=2), got_b)
    assert [r.sum for r in got_a.wait(lambda items: len(items) == 1, what="first response")] == [3]
    assert [r.sum for r in got_b.wait(lambda items: len(items) == 1, what="second response")] == [42]
    ids = sorted((rid.sequence_number, len(rid.client_gid)) for _req, _resp, rid in held)
    assert ids == sorted([(seq_a, 16), (seq_b, 16)]) and held[0][2].client_gid != held[1][2].client_gid
    server.close()
    until(lambda: not a.service_is_ready(), wire.spec.graph_deadline_s, "client sees the server gone")


@pytest.mark.parametrize("wire", [w for w in WIRES if w.services], ids=lambda w: w.name, indirect=True)
def test_a_service_elsewhere_answers(wire: Any) -> None:
    # Wires with processes put the server in a child process: requests and replies cross the wire.
    wire.peer("adder", "/conformance/remote_add")
    types = typestore().types
    client = Node("caller", context=wire.context()).create_client(ADD, "/conformance/remote_add")
    assert client.wait_for_service(wire.spec.graph_deadline_s)
    assert client.call(types[ADD + "_Request"](a=20, b=22), timeout=DELIVERY_S).sum == 42
