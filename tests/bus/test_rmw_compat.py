"""Our reading and writing of rmw_zenoh's graph and sample forms, against forms built by hand.

Each expected value below is written out from rmw_zenoh's rules (Jazzy, zenoh 1.x), not
computed with our own helpers:

- QoS text in a liveliness token (liveliness_utils ``qos_to_keyexpr``/``keyexpr_to_qos``):
  ``rel:dur:hist,depth:dl_sec,dl_nsec:ls_sec,ls_nsec:liv,lease_sec,lease_nsec``, each field
  left empty when it equals rmw_zenoh's default (reliable 1, volatile 2, keep-last 1, depth
  42, durations {9223372036 s, 854775807 ns} = RMW_DURATION_INFINITE, liveliness automatic 1).
  Before writing, rmw_zenoh's ``best_available_qos`` turns a system-default policy (0) into
  its default, depth 0 into 42, and an unspecified duration ({0, 0}, rclpy's
  ``Duration()``) into infinite.
- Reading a token back, rmw_zenoh accepts for each policy exactly the integers of its
  lookup tables: reliability, durability and history 0..3 (system default, the two
  policies, unknown), liveliness 0, 1, 3, 4, 5 (not 2, the deprecated manual-by-node); any
  other value makes it ignore the token. Numbers are decimal.
- Types in tokens and keys are ``pkg::msg::dds_::Name_``; the graph shows them as rmw_zenoh's
  graph cache demangles them: text ending in '_' and holding ``dds_::`` becomes the part
  before ``dds_::`` with every ``::`` made '/', then the name without its final '_';
  anything else is shown as it is.
- Attachment: rmw_zenoh reads int64 sequence number, int64 source time, then the GID as a
  zenoh-ext sequence (LEB128 length that must be 16, then 16 bytes), and does not look at
  what follows; a sample without an attachment is dropped.
"""

from __future__ import annotations

import json
import struct
import threading
import time
from typing import Any

import pytest
import zenoh

from robotmodel.bus import (
    QOS_LATCHED,
    QOS_TF,
    QOS_TF_STATIC,
    Attachment,
    BusError,
    Node,
    QoS,
    RawMessage,
    Token,
    default_domain_id,
    gid_of,
    qos_from_keyexpr,
    qos_to_keyexpr,
    ros_type_name,
    typestore,
)
from robotmodel.bus._attachment import is_attachment, read_attachment
from robotmodel.bus._config import rendezvous_endpoint
from robotmodel.bus._qos import DURATION_INFINITE_NS, Durability, History, Liveliness, Reliability

INF = DURATION_INFINITE_NS
STRING_HASH = "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"


def token(kind: str, qos: str, *, ns: str = "%", node: str = "talker", topic: str = "%chatter",
          enclave: str = "%", ids: str = "0/10") -> str:
    """An entity token as an rmw_zenoh node writes it (domain 0, a made-up session id)."""
    return (f"@ros2_lv/0/8b20917502ee955ac4476e0266340d5c/{ids}/{kind}/{enclave}/{ns}/{node}/{topic}/"
            f"std_msgs::msg::dds_::String_/{STRING_HASH}/{qos}")


# --- writing the QoS text -----------------------------------------------------------------

@pytest.mark.parametrize(("qos", "text"), [
    # rclcpp's SensorDataQoS: best effort, keep last 5.
    (QoS(5, Reliability.BEST_EFFORT), "2::,5:,:,:,,"),
    # tf2_ros StaticBroadcasterQoS: transient local, keep last 1.
    (QoS(1, durability=Durability.TRANSIENT_LOCAL), ":1:,1:,:,:,,"),
    # KeepAll with depth 0: the depth becomes 42, the default, so it is left empty.
    (QoS(0, history=History.KEEP_ALL), "::2,:,:,:,,"),
    # System defaults everywhere: rmw_zenoh's defaults, all empty.
    (QoS(0, Reliability.SYSTEM_DEFAULT, Durability.SYSTEM_DEFAULT, History.SYSTEM_DEFAULT,
         liveliness=Liveliness.SYSTEM_DEFAULT), "::,:,:,:,,"),
    # A deadline of 100 ms: {0 s, 100000000 ns}; 0 s differs from the default seconds.
    (QoS(10, deadline_ns=100_000_000), "::,10:0,100000000:,:,,"),
    # Manual-by-topic liveliness with a 1.5 s lease.
    (QoS(10, liveliness=Liveliness.MANUAL_BY_TOPIC, liveliness_lease_ns=1_500_000_000),
     "::,10:,:,:3,1,500000000"),
    # rclpy's unspecified durations (Duration() = 0 ns) are made infinite before writing.
    (QoS(10, deadline_ns=0, lifespan_ns=0, liveliness_lease_ns=0), "::,10:,:,:,,"),
])
def test_qos_text_as_rmw_zenoh_writes_it(qos: QoS, text: str) -> None:
    assert qos_to_keyexpr(qos) == text


