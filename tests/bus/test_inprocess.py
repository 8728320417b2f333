"""The node API on the in-process backend: delivery, latching, sample info, graph, bad payloads."""

from __future__ import annotations

import logging
from typing import Any

import pytest

from robotmodel.bus import (
    QOS_TF,
    QOS_TF_STATIC,
    QOS_TF_STATIC_LISTENER,
    Attachment,
    BusError,
    Context,
    Node,
    RawMessage,
    TFRecords,
    codec_for,
    gid_of,
    typestore,
)
from robotmodel.msgs import TFMessage, make_transform

String = typestore().types["std_msgs/msg/String"]


def test_publish_subscribe_robotmodel_messages() -> None:
    got: list[TFMessage] = []
    with Node("listener", backend="inprocess", domain_id=101) as node:
        node.create_subscription(TFMessage, "/tf", got.append, QOS_TF)
        pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
        msg = TFMessage([make_transform("world", "base", (1.0, 2.0, 3.0), stamp_ns=5_000_000_123)])
        pub.publish(msg)
    assert got == [msg]


def test_domains_do_not_mix() -> None:
    got: list[object] = []
    with Node("a", backend="inprocess", domain_id=102) as a, Node("b", backend="inprocess", domain_id=103) as b:
        a.create_subscription(String, "chatter", got.append)
        b.create_publisher(String, "chatter").publish(String(data="x"))
    assert got == []


def test_latched_reaches_late_and_early_subscribers() -> None:
    early: list[TFMessage] = []
    late: list[TFMessage] = []
    with Node("static", backend="inprocess", domain_id=104) as node:
        node.create_subscription(TFMessage, "/tf_static", early.append, QOS_TF_STATIC_LISTENER)
        pub = node.create_publisher(TFMessage, "/tf_static", QOS_TF_STATIC)
        first = TFMessage([make_transform("a", "b")])
        second = TFMessage([make_transform("a", "c")])
        pub.publish(first)
        pub.publish(second)
        node.create_subscription(TFMessage, "/tf_static", late.append, QOS_TF_STATIC_LISTENER)
    assert early == [first, second]
    assert late == [second]  # the publisher's cache holds depth 1, as tf2_ros's static broadcaster


def test_raw_subscription_sees_type_and_attachment() -> None:
    got: list[RawMessage] = []
    with Node("echo", "/robot1", backend="inprocess", domain_id=105) as node:
        node.create_raw_subscription("chatter", got.append)
        pub = node.create_publisher(String, "chatter")
        pub.publish(String(data="one"))
        pub.publish(String(data="two"))
    assert [m.topic for m in got] == ["/robot1/chatter"] * 2
    assert {m.typename for m in got} == {"std_msgs/msg/String"}
    assert [m.info.sequence_number for m in got] == [1, 2]
    assert all(m.info.gid == pub.gid for m in got)
    assert {m.encoding for m in got} == {"cdr"}
    assert codec_for(String).decode(got[1].payload).data == "two"


def test_bad_payload_is_dropped_with_one_warning(caplog: pytest.LogCaptureFixture) -> None:
    got: list[TFMessage] = []
    with Node("victim", backend="inprocess", domain_id=106) as node:
        node.create_subscription(TFMessage, "/tf", got.append, QOS_TF)
        pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
        with caplog.at_level(logging.WARNING, logger="robotmodel.bus"):
            for _ in range(3):
                pub.publish_raw(b"\x00\x01\x00\x00garbage")
        pub.publish(TFMessage([make_transform("a", "b")]))
    assert len(got) == 1
    warnings = [r.getMessage() for r in caplog.records if r.name == "robotmodel.bus"]
    assert len(warnings) == 1, warnings
    assert "'/tf'" in warnings[0] and "tf2_msgs/msg/TFMessage" in warnings[0]


def test_failing_callback_does_not_stop_delivery(caplog: pytest.LogCaptureFixture) -> None:
    seen: list[str] = []

    def callback(msg: object) -> None:
        seen.append(msg.data)  # type: ignore[attr-defined]
        raise RuntimeError("user bug")

    with Node("n", backend="inprocess", domain_id=107) as node, caplog.at_level(logging.ERROR):
        node.create_subscription(String, "x", callback)
        pub = node.create_publisher(String, "x")
        pub.publish(String(data="1"))
        pub.publish(String(data="2"))
    assert seen == ["1", "2"]


def test_graph_lists_topics_nodes_and_counts() -> None:
    with Context(backend="inprocess", domain_id=108) as ctx:
        a = Node("talker", "/ns", context=ctx)
        b = Node("listener", context=ctx)
        pub = a.create_publisher(String, "chatter")
        b.create_subscription(TFMessage, "/tf", lambda m: None, QOS_TF)
        assert b.get_topic_names_and_types() == [
            ("/ns/chatter", ["std_msgs/msg/String"]),
            ("/tf", ["tf2_msgs/msg/TFMessage"]),
        ]
        assert b.get_node_names_and_namespaces() == [("listener", "/"), ("talker", "/ns")]
        assert b.count_publishers("/ns/chatter") == 1
        assert pub.get_subscription_count() == 0
        b.create_subscription(String, "/ns/chatter", lambda m: None)
        assert pub.wait_for_subscriptions(1, timeout=1.0)
        pub.close()
        assert b.count_publishers("/ns/chatter") == 0
        a.close()
        assert b.get_node_names_and_namespaces() == [("listener", "/")]


