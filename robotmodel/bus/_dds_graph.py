"""The ROS graph on DDS, as rmw_dds_common keeps it: ``ros_discovery_info`` plus DDS's built-in topics.

DDS discovery knows participants and endpoints (DCPSParticipant, DCPSPublication,
DCPSSubscription: GUID, topic, type, QoS) but not ROS nodes. ROS 2 adds them with the
``ros_discovery_info`` topic (``rmw_dds_common/msg/ParticipantEntitiesInfo``, reliable,
transient local, keep last 1): each participant publishes its GID and, per node, the
namespace, the name and the GIDs of the node's readers and writers, again whenever that
changes. This module does both halves for one session: it publishes the session's nodes
and reads everyone's (its own taken from the session itself, so that they show at once),
and joins the two into the seam's :class:`Entity` records. An endpoint no node claims
(yet) is shown as rmw shows it, with node ``_NODE_NAME_UNKNOWN_`` in
``_NODE_NAMESPACE_UNKNOWN_`` and no ``node_key``. A participant that leaves (or whose
lease runs out when its process dies) takes its nodes along; Cyclone disposes its endpoints.
A service is its endpoints on ``rq/<name>Request`` and ``rr/<name>Reply``; as rmw_dds_common
demangles them, a reader of the first is a server of ``/<name>`` and a reader of the second a
client, of the service type (the request's or reply's type without ``_Request``/``_Response``).

Fast DDS sends a new reader of its ``ros_discovery_info`` its first heartbeat as soon as it
matches it, often before its own announcement of that writer has reached us; Cyclone ignores a
heartbeat from a writer it does not know yet, and a transient-local reader takes nothing from a
non-Cyclone writer before a heartbeat, so the nodes of a Fast DDS participant would show only at
its next one (every 3 s). When another vendor's discovery writer appears, the discovery reader is
made anew, so that the writer, now known, heartbeats to it at once.

GIDs are DDS GUIDs, 16 bytes (Jazzy's ``rmw_gid_t``; Fast DDS and Cyclone alike).
Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from typing import Any

from cyclonedds.builtin import (
    BuiltinDataReader,
    BuiltinTopicDcpsParticipant,
    BuiltinTopicDcpsPublication,
    BuiltinTopicDcpsSubscription,
)
from cyclonedds.core import Policy, Qos
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from robotmodel.bus._backend import Entity, EntityKind, GraphCallback
from robotmodel.bus._dds_qos import qos_from_dds, type_hash_of
from robotmodel.bus._dds_raw import Pump, destroy, take_raw, write_raw
from robotmodel.bus._dds_types import CYCLONE_VENDOR, idl_type, ros_topic_name
from robotmodel.bus._names import ros_type_name
from robotmodel.bus._warn import Warner

__all__ = ["DISCOVERY_TOPIC", "DdsGraph", "LocalNode"]

DISCOVERY_TOPIC = "ros_discovery_info"
_INFO_TYPE = "rmw_dds_common/msg/ParticipantEntitiesInfo"
_UNKNOWN_NAME = "_NODE_NAME_UNKNOWN_"
_UNKNOWN_NS = "_NODE_NAMESPACE_UNKNOWN_"
_ALIVE = 16  # DDS_IST_ALIVE
_BATCH = 256


@dataclass
class LocalNode:
    """One of this session's nodes as ``ros_discovery_info`` lists it."""

    namespace: str
    name: str
    readers: list[bytes] = field(default_factory=list)
    writers: list[bytes] = field(default_factory=list)


@dataclass(frozen=True)
class _Endpoint:
    kind: EntityKind
    participant: bytes
    topic: str
    typename: str
    type_hash: str
    qos: Any


def _service_of(dds_topic: str, typename: str) -> tuple[EntityKind, str, str] | None:
    """A reader of a service's DDS topic as rmw_dds_common's graph shows it: (kind, service, type), or None.

    A reader of ``rq/<name>Request`` is a server of ``/<name>``, a reader of ``rr/<name>Reply``
    a client; the type is the request's or reply's without its ``_Request`` or ``_Response``.
    Writers are not counted: each server and client has one reader.
    """
    for prefix, suffix, type_suffix, kind in (("rq/", "Request", "_Request", EntityKind.SERVICE),
                                              ("rr/", "Reply", "_Response", EntityKind.CLIENT)):
        if dds_topic.startswith(prefix) and dds_topic.endswith(suffix) and typename.endswith(type_suffix):
            return kind, dds_topic[len(prefix) - 1:-len(suffix)], typename[:-len(type_suffix)]
    return None


