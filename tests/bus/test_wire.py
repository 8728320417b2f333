"""The bytes a /tf publisher puts on zenoh, against values derived by hand from rmw_zenoh's design.

Derivation (rmw_zenoh docs/design.md, "Topic and Service name mapping", "Graph Cache",
"Publishers"; liveliness_utils.cpp for the QoS text):

- Key: ``<domain_id>/<fully qualified name>/<type_name>/<type_hash>``: the name without its
  leading '/', the type as DDS names it for CDR (``tf2_msgs::msg::dds_::TFMessage_``) and
  the REP-2011 hash. The TFMessage hash below is the one published in ZettaScale's
  rmw_zenoh TF example (the same text the design doc's String example follows).
- Publisher token: ``@ros2_lv/<domain>/<zid>/<node id>/<entity id>/MP/<enclave>/<namespace>/
  <node>/<topic>/<type>/<hash>/<qos>``; every '/' inside a chunk becomes '%' (root enclave
  and namespace are '%', topic /tf is '%tf'). The node token stops after the node name and
  repeats the node id. Ids come from one counter per session: the node 0, its publisher 1.
- QoS text ``rel:dur:hist,depth:dl:ls:liv``, a field left empty when it equals rmw_zenoh's
  default (reliable, volatile, keep-last, depth 42, infinite durations, automatic): tf2_ros's
  broadcaster (keep-last 100, reliable, volatile) gives ``::,100:,:,:,,``.
- Attachment: int64 LE sequence number (1 for a publisher's first message), int64 LE source
  time in ns since the epoch, one byte 16 (the GID length), the 16-byte GID.
- GID: XXH3-128 of the publisher's token, low 64 bits then high 64 bits, little-endian
  (checked below on the design doc's talker token against the value rmw_zenoh's own C++
  xxhash gives, from its simplified_xxhash3.cpp compiled on its own).
- Payload: CDR encapsulation header ``00 01 00 00`` (little-endian CDR) and the XCDR1 body:
  uint32 transform count; per transform int32 sec, uint32 nanosec, then each string as
  uint32 length counting its NUL, the bytes and the NUL, 4-aligned for the next length;
  the seven float64 of the pose 8-aligned (alignment counted from the body's start).
"""

from __future__ import annotations

import json
import re
import struct
import threading
import time

import xxhash
import zenoh

from robotmodel.bus import QOS_TF, EntityKind, Node, Token, gid_of, topic_keyexpr
from robotmodel.bus._config import rendezvous_endpoint
from robotmodel.msgs import TFMessage, make_transform

TF_HASH = "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087"
DESIGN_TALKER = ("@ros2_lv/0/8b20917502ee955ac4476e0266340d5c/0/10/MP/%/%/talker/%chatter/"
                 "std_msgs::msg::dds_::String_/"
                 "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18/::,7:,:,:,,")


def hand_payload() -> bytes:
    """TFMessage([world -> base_link at 12.5 s, t = (1, 2, 3), q = (0, 0, 0.6, 0.8)]) in CDR, by hand."""
    body = b""
    body += struct.pack("<I", 1)                                  # offset 0: one transform
    body += struct.pack("<iI", 12, 500_000_000)                   # 4: stamp
    body += struct.pack("<I", 6) + b"world\x00"                   # 12: "world" + NUL, ends at 22
    body += b"\x00\x00"                                           # 22: align the next length to 24
    body += struct.pack("<I", 10) + b"base_link\x00"              # 24: "base_link" + NUL, ends at 38
    body += b"\x00\x00"                                           # 38: align the doubles to 40
    body += struct.pack("<7d", 1.0, 2.0, 3.0, 0.0, 0.0, 0.6, 0.8)  # 40: pose, ends at 96
    assert len(body) == 96
    return b"\x00\x01\x00\x00" + body


def test_keyexpr_by_hand() -> None:
    assert topic_keyexpr(0, "/tf", "tf2_msgs/msg/TFMessage", TF_HASH) == (
        "0/tf/tf2_msgs::msg::dds_::TFMessage_/" + TF_HASH)
    assert topic_keyexpr(2, "/robot1/tf", "tf2_msgs/msg/TFMessage", TF_HASH).startswith(
        "2/robot1/tf/tf2_msgs::msg::dds_::TFMessage_/")


def test_gid_matches_rmw_zenoh_xxhash_on_the_design_token() -> None:
    assert gid_of(DESIGN_TALKER).hex() == "eb85fa883b7846dc448a4501890ad062"
    parsed = Token.parse(DESIGN_TALKER)
    assert (parsed.topic, parsed.typename, parsed.qos.depth if parsed.qos else None) == (
        "/chatter", "std_msgs/msg/String", 7)
    assert parsed.keyexpr == DESIGN_TALKER


