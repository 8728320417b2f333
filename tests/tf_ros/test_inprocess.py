"""Logic of robotmodel.tf_ros on the in-process bus (the live tests cover real processes)."""

from __future__ import annotations

import itertools
import threading
import time

import pytest

from robotmodel.bus import Node
from robotmodel.msgs import TFMessage, make_transform
from robotmodel.tf import Buffer, Duration, Time
from robotmodel.tf_ros import DEFAULT_AUTHORITY, StaticTransformBroadcaster, TransformBroadcaster, TransformListener

_domains = itertools.count(300)


@pytest.fixture
def domain():
    return next(_domains)


def test_static_broadcaster_keeps_latest_per_child_and_latches_the_set(domain):
    with StaticTransformBroadcaster(backend="inprocess", domain_id=domain) as static:
        static.send_transform(make_transform("world", "a", (1, 0, 0)))
        static.send_transform([make_transform("world", "b", (2, 0, 0)), make_transform("world", "a", (3, 0, 0))])
        assert [(t.child_frame_id, t.transform.translation.x) for t in static.transforms] == [("a", 3.0), ("b", 2.0)]
        # A subscriber arriving afterwards gets the whole set in the one latched message.
        got: list[TFMessage] = []
        from robotmodel.bus import QOS_TF_STATIC_LISTENER

        with Node("late", backend="inprocess", domain_id=domain) as node:
            node.create_subscription(TFMessage, "/tf_static", got.append, QOS_TF_STATIC_LISTENER)
            assert len(got) == 1
            assert sorted((t.child_frame_id, t.transform.translation.x) for t in got[0].transforms) == [
                ("a", 3.0), ("b", 2.0)]


def test_listener_fills_buffer_with_statics_and_dynamics(domain):
    buffer = Buffer()
    opts = {"backend": "inprocess", "domain_id": domain}
    with TransformListener(buffer, **opts), StaticTransformBroadcaster(**opts) as static, \
            TransformBroadcaster(**opts) as dynamic:
        static.sendTransform(make_transform("world", "base", (0, 0, 1)))
        dynamic.sendTransform(make_transform("base", "arm", (1, 0, 0), stamp_ns=1_000_000_000))
        dynamic.send_transform([make_transform("base", "arm", (3, 0, 0), stamp_ns=2_000_000_000)])
        t = buffer.lookup_transform("world", "arm", Time(nanoseconds=1_500_000_000))
        assert (t.transform.translation.x, t.transform.translation.z) == (2.0, 1.0)
        frames = buffer.all_frames_as_yaml()
        # Broadcasters are named after the publishing node's fully qualified name.
        assert f"broadcaster: '{static.node.fully_qualified_name}'" in frames
        assert f"broadcaster: '{dynamic.node.fully_qualified_name}'" in frames
        assert "most_recent_transform: 0.000000" in frames  # the static one


def test_listener_with_fixed_authority(domain):
    buffer = Buffer()
    opts = {"backend": "inprocess", "domain_id": domain}
    with TransformListener(buffer, authority=DEFAULT_AUTHORITY, **opts), TransformBroadcaster(**opts) as br:
        br.send_transform(make_transform("a", "b", stamp_ns=5))
    assert "broadcaster: 'default_authority'" in buffer.all_frames_as_yaml()


def test_lookup_with_timeout_wakes_when_data_arrives(domain):
    buffer = Buffer()
    opts = {"backend": "inprocess", "domain_id": domain}
    with TransformListener(buffer, **opts), TransformBroadcaster(**opts) as br:
        timer = threading.Timer(0.2, br.send_transform, [make_transform("odom", "base", (4, 0, 0), stamp_ns=7)])
        began = time.monotonic()
        timer.start()
        try:
            t = buffer.lookup_transform("odom", "base", Time(), timeout=Duration(seconds=5))
        finally:
            timer.join()
        assert t.transform.translation.x == 4.0
        assert time.monotonic() - began < 4.0


def test_closing_leaves_a_given_node_open_and_closes_an_owned_one(domain):
    with Node("mine", backend="inprocess", domain_id=domain) as node:
        br = TransformBroadcaster(node)
        br.close()
        br.close()  # twice is harmless
        # The node still works: a new broadcaster on it publishes.
        with TransformBroadcaster(node) as again:
            again.send_transform(make_transform("a", "b"))
    with Node("observer", backend="inprocess", domain_id=domain) as observer:
        owned = TransformListener(Buffer(), backend="inprocess", domain_id=domain)
        name = owned.node.get_name()
        assert (name, "/") in observer.get_node_names_and_namespaces()
        owned.close()
        # Its node left the graph with it.
        assert (name, "/") not in observer.get_node_names_and_namespaces()


def test_static_sample_before_its_publisher_is_known_is_reattributed(domain):
    """A latched transform can arrive before the graph shows its publisher; it is sent once,
    so the listener must fix its broadcaster name when the publisher shows up."""
    from robotmodel.bus import QOS_TF_STATIC, Entity, EntityKind, codec_for
    from robotmodel.bus._inprocess import _BUS

    buffer = Buffer()
    with TransformListener(buffer, backend="inprocess", domain_id=domain), \
            Node("late_node", backend="inprocess", domain_id=domain) as node:
        pub = node.create_publisher(TFMessage, "/tf_static", QOS_TF_STATIC)
        # Take the publisher out of the graph, as if its announcement had not arrived yet.
        key, entity = next((k, e) for (d, k), e in _BUS.entities.items()
                           if d == domain and e.kind is EntityKind.PUBLISHER and e.topic == "/tf_static")
        _BUS.announce(domain, key, None)
        pub.publish(TFMessage([make_transform("world", "cam", (1, 0, 0))]))
        assert "broadcaster: 'default_authority'" in buffer.all_frames_as_yaml()
        assert isinstance(entity, Entity) and entity.gid == pub.gid
        _BUS.announce(domain, key, entity)
        deadline = time.monotonic() + 10
        while "broadcaster: '/late_node'" not in buffer.all_frames_as_yaml():
            assert time.monotonic() < deadline, buffer.all_frames_as_yaml()
            time.sleep(0.01)
        assert buffer.lookup_transform("world", "cam", Time()).transform.translation.x == 1.0
        assert codec_for(TFMessage).typename == entity.typename


def test_listener_reports_a_bad_stamp_and_keeps_the_rest_of_the_message(domain, caplog):
    # A negative stamp is valid int32 on the wire but no valid tf2 time: tf2_ros's listener
    # reports that transform and still inserts the others of the same message.
    buffer = Buffer()
    opts = {"backend": "inprocess", "domain_id": domain}
    bad = make_transform("base", "bad", (1, 0, 0))
    bad.header.stamp.sec = -5
    good = make_transform("base", "good", (2, 0, 0), stamp_ns=1_000_000_000)
    with TransformListener(buffer, **opts), TransformBroadcaster(**opts) as br:
        br.send_transform([bad, good])
        t = buffer.lookup_transform("base", "good", Time(), timeout=Duration(seconds=5))
        assert t.transform.translation.x == 2.0
        assert not buffer.can_transform("base", "bad", Time())
    assert any("Failure to set received transform from bad to base" in r.getMessage() for r in caplog.records)