def test_unspecified_durations_resolve_to_infinite() -> None:
    q = QoS(10, deadline_ns=0, lifespan_ns=0, liveliness_lease_ns=0).resolved()
    assert (q.deadline_ns, q.lifespan_ns, q.liveliness_lease_ns) == (INF, INF, INF)


# --- reading tokens real nodes write ------------------------------------------------------

def test_compact_default_qos_from_a_real_node_parses() -> None:
    e = Token.parse(token("MS", "::,10:,:,:,,", ids="0/12"))
    assert e.qos == QoS(10)
    assert (e.node_id, e.entity_id, e.topic, e.typename, e.type_hash) == (
        0, 12, "/chatter", "std_msgs/msg/String", STRING_HASH)
    # Every field empty: rmw_zenoh's defaults, depth 42.
    assert Token.parse(token("MS", "::,:,:,:,,")).qos == QoS(42)


def test_nested_namespace_enclave_and_topic_are_demangled() -> None:
    e = Token.parse(token("MP", "2::,5:,:,:,,", ns="%robots%r1", enclave="%secure%arm",
                           topic="%robots%r1%scan"))
    assert (e.namespace, e.enclave, e.topic, e.node_fqn) == ("/robots/r1", "/secure/arm", "/robots/r1/scan",
                                                            "/robots/r1/talker")
    assert e.qos == QoS(5, Reliability.BEST_EFFORT)
    # Written back, it is the same text (and so the same GID as the writer's).
    assert e.keyexpr == e.token


def test_node_and_entity_ids_are_opaque_text_as_in_rmw_zenoh() -> None:
    # rmw_zenoh keeps the session, node and entity ids of a token as text and only asks
    # that they be non-empty; nodes are told apart by (session id, node id) text.
    e = Token.parse(token("MP", "::,7:,:,:,,", ids="n1/pub-a"))
    assert (e.node_id, e.entity_id) == ("n1", "pub-a")
    assert e.keyexpr == e.token
    node = Token.parse("@ros2_lv/0/abc/n1/n1/NN/%/%/talker")
    assert node.node_id == "n1" and node.keyexpr == node.token
    # Decimal ids read as numbers (ours are), so the two spellings name the same node.
    assert Token.parse(token("MP", "::,7:,:,:,,", ids="0/10")).node_id == 0


@pytest.mark.parametrize(("text", "expected"), [
    # liveliness BEST_AVAILABLE (5) and UNKNOWN (4) are in rmw_zenoh's table.
    ("::,10:,:,:5,,", QoS(10, liveliness=Liveliness.BEST_AVAILABLE)),
    ("::,10:,:,:4,,", QoS(10, liveliness=Liveliness.UNKNOWN)),
    # UNKNOWN (3) reliability, durability and history too.
    ("3:3:3,10:,:,:,,", QoS(10, Reliability.UNKNOWN, Durability.UNKNOWN, History.UNKNOWN)),
    # rclpy's best-available durations {9223372036 s, 854775806 ns} are plain durations.
    ("::,10:9223372036,854775806:,:,9223372036,854775806",
     QoS(10, deadline_ns=INF - 1, liveliness_lease_ns=INF - 1)),
])
def test_policies_rmw_zenoh_accepts_are_read(text: str, expected: QoS) -> None:
    assert qos_from_keyexpr(text) == expected
    assert Token.parse(token("MS", text)).qos == expected