def _store() -> Any:
    from robotmodel.msgs import typestore

    return typestore()


class DdsGraph:
    """One session's half of ROS's DDS graph: publishes its nodes, follows everyone's."""

    def __init__(self, participant: Any) -> None:
        self._participant = participant
        self.gid: bytes = participant.guid.bytes
        self.lock = threading.RLock()
        self._warner = Warner()
        self._local: list[LocalNode] = []
        self._nodes: dict[bytes, list[tuple[str, str, frozenset[bytes], frozenset[bytes]]]] = {}
        self._endpoints: dict[bytes, _Endpoint] = {}
        self._emitted: dict[str, Entity] = {}
        self._watchers: list[GraphCallback] = []
        self._closed = False
        # rmw_dds_common's QoS for the topic; the reader keeps more than 1 so that no
        # participant's update is overwritten by another's before it is read.
        qos = Qos(Policy.Reliability.Reliable(2**63 - 1), Policy.Durability.TransientLocal, Policy.History.KeepLast(1))
        rqos = Qos(Policy.Reliability.Reliable(2**63 - 1), Policy.Durability.TransientLocal,
                   Policy.History.KeepLast(_BATCH))
        self._readers: list[Any] = []
        self._foreign_info: set[bytes] = set()
        self._renew = False
        self._pump = Pump("dds-graph", self._drain)
        topic = Topic(participant, DISCOVERY_TOPIC, idl_type(_INFO_TYPE))
        self._info = (topic, rqos)
        self._writer = DataWriter(participant, topic, qos)
        listener = self._pump.listener()
        readers = [
            DataReader(participant, topic, rqos, listener=listener),
            BuiltinDataReader(participant, BuiltinTopicDcpsParticipant, listener=listener),
            BuiltinDataReader(participant, BuiltinTopicDcpsPublication, listener=listener),
            BuiltinDataReader(participant, BuiltinTopicDcpsSubscription, listener=listener),
        ]
        with self.lock:
            self._readers = readers
        self._listener = listener
        self._pump.poke()

    # --- this session's nodes --------------------------------------------------------------

    def add_node(self, node: LocalNode) -> None:
        """Announce a new node of this session."""
        with self.lock:
            self._local.append(node)
        self.publish()

    def remove_node(self, node: LocalNode) -> None:
        """Withdraw a node of this session."""
        with self.lock:
            if node in self._local:
                self._local.remove(node)
        self.publish()

    def publish(self) -> None:
        """Send this participant's ParticipantEntitiesInfo (call after any change to a node)."""
        store = _store()
        with self.lock:
            if self._closed:
                return
            t = store.types
            gid_type = t["rmw_dds_common/msg/Gid"]

            def gid(raw: bytes) -> Any:
                import numpy as np

                return gid_type(data=np.frombuffer(raw.ljust(16, b"\0")[:16], dtype=np.uint8).copy())

            info = t[_INFO_TYPE](gid=gid(self.gid), node_entities_info_seq=[
                t["rmw_dds_common/msg/NodeEntitiesInfo"](
                    node_namespace=n.namespace, node_name=n.name,
                    reader_gid_seq=[gid(g) for g in n.readers], writer_gid_seq=[gid(g) for g in n.writers])
                for n in self._local])
            payload = bytes(store.serialize_cdr(info, _INFO_TYPE))
            write_raw(self._writer, payload, DISCOVERY_TOPIC, _INFO_TYPE)
            if self._readers:
                self._emit()

    # --- following the domain --------------------------------------------------------------

    def _drain(self) -> None:
        with self.lock:
            if self._closed or not self._readers:
                return  # not built yet: the constructor pokes again when it is
            changed = False
            info_reader, part_reader, pub_reader, sub_reader = self._readers
            while batch := take_raw(info_reader):
                changed = True
                for data, info in batch:
                    if info.valid_data:
                        self._on_info(data)
            for reader, kind in ((pub_reader, EntityKind.PUBLISHER), (sub_reader, EntityKind.SUBSCRIPTION)):
                while batch := reader.take(_BATCH):
                    changed = True
                    for sample in batch:
                        self._on_endpoint(sample, kind)
            while batch := part_reader.take(_BATCH):
                changed = True
                for sample in batch:
                    if sample.sample_info.instance_state != _ALIVE:
                        self._nodes.pop(sample.key.bytes, None)
            if self._renew:
                self._renew_info_reader()
            if changed:
                self._emit()

    def _renew_info_reader(self) -> None:
        # See the module docstring: a new reader gets a first heartbeat from a writer we now know.
        self._renew = False
        old = self._readers[0]
        while batch := take_raw(old):
            for data, info in batch:
                if info.valid_data:
                    self._on_info(data)
        self._readers[0] = DataReader(self._participant, self._info[0], self._info[1], listener=self._listener)
        destroy(old)

    def _on_info(self, data: bytes) -> None:
        try:
            msg = _store().deserialize_cdr(data, _INFO_TYPE)
        except Exception as exc:
            self._warner.warn("info", f"ignored a malformed '{DISCOVERY_TOPIC}' sample: {exc}")
            return
        pgid = bytes(msg.gid.data)
        self._nodes[pgid] = [
            (n.node_namespace, n.node_name, frozenset(bytes(g.data) for g in n.reader_gid_seq),
             frozenset(bytes(g.data) for g in n.writer_gid_seq))
            for n in msg.node_entities_info_seq]

    def _on_endpoint(self, sample: Any, kind: EntityKind) -> None:
        key = sample.key.bytes
        if sample.sample_info.instance_state != _ALIVE:
            self._endpoints.pop(key, None)
            self._foreign_info.discard(key)
            return
        if (kind is EntityKind.PUBLISHER and sample.topic_name == DISCOVERY_TOPIC and key[:2] != CYCLONE_VENDOR
                and key not in self._foreign_info):
            self._foreign_info.add(key)
            self._renew = True
        typename = ros_type_name(sample.type_name)
        topic = ros_topic_name(sample.topic_name or "")
        if topic is None:
            service = _service_of(sample.topic_name or "", typename) if kind is EntityKind.SUBSCRIPTION else None
            if service is None:
                return
            kind, topic, typename = service
        self._endpoints[key] = _Endpoint(kind, sample.participant_key.bytes, topic, typename,
                                         type_hash_of(sample.qos), qos_from_dds(sample.qos))

    def _current(self) -> dict[str, Entity]:
        entities: dict[str, Entity] = {}
        owner: dict[bytes, tuple[str, str, str]] = {}
        # This session's own nodes as they are now, not as its last sample said.
        known = {**self._nodes, self.gid: [(n.namespace, n.name, frozenset(n.readers), frozenset(n.writers))
                                           for n in self._local]}
        for pgid, nodes in known.items():
            seen: dict[tuple[str, str], int] = {}
            for ns, name, readers, writers in nodes:
                n = seen[(ns, name)] = seen.get((ns, name), -1) + 1
                node_key = f"{pgid.hex()}/{ns}/{name}/{n}"
                entities["node:" + node_key] = Entity(EntityKind.NODE, name, ns, node_key=node_key)
                for g in readers | writers:
                    owner[g] = (name, ns, node_key)
        for egid, ep in self._endpoints.items():
            name, ns, node_key = owner.get(egid, (_UNKNOWN_NAME, _UNKNOWN_NS, ""))
            entities["ep:" + egid.hex()] = Entity(ep.kind, name, ns, "/", ep.topic, ep.typename, ep.type_hash,
                                                  ep.qos, egid, node_key)
        return entities

    def _emit(self) -> None:
        now = self._current()
        before = self._emitted
        self._emitted = now
        for key in before.keys() - now.keys():
            for cb in list(self._watchers):
                cb(key, None)
        for key, entity in now.items():
            if before.get(key) != entity:
                for cb in list(self._watchers):
                    cb(key, entity)

    def watch(self, callback: GraphCallback) -> None:
        """Call ``callback`` for every entity known now, then for every change."""
        with self.lock:
            for key, entity in self._emitted.items():
                callback(key, entity)
            self._watchers.append(callback)

    def unwatch(self, callback: GraphCallback) -> None:
        """Stop calling ``callback``."""
        with self.lock:
            if callback in self._watchers:
                self._watchers.remove(callback)

    def close(self) -> None:
        """Stop following the graph and withdraw this session's discovery writer."""
        with self.lock:
            self._closed = True
            self._watchers.clear()
        self._pump.close()
        for reader in self._readers:
            destroy(reader)
        destroy(self._writer)