@pytest.mark.parametrize(("name", "ns", "expected"), [
    ("tf", "/", "/tf"), ("tf", "/robot1", "/robot1/tf"), ("/tf", "/robot1", "/tf"),
    ("~/state", "/robot1", "/robot1/n/state"), ("a/b", "", "/a/b"),
])
def test_topic_names_expand_as_rcl(name: str, ns: str, expected: str) -> None:
    with Node("n", ns, backend="inprocess", domain_id=110) as node:
        assert node.resolve_topic_name(name) == expected


@pytest.mark.parametrize("bad", ["", "/", "a//b", "1abc", "a/", "a b", "/x/2y"])
def test_bad_topic_names_raise(bad: str) -> None:
    with Node("n", backend="inprocess", domain_id=111) as node, pytest.raises(BusError):
        node.create_publisher(String, bad)


def test_bad_node_names_and_domains_raise(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(BusError):
        Node("1node", backend="inprocess")
    monkeypatch.setenv("ROS_DOMAIN_ID", "abc")
    with pytest.raises(BusError, match="ROS_DOMAIN_ID"):
        Node("n", backend="inprocess")
    monkeypatch.setenv("ROS_DOMAIN_ID", "12")
    with Node("n", backend="inprocess") as node:
        assert node.context.domain_id == 12


def test_attachment_round_trip_and_rejects() -> None:
    att = Attachment(7, 1_700_000_000_123_456_789, bytes(range(16)))
    assert Attachment.decode(att.encode()) == att
    with pytest.raises(BusError):
        Attachment.decode(att.encode()[:-1])
    with pytest.raises(BusError):
        Attachment(1, 2, b"short").encode()


def test_tf_records_share_the_tfmessage_key_and_bytes() -> None:
    records: list[list[Any]] = []
    messages: list[TFMessage] = []
    with Node("tf", backend="inprocess", domain_id=112) as node:
        node.create_subscription(TFRecords, "/tf", records.append, QOS_TF)
        node.create_subscription(TFMessage, "/tf", messages.append, QOS_TF)
        msg_pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
        rec_pub = node.create_publisher(TFRecords, "/tf", QOS_TF)
        assert codec_for(TFRecords).message_type() == codec_for(TFMessage).message_type()
        msg_pub.publish(TFMessage([make_transform("a", "b", (1.0, 2.0, 3.0), (0.0, 0.0, 0.6, 0.8), 7_000_000_001)]))
        rec_pub.publish(records[0])
    assert records[0] == records[1]
    parent, child, stamp_ns, pose = records[0][0]
    assert (parent, child, stamp_ns, pose) == ("a", "b", 7_000_000_001, (1.0, 2.0, 3.0, 0.0, 0.0, 0.6, 0.8))
    assert messages[0] == messages[1]


def test_graph_finds_a_publisher_by_the_gid_in_its_samples() -> None:
    got: list[RawMessage] = []
    with Node("talker", "/ns", backend="inprocess", domain_id=113) as node:
        node.create_raw_subscription("chatter", got.append)
        pub = node.create_publisher(String, "chatter")
        pub.publish(String(data="x"))
        entity = node.context.graph.by_gid(got[0].info.gid)
        assert entity is not None
        assert (entity.node_fqn, entity.topic) == ("/ns/talker", "/ns/chatter")
        assert node.context.graph.by_gid(bytes(16)) is None


def test_gid_hashes_the_token_as_written() -> None:
    from robotmodel.bus import Token

    # Another implementation may spell an equal QoS differently; the GID follows its text.
    token = ("@ros2_lv/0/8b20917502ee955ac4476e0266340d5c/0/10/MP/%/%/talker/%chatter/"
             "std_msgs::msg::dds_::String_/RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18/"
             "1:2:1,7:,:,:,,")
    entity = Token.parse(token)
    assert entity.keyexpr != token  # ours leaves the default reliability and durability empty
    assert entity.gid == gid_of(token)


def test_a_closed_node_or_publisher_refuses_with_bus_error() -> None:
    node = Node("gone", backend="inprocess", domain_id=114)
    pub = node.create_publisher(String, "x")
    node.close()
    with pytest.raises(BusError, match="'/gone' is closed"):
        node.create_publisher(String, "y")
    with pytest.raises(BusError, match="closed"):
        pub.publish(String(data="z"))
    node.close()  # twice is harmless


def test_matched_follows_subscribers() -> None:
    with Node("m", backend="inprocess", domain_id=115) as node:
        pub = node.create_publisher(String, "/m")
        assert not pub.matched()
        sub = node.create_subscription(String, "/m", lambda m: None)
        assert pub.matched()
        sub.close()
        assert not pub.matched()