@pytest.mark.parametrize("text", [
    "4::,10:,:,:,,",        # reliability BEST_AVAILABLE: not in rmw_zenoh's table
    ":4:,10:,:,:,,",        # durability BEST_AVAILABLE: same
    "::4,10:,:,:,,",        # no history 4
    "::,10:,:,:2,,",        # liveliness 2 (deprecated manual-by-node): not in the table
    "::,10:,:,:,",          # liveliness needs three components
    "::,x:,:,:,,",          # not a number
    "::01,10:,:,:,,",       # policies are looked up by their exact text
    "::,10:,:,",            # too few fields
])
def test_tokens_rmw_zenoh_rejects_are_rejected(text: str) -> None:
    with pytest.raises(BusError):
        qos_from_keyexpr(text)
    with pytest.raises(BusError):
        Token.parse(token("MS", text))


@pytest.mark.parametrize(("dds", "ros"), [
    ("std_msgs::msg::dds_::String_", "std_msgs/msg/String"),
    ("example_interfaces::srv::dds_::AddTwoInts_", "example_interfaces/srv/AddTwoInts"),
    ("action_tutorials::action::dds_::Fibonacci_SendGoal_", "action_tutorials/action/Fibonacci_SendGoal"),
    # More (or fewer) '::' chunks before dds_:: all become '/'.
    ("pkg::msg::detail::dds_::Thing_", "pkg/msg/detail/Thing"),
    ("pkg::dds_::Thing_", "pkg/Thing"),
    # Not a ROS DDS name: shown as it is.
    ("std_msgs::msg::String", "std_msgs::msg::String"),
    ("plain_", "plain_"),
])
def test_type_names_demangled_as_rmw_zenohs_graph_cache(dds: str, ros: str) -> None:
    assert ros_type_name(dds) == ros


# --- the attachment -----------------------------------------------------------------------

GID = bytes(range(16))


def test_attachment_bytes_by_hand() -> None:
    by_hand = (7).to_bytes(8, "little", signed=True) + (-5).to_bytes(8, "little", signed=True) + b"\x10" + GID
    assert Attachment(7, -5, GID).encode() == by_hand
    assert Attachment.decode(by_hand) == (7, -5, GID)
    assert read_attachment(by_hand) == (7, -5, GID) and read_attachment(None) is None


def test_trailing_bytes_after_the_gid_are_ignored() -> None:
    att = struct.pack("<qqB", 3, 1_700_000_000_000_000_000, 16) + GID + b"\x01\x02\x03\x04"
    assert is_attachment(att)
    assert Attachment.decode(att) == (3, 1_700_000_000_000_000_000, GID)
    assert read_attachment(att) == (3, 1_700_000_000_000_000_000, GID)


def test_labelled_attachment_of_jazzy_before_0_2_4_is_read() -> None:
    # rmw_zenoh Jazzy 0.2.0-0.2.3 (before ros2/rmw_zenoh#601) wrote each field behind its
    # name, all with the zenoh-ext serializer: string (LEB128 length, bytes), int64 LE.
    def text(s: bytes) -> bytes:
        return bytes([len(s)]) + s

    old = (text(b"sequence_number") + struct.pack("<q", 9) + text(b"source_timestamp") + struct.pack("<q", 11)
           + text(b"source_gid") + b"\x10" + GID)
    assert len(old) == 77
    assert is_attachment(old)
    assert Attachment.decode(old) == (9, 11, GID)
    # Sequence number 16 puts 0x10 where today's form has its GID length: still labelled.
    old16 = old.replace(struct.pack("<q", 9), struct.pack("<q", 16), 1)
    assert Attachment.decode(old16) == (16, 11, GID)
    # The receive path's fast reader agrees.
    assert read_attachment(old) == (9, 11, GID) and read_attachment(old16) == (16, 11, GID)
    # Written, we use only today's form.
    assert len(Attachment(9, 11, GID).encode()) == 33


