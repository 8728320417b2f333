"""The DDS wire's own pieces: names, types, QoS mapping, discovery configuration, raw CDR."""

from __future__ import annotations

import logging

import pytest

from robotmodel.bus import QOS_LATCHED, QOS_TF, BusError, Context, Durability, History, Node, QoS, Reliability
from robotmodel.bus import typestore as store
from robotmodel.bus._dds_qos import cyclone_config, qos_from_dds, qos_to_dds, type_hash_of
from robotmodel.bus._dds_raw import pad, unpad
from robotmodel.bus._dds_types import dds_topic_name, idl_type, ros_topic_name


def test_topic_names_are_rmws() -> None:
    assert dds_topic_name("/ns/chatter") == "rt/ns/chatter"
    assert ros_topic_name("rt/ns/chatter") == "/ns/chatter"
    assert ros_topic_name("ros_discovery_info") is None
    assert ros_topic_name("rq/add_two_intsRequest") is None


@pytest.mark.parametrize("typename", ["std_msgs/msg/String", "sensor_msgs/msg/JointState",
                                      "tf2_msgs/msg/TFMessage", "rmw_dds_common/msg/ParticipantEntitiesInfo",
                                      "std_msgs/msg/Empty"])
def test_topic_types_carry_ros_dds_names_and_read_rosbags_cdr(typename: str) -> None:
    cls = idl_type(typename)
    pkg, _, name = typename.split("/")
    assert cls.__idl__.idl_transformed_typename == f"{pkg}::msg::dds_::{name}_"
    # The struct Cyclone checks samples against reads what rosbags (ROS 2's CDR) writes.
    ts = store()
    msg = ts.types[typename]
    defaults = {"std_msgs/msg/String": {"data": "hi"}}
    if typename in defaults:
        cdr = bytes(ts.serialize_cdr(msg(**defaults[typename]), typename))
        assert cls.deserialize(cdr).data == "hi"
    assert idl_type(typename) is cls


def test_an_unknown_type_is_one_clear_error() -> None:
    with pytest.raises(BusError, match="unknown message type 'nope_msgs/msg/Nothing'"):
        idl_type("nope_msgs/msg/Nothing")


@pytest.mark.parametrize("qos", [QoS(10), QoS(7, Reliability.BEST_EFFORT), QOS_LATCHED, QOS_TF,
                                 QoS(0, history=History.KEEP_ALL),
                                 QoS(3, durability=Durability.TRANSIENT_LOCAL, deadline_ns=2_000_000_000,
                                     lifespan_ns=5_000_000)],
                         ids=["default", "best_effort", "latched", "tf", "keep_all", "durations"])
def test_ros_qos_survives_the_dds_mapping(qos: QoS) -> None:
    back = qos_from_dds(qos_to_dds(qos, "RIHS01_ab"))
    q = qos.resolved()
    assert (back.reliability, back.durability, back.history, back.deadline_ns, back.lifespan_ns) == \
        (q.reliability, q.durability, q.history, q.deadline_ns, q.lifespan_ns)
    if q.history == History.KEEP_LAST:
        assert back.depth == q.depth
    assert type_hash_of(qos_to_dds(qos, "RIHS01_ab")) == "RIHS01_ab"


def test_discovery_stays_on_loopback_unless_widened() -> None:
    local = cyclone_config(env={})
    assert 'address="127.0.0.1"' in local and "<AllowMulticast>false" in local and '<Peer address="localhost"/>' in local
    assert cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}) == local
    subnet = cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"})
    assert "127.0.0.1" not in subnet and "<Peer" not in subnet
    off = cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF"})
    assert "127.0.0.1" in off and "<Peer" not in off
    peers = cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_STATIC_PEERS": "10.0.0.2; robot.local"})
    assert '<Peer address="10.0.0.2"/>' in peers and '<Peer address="robot.local"/>' in peers
    # REP 2016's way to reach a robot with discovery kept local: the peer must be reachable.
    robot = cyclone_config(env={"ROS_STATIC_PEERS": "10.0.0.2"})
    assert "127.0.0.1" not in robot and "<AllowMulticast>false" in robot
    assert '<Peer address="localhost"/><Peer address="10.0.0.2"/>' in robot
    assert cyclone_config(env={"ROS_STATIC_PEERS": "127.0.0.1"}).count("127.0.0.1") == 2  # interface and peer
    with pytest.raises(BusError, match="ROS_AUTOMATIC_DISCOVERY_RANGE is 'ROOM'"):
        cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "ROOM"})


def test_deprecated_localhost_only_and_off_with_peers_as_rcl_reads_them(caplog: pytest.LogCaptureFixture) -> None:
    # rcl (Jazzy): ROS_LOCALHOST_ONLY=1 wins over the range and the static peers, with its
    # deprecation warning; OFF ignores static peers, with its note (texts from librcl).
    local = cyclone_config(env={})
    widened = {"ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET", "ROS_STATIC_PEERS": "10.0.0.2"}
    with caplog.at_level(logging.WARNING, "robotmodel.bus"):
        assert cyclone_config(env={**widened, "ROS_LOCALHOST_ONLY": "1"}) == local
        assert cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF", "ROS_STATIC_PEERS": "10.0.0.2"}) == \
            cyclone_config(env={"ROS_AUTOMATIC_DISCOVERY_RANGE": "OFF"})
    assert [r.getMessage() for r in caplog.records] == [
        "ROS_LOCALHOST_ONLY is deprecated but still honored if it is enabled. "
        "Use ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS instead.",
        "Note: ROS_AUTOMATIC_DISCOVERY_RANGE is set to OFF, but found static peers in ROS_STATIC_PEERS. "
        "ROS_STATIC_PEERS will be ignored."]
    assert cyclone_config(env={**widened, "ROS_LOCALHOST_ONLY": "0"}) == cyclone_config(env=widened)


@pytest.mark.parametrize("size", range(4, 12))
def test_padding_is_recorded_in_the_encapsulation_options(size: int) -> None:
    payload = b"\x00\x01\x00\x00" + bytes(range(1, size - 3))
    padded = pad(payload)
    assert len(padded) % 4 == 0 and padded[3] & 3 == len(padded) - len(payload)
    assert unpad(padded) == payload


def test_a_payload_that_is_not_the_type_is_refused_in_one_line(bus_env: dict[str, str]) -> None:
    with Context(backend="dds", domain_id=int(bus_env["ROS_DOMAIN_ID"])) as ctx:
        node = Node("garbage", context=ctx)
        pub = node.create_publisher("std_msgs/msg/String", "/garbage", QoS(10))
        # A string length of 255 with 2 bytes behind it: Cyclone checks the CDR against the type.
        with pytest.raises(BusError, match=r"DDS refused a sample on '/garbage' .*std_msgs/msg/String"):
            pub.handle.publish(b"\x00\x01\x00\x00\xff\x00\x00\x00ab\x00")  # type: ignore[union-attr]
        pub.publish(store().types["std_msgs/msg/String"](data="still fine"))