def test_a_live_tf_publisher_puts_rmw_zenohs_bytes(bus_env: dict[str, str]) -> None:
    domain = int(bus_env["ROS_DOMAIN_ID"])
    config = zenoh.Config()
    config.insert_json5("mode", '"peer"')
    config.insert_json5("listen/endpoints", '["tcp/127.0.0.1:0"]')
    config.insert_json5("connect/endpoints", json.dumps([rendezvous_endpoint()]))
    config.insert_json5("scouting/multicast/enabled", "false")
    samples: list[zenoh.Sample] = []
    arrived = threading.Event()

    def on_sample(s: zenoh.Sample) -> None:
        samples.append(s)
        arrived.set()

    with Node("tf_pub") as node:
        session_zid = str(node.context.backend.session.zid())  # type: ignore[attr-defined]
        spy = zenoh.open(config)  # a plain zenoh session, as any rmw_zenoh peer would be
        try:
            spy.declare_subscriber(f"{domain}/**", on_sample)
            pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
            # Ready when the spy sees both tokens and the publisher sees the spy's subscriber.
            tokens: list[str] = []
            end = time.monotonic() + 10
            while (len(tokens) < 2 or not pub.matched()) and time.monotonic() < end:
                tokens = [str(r.ok.key_expr) for r in spy.liveliness().get(f"@ros2_lv/{domain}/**", timeout=2)
                          if r.ok is not None]
                time.sleep(0.01)
            before = time.time_ns()
            pub.publish(TFMessage([make_transform("world", "base_link", (1.0, 2.0, 3.0), (0.0, 0.0, 0.6, 0.8),
                                                  stamp_ns=12_500_000_000)]))
            after = time.time_ns()
            assert arrived.wait(10), "the spy received nothing"
        finally:
            spy.close()

    zid = node.context.backend.zid
    # zenoh's own text of the id (rmw_zenoh writes zid.to_string()): lowercase hex of the
    # little-endian 128-bit id, without leading zeros, so 32 digits or (1 in 16) fewer.
    assert re.fullmatch(r"[0-9a-f]{1,32}", zid) and zid == session_zid
    node_token = f"@ros2_lv/{domain}/{zid}/0/0/NN/%/%/tf_pub"
    pub_token = (f"@ros2_lv/{domain}/{zid}/0/1/MP/%/%/tf_pub/%tf/tf2_msgs::msg::dds_::TFMessage_/{TF_HASH}/"
                 "::,100:,:,:,,")
    assert sorted(tokens) == sorted([node_token, pub_token])

    sample = samples[0]
    assert str(sample.key_expr) == f"{domain}/tf/tf2_msgs::msg::dds_::TFMessage_/{TF_HASH}"
    assert sample.payload.to_bytes() == hand_payload()
    assert str(sample.encoding) == "zenoh/bytes"  # rmw_zenoh sets no encoding

    assert sample.attachment is not None
    att = sample.attachment.to_bytes()
    assert len(att) == 33
    seq, stamp = struct.unpack_from("<qq", att)
    assert seq == 1
    assert before <= stamp <= after
    assert att[16] == 16
    digest = xxhash.xxh3_128(pub_token.encode()).intdigest()
    expected_gid = (digest & (2**64 - 1)).to_bytes(8, "little") + (digest >> 64).to_bytes(8, "little")
    assert att[17:] == expected_gid


def test_design_doc_tokens_parse() -> None:
    node = Token.parse("@ros2_lv/2/aac3178e146ba6f1fc6e6a4085e77f21/0/0/NN/%/%/listener")
    assert (node.domain_id, node.kind, node.namespace, node.node_name, node.enclave) == (
        2, EntityKind.NODE, "/", "listener", "/")
    assert node.keyexpr == "@ros2_lv/2/aac3178e146ba6f1fc6e6a4085e77f21/0/0/NN/%/%/listener"
    server = Token.parse(
        "@ros2_lv/2/f9980ee0495eaafb3e38f0d19e2eae12/0/10/SS/%/%/add_two_ints_server/%add_two_ints/"
        "example_interfaces::srv::dds_::AddTwoInts_/"
        "RIHS01_e118de6bf5eeb66a2491b5bda11202e7b68f198d6f67922cf30364858239c81a/::,10:,:,:,,")
    assert (server.kind, server.topic, server.typename) == (
        EntityKind.SERVICE, "/add_two_ints", "example_interfaces/srv/AddTwoInts")
    # A namespaced node: every '/' of the namespace and of the topic written '%'.
    ns = Token(0, "abc", 3, 4, Token.parse(DESIGN_TALKER).kind, "/robot1", "talker", "/", "/robot1/chatter",
                "std_msgs/msg/String", "RIHS01_x", Token.parse(DESIGN_TALKER).qos)
    assert ns.keyexpr == ("@ros2_lv/0/abc/3/4/MP/%/%robot1/talker/%robot1%chatter/std_msgs::msg::dds_::String_/"
                          "RIHS01_x/::,7:,:,:,,")
    assert Token.parse(ns.keyexpr) == ns


def test_node_and_entity_ids_follow_one_counter_per_session(bus_env: dict[str, str]) -> None:
    # rmw_zenoh numbers a session's nodes and their publishers and subscriptions with one counter.
    from robotmodel.bus import Context

    with Context() as ctx:
        node = Node("n", context=ctx)
        pub = node.create_publisher("std_msgs/msg/String", "a")
        sub = node.create_subscription("std_msgs/msg/String", "b", lambda m: None)
        other = Node("m", context=ctx)
        tokens = [node.handle.token, pub.handle.token, other.handle.token]  # type: ignore[union-attr]
        assert [(t.node_id, t.entity_id) for t in tokens] == [(0, 0), (0, 1), (3, 3)]
        assert sub.handle is not None