@pytest.mark.parametrize("att", [
    b"",
    struct.pack("<qqB", 1, 2, 16) + GID[:15],           # GID cut short
    struct.pack("<qqB", 1, 2, 24) + GID + bytes(8),     # a 24-byte GID: rmw_zenoh wants 16
    struct.pack("<qq", 1, 2),
])
def test_attachments_rmw_zenoh_cannot_read_are_refused(att: bytes) -> None:
    assert not is_attachment(att)
    assert read_attachment(att) is None
    with pytest.raises(BusError):
        Attachment.decode(att)


# --- live: a plain zenoh session playing an rmw_zenoh node --------------------------------

def plain_session() -> zenoh.Session:
    """A zenoh peer on the test's rendezvous, configured like an rmw_zenoh session."""
    config = zenoh.Config()
    config.insert_json5("mode", '"peer"')
    config.insert_json5("listen/endpoints", '["tcp/127.0.0.1:0"]')
    config.insert_json5("connect/endpoints", json.dumps([rendezvous_endpoint()]))
    config.insert_json5("scouting/multicast/enabled", "false")
    config.insert_json5("timestamping/enabled", "true")
    return zenoh.open(config)


def test_samples_from_another_writer_by_their_attachment(bus_env: dict[str, str]) -> None:
    domain = int(bus_env["ROS_DOMAIN_ID"])
    got: list[RawMessage] = []
    arrived = threading.Condition()

    def on_msg(m: RawMessage) -> None:
        with arrived:
            got.append(m)
            arrived.notify_all()

    key = f"{domain}/chatter/std_msgs::msg::dds_::String_/{STRING_HASH}"
    payload = b"\x00\x01\x00\x00" + struct.pack("<I", 3) + b"hi\x00"
    with Node("listener") as node:
        node.create_subscription("std_msgs/msg/String", "/chatter", on_msg, raw=True)
        other = plain_session()
        try:
            pub = other.declare_publisher(key)
            end = time.monotonic() + 10
            while not pub.matching_status.matching and time.monotonic() < end:
                time.sleep(0.01)
            # What rmw_zenoh drops: no attachment, a short one, a GID length other than 16.
            pub.put(payload)
            pub.put(payload, attachment=struct.pack("<qqB", 1, 2, 16) + GID[:8])
            pub.put(payload, attachment=struct.pack("<qqB", 1, 2, 24) + GID + bytes(8))
            # What it reads: the three fields, whatever follows them.
            pub.put(payload, attachment=struct.pack("<qqB", 5, 6, 16) + GID + b"more")
            pub.put(payload, attachment=struct.pack("<qqB", 7, 8, 16) + GID)
            with arrived:
                assert arrived.wait_for(lambda: len(got) >= 2, 10), got
        finally:
            other.close()
    assert [(m.info.sequence_number, m.info.source_timestamp_ns, m.info.gid) for m in got] == [
        (5, 6, GID), (7, 8, GID)]
    assert [m.payload for m in got] == [payload, payload]


def test_graph_shows_a_real_nodes_tokens(bus_env: dict[str, str]) -> None:
    domain = int(bus_env["ROS_DOMAIN_ID"])
    zid = "8b20917502ee955ac4476e0266340d5c"
    head = f"@ros2_lv/{domain}/{zid}"
    # As rclcpp's talker in namespace /robots/r1 (enclave '/') declares them: its ids come
    # from one counter that rclcpp's own parameter services and /rosout also draw from.
    tokens = [
        f"{head}/0/0/NN/%/%robots%r1/talker",
        f"{head}/0/10/MP/%/%robots%r1/talker/%robots%r1%chatter/std_msgs::msg::dds_::String_/{STRING_HASH}/"
        "::,7:,:,:,,",
        # ros2 topic echo's best-available liveliness: rmw_zenoh keeps the token.
        f"{head}/0/11/MS/%/%robots%r1/talker/%robots%r1%cmd/std_msgs::msg::dds_::String_/{STRING_HASH}/"
        "2::,10:,:,:5,,",
        # Best-available reliability: rmw_zenoh ignores the token, so does the graph.
        f"{head}/0/12/MS/%/%robots%r1/talker/%robots%r1%ignored/std_msgs::msg::dds_::String_/{STRING_HASH}/"
        "4::,10:,:,:,,",
    ]
    with Node("viewer") as node:
        other = plain_session()
        try:
            held = [other.liveliness().declare_token(t) for t in tokens]
            graph = node.context.graph
            assert graph.wait_for(lambda es: len([e for e in es if e.node_key.startswith(zid + "/")]) >= 3, 10)
            assert ("talker", "/robots/r1") in node.get_node_names_and_namespaces()
            topics = dict(node.get_topic_names_and_types())
            assert topics["/robots/r1/chatter"] == ["std_msgs/msg/String"]
            assert topics["/robots/r1/cmd"] == ["std_msgs/msg/String"]
            assert "/robots/r1/ignored" not in topics
            pub = graph.by_gid(gid_of(tokens[1]))
            assert pub is not None and pub.qos == QoS(7)
            for h in held:
                h.undeclare()
            assert graph.wait_for(lambda es: not [e for e in es if e.node_key.startswith(zid + "/")], 10)
        finally:
            other.close()


def test_node_list_counts_nodes_as_rmw_zenohs_graph_cache(bus_env: dict[str, str]) -> None:
    # rmw_zenoh's graph holds one node per (session id, node id), made from whichever of its
    # tokens comes first, and lists every one: two 'talker' nodes are listed twice (ros2
    # node list then warns that names are shared).
    domain = int(bus_env["ROS_DOMAIN_ID"])
    a, b, c = "1a2b", "3c4d", "5e6f"
    tokens = [
        f"@ros2_lv/{domain}/{a}/0/0/NN/%/%/talker",
        f"@ros2_lv/{domain}/{b}/3/3/NN/%/%/talker",
        # A node known only from its publisher's token.
        f"@ros2_lv/{domain}/{c}/7/8/MP/%/%/lonely/%chatter/std_msgs::msg::dds_::String_/{STRING_HASH}/::,7:,:,:,,",
        # Its second entity names the same node: still one node.
        f"@ros2_lv/{domain}/{c}/7/9/MS/%/%/lonely/%chatter/std_msgs::msg::dds_::String_/{STRING_HASH}/::,7:,:,:,,",
    ]
    with Node("viewer") as node:
        other = plain_session()
        try:
            held = [other.liveliness().declare_token(t) for t in tokens]
            graph = node.context.graph
            assert graph.wait_for(lambda es: len([e for e in es if e.node_key.split("/")[0] in (a, b, c)]) == 4, 10)
            listed = node.get_node_names_and_namespaces()
            assert sorted(n for n in listed if n[0] != "viewer") == [
                ("lonely", "/"), ("talker", "/"), ("talker", "/")]
            for h in held:
                h.undeclare()
        finally:
            other.close()


def rmw_zenoh_session(port: int) -> zenoh.Session:
    """A session with DEFAULT_RMW_ZENOH_SESSION_CONFIG's settings, its router port made ``port``."""
    config = zenoh.Config()
    for key, value in {
        "mode": '"peer"',
        "connect/endpoints": json.dumps([f"tcp/localhost:{port}"]),
        "listen/endpoints": '["tcp/localhost:0"]',
        "scouting/multicast/enabled": "false",
        "scouting/gossip/enabled": "true",
        "scouting/gossip/multihop": "false",
        "scouting/gossip/target": '{router: ["router", "peer"], peer: ["router"]}',
        "scouting/gossip/autoconnect": '{router: [], peer: ["router", "peer"]}',
        "scouting/gossip/autoconnect_strategy": '{peer: {to_router: "always", to_peer: "greater-zid"}}',
        "timestamping/enabled": "{router: true, peer: true, client: true}",
        "queries_default_timeout": "60000",
        "transport/link/tx/lease": "60000",
        "transport/link/tx/keep_alive": "2",
        "transport/shared_memory/enabled": "false",
    }.items():
        config.insert_json5(key, value)
    return zenoh.open(config)


def test_rmw_zenoh_sessions_meet_ours_without_a_router(bus_env: dict[str, str]) -> None:
    # No rmw_zenohd: our first session starts a router on the port rmw_zenoh's sessions
    # connect to. rmw_zenoh's sessions gossip their endpoints to routers only, and peers
    # forward nothing for others, so unless a router (as rmw_zenohd) is there, they never
    # link with each other or with our later sessions, and their samples are lost.
    domain = int(bus_env["ROS_DOMAIN_ID"])
    port = int(bus_env["ROBOTMODEL_ZENOH_PORT"])
    key = f"{domain}/chatter/std_msgs::msg::dds_::String_/{STRING_HASH}"
    payload = b"\x00\x01\x00\x00" + struct.pack("<I", 3) + b"hi\x00"
    got_b: list[bytes] = []
    got_viewer: list[str] = []
    with Node("robot"), Node("viewer") as viewer:
        viewer.create_subscription("std_msgs/msg/String", "/chatter", lambda m: got_viewer.append(m.data))
        a = rmw_zenoh_session(port)
        b = rmw_zenoh_session(port)
        try:
            b.declare_subscriber(key, lambda s: got_b.append(s.payload.to_bytes()))
            pub = a.declare_publisher(key)
            # Generous: gossip and the links it brings take seconds on a loaded 2-core machine.
            end = time.monotonic() + 30
            while time.monotonic() < end and not (got_b and got_viewer):
                pub.put(payload, attachment=struct.pack("<qqB", 1, time.time_ns(), 16) + GID)
                time.sleep(0.05)
            assert got_b, "one rmw_zenoh session did not reach another"
            assert got_viewer == ["hi"] * len(got_viewer) and got_viewer, "our second session got nothing"
            # ros2 node list's view from their side (once gossip has linked them to us).
            seen: list[str] = []
            end = time.monotonic() + 30
            mine = viewer.handle.token.keyexpr  # type: ignore[attr-defined]
            while mine not in seen and time.monotonic() < end:
                seen = [str(r.ok.key_expr) for r in a.liveliness().get(f"@ros2_lv/{domain}/**", timeout=2)
                        if r.ok is not None]
            assert mine in seen
        finally:
            a.close()
            b.close()


# --- congestion control -------------------------------------------------------------------

def test_congestion_control_as_rmw_zenoh_chooses_it(bus_env: dict[str, str]) -> None:
    # rmw_zenoh: BLOCK only for reliable + keep-all, DROP otherwise, tf2_ros's and
    # robot_state_publisher's keep-last profiles included.
    for qos in (QOS_TF, QOS_TF_STATIC, QOS_LATCHED, QoS(10), QoS(0, history=History.KEEP_ALL,
                                                               reliability=Reliability.BEST_EFFORT)):
        assert not qos.blocks, qos
    assert QoS(0, history=History.KEEP_ALL).blocks
    with Node("talker") as node:
        tf = node.create_publisher("tf2_msgs/msg/TFMessage", "/tf", QOS_TF)
        every = node.create_publisher("std_msgs/msg/String", "/log", QoS(0, history=History.KEEP_ALL))
        raw: Any = tf.handle
        assert raw.raw._pub.congestion_control == zenoh.CongestionControl.DROP
        raw = every.handle
        assert raw.raw._pub.congestion_control == zenoh.CongestionControl.BLOCK


# --- the domain id ------------------------------------------------------------------------
# rcl reads ROS_DOMAIN_ID with strtoul(text, &end, 0): leading blanks and a sign are
# skipped, '0x' means hex and a leading '0' octal, digits are read as far as they go.
# It fails with "ROS_DOMAIN_ID is not an integral number" only when that gives 0 with
# text left over, and with "ROS_DOMAIN_ID is out of range" past 2**64 - 1; a negative
# number wraps modulo 2**64. rcl and rmw_zenoh then take SIZE_MAX (rcl's "default
# domain") as domain 0.

@pytest.mark.parametrize(("text", "domain"), [
    ("", 0), ("7", 7), (" \t7", 7), ("+7", 7), ("010", 8), ("0x2a", 42), ("0X2A", 42),
    ("5abc", 5), ("0", 0), ("-1", 0), ("-2", 2**64 - 2), (str(2**64 - 1), 0),
])
def test_ros_domain_id_read_as_rcl_reads_it(monkeypatch: pytest.MonkeyPatch, text: str, domain: int) -> None:
    monkeypatch.setenv("ROS_DOMAIN_ID", text)
    assert default_domain_id() == domain


@pytest.mark.parametrize(("text", "message"), [
    ("abc", "ROS_DOMAIN_ID is not an integral number"),
    ("08", "ROS_DOMAIN_ID is not an integral number"),   # octal: reads '0', then '8' is left
    ("0x", "ROS_DOMAIN_ID is not an integral number"),
    (" ", "ROS_DOMAIN_ID is not an integral number"),
    (str(2**64), "ROS_DOMAIN_ID is out of range"),
])
def test_bad_ros_domain_id_fails_with_rcls_text(monkeypatch: pytest.MonkeyPatch, text: str, message: str) -> None:
    monkeypatch.setenv("ROS_DOMAIN_ID", text)
    with pytest.raises(BusError) as err:
        default_domain_id()
    assert str(err.value) == message


# --- latched topics -----------------------------------------------------------------------
# rmw_zenoh's TRANSIENT_LOCAL: the publisher is a zenoh-ext AdvancedPublisher with a cache
# of `depth` samples and publisher detection, plus sample-miss detection with a sporadic
# 500 ms heartbeat when reliable; the subscription an AdvancedSubscriber with subscriber
# detection, history (late-publisher detection, `depth` samples) and, when reliable,
# heartbeat-driven recovery. Built here from those options, not from our backend.

TF_HASH = "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087"


def test_latched_both_ways_with_rmw_zenohs_advanced_pub_sub(bus_env: dict[str, str]) -> None:
    import zenoh.ext as zx

    from robotmodel.bus import QOS_TF_STATIC_LISTENER
    from robotmodel.msgs import TFMessage

    domain = int(bus_env["ROS_DOMAIN_ID"])
    port = int(bus_env["ROBOTMODEL_ZENOH_PORT"])
    tf_static = f"{domain}/tf_static/tf2_msgs::msg::dds_::TFMessage_/{TF_HASH}"
    description = f"{domain}/robot_description/std_msgs::msg::dds_::String_/{STRING_HASH}"
    static_payload = bytes(typestore().serialize_cdr(
        typestore().types["tf2_msgs/msg/TFMessage"](transforms=[]), "tf2_msgs/msg/TFMessage"))
    got_static: list[Any] = []
    got_description: list[zenoh.Sample] = []
    with Node("robot") as node:
        ros = rmw_zenoh_session(port)
        try:
            # Theirs first, ours late: a static broadcaster (reliable, depth 1).
            theirs = zx.declare_advanced_publisher(
                ros, tf_static, cache=zx.CacheConfig(1), publisher_detection=True,
                sample_miss_detection=zx.MissDetectionConfig(sporadic_heartbeat=0.5),
                congestion_control=zenoh.CongestionControl.DROP, reliability=zenoh.Reliability.RELIABLE)
            theirs.put(static_payload, attachment=struct.pack("<qqB", 1, time.time_ns(), 16) + GID)
            node.create_subscription(TFMessage, "/tf_static", got_static.append, QOS_TF_STATIC_LISTENER)
            # Ours first, theirs late: robot_state_publisher's /robot_description.
            pub = node.create_publisher("std_msgs/msg/String", "/robot_description", QOS_LATCHED)
            pub.publish(typestore().types["std_msgs/msg/String"](data="<robot name='r'/>"))
            zx.declare_advanced_subscriber(
                ros, description, got_description.append, subscriber_detection=True,
                history=zx.HistoryConfig(detect_late_publishers=True, max_samples=1),
                recovery=zx.RecoveryConfig(heartbeat=True))
            end = time.monotonic() + 15
            while not (got_static and got_description) and time.monotonic() < end:
                time.sleep(0.01)
        finally:
            ros.close()
    assert got_static and got_static[0].transforms == []
    assert got_description, "an rmw_zenoh-style late subscriber got nothing from our latched publisher"
    sample = got_description[0]
    att = sample.attachment.to_bytes() if sample.attachment is not None else b""
    assert len(att) == 33 and att[16] == 16 and att[17:] == pub.gid
    assert typestore().deserialize_cdr(sample.payload.to_bytes(), "std_msgs/msg/String").data == "<robot name='r'/>"
