"""The DDS wire: ROS 2's DDS conventions on Cyclone DDS (cyclonedds-python), behind the backend seam.

What goes on the wire is what rmw_cyclonedds_cpp and rmw_fastrtps_cpp put there: a ROS topic
``/x`` is the DDS topic ``rt/x`` of type ``pkg::msg::dds_::Name_`` (:mod:`._dds_types`),
samples are the CDR the seam hands over (:mod:`._dds_raw`), the ROS QoS is mapped onto DDS
QoS with Jazzy's type hash in USER_DATA (:mod:`._dds_qos`), and nodes are announced on
``ros_discovery_info`` (:mod:`._dds_graph`). Each session is one DDS participant; matching,
durability, history and the refusal of incompatible QoS are DDS's own, and Cyclone's
offered/requested-incompatible-QoS statuses become the seam's :class:`QoSEvent`.
A peer whose type cannot match an endpoint's (another type name on the topic, as the graph
shows it, or another definition under the same name, which Cyclone refuses by XTypes type
consistency) gets ROS's incompatible-type warning, once per endpoint and peer type.

A sample's GID is its writer's GUID; DDS carries no per-sample sequence number to the
reader here, so the sequence number is counted per writer on receipt. An untyped
subscription (``topic echo`` without a type) opens one reader per type the graph shows
published on its topic, for every type the typestore knows.

Discovery stays on this machine unless ``ROS_AUTOMATIC_DISCOVERY_RANGE`` or
``ROS_STATIC_PEERS`` widen it (:func:`._dds_qos.cyclone_config`); Cyclone reads that
configuration when the first session of a domain in this process opens, and lets it go
with the last one.
Parameters are node-local. Services are rmw_cyclonedds_cpp's (:mod:`._dds_service`).
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Sequence
from typing import Any, cast

from cyclonedds.core import DDSException, Policy, Qos
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from robotmodel._heap import sample_released
from robotmodel.bus._backend import (
    CDR,
    Backend,
    ClientHandle,
    Entity,
    GraphCallback,
    Handle,
    LocalParameters,
    MessageType,
    NodeHandle,
    ParameterStore,
    PublisherHandle,
    QoSEvent,
    QoSEventCallback,
    RequestCallback,
    Sample,
    SampleCallback,
    SampleInfo,
    ServiceType,
)
from robotmodel.bus._book import NodeBook, OnClose
from robotmodel.bus._dds_graph import DdsGraph, LocalNode
from robotmodel.bus._dds_qos import POLICY_NAMES, check_peers, cyclone_config, qos_to_dds
from robotmodel.bus._dds_raw import Pump, destroy, make_listener, take_raw, write_raw
from robotmodel.bus._dds_types import dds_topic_name, idl_type
from robotmodel.bus._qos import QoS, incompatible_policy
from robotmodel.bus._warn import Warner
from robotmodel.errors import BusError

__all__ = ["DdsBackend"]

log = logging.getLogger("robotmodel.bus")
# Per domain id: Cyclone's configured domain and how many sessions of this process use it.
_DOMAINS: dict[int, list[Any]] = {}
_DOMAINS_LOCK = threading.Lock()


def _enter_domain(domain_id: int, connect: Sequence[str]) -> None:
    """Configure Cyclone for ``domain_id`` before the first participant of this process joins it."""
    with _DOMAINS_LOCK:
        entry = _DOMAINS.get(domain_id)
        if entry is None:
            entry = _DOMAINS[domain_id] = [Domain(domain_id, cyclone_config(connect)), 0]
        entry[1] += 1


def _leave_domain(domain_id: int) -> None:
    """The last session of a domain gone: Cyclone's threads and sockets for it go too."""
    with _DOMAINS_LOCK:
        entry = _DOMAINS.get(domain_id)
        if entry is None:
            return
        entry[1] -= 1
        if entry[1] <= 0:
            del _DOMAINS[domain_id]
            destroy(entry[0])


# DDS_TYPE_CONSISTENCY_ENFORCEMENT_QOS_POLICY_ID: Cyclone's reason when a peer's type
# definition cannot be assigned to the endpoint's; ROS reports that as an incompatible type.
_TYPE_CONSISTENCY = 24


class _TypeCheck:
    """ROS's incompatible-type warning for one endpoint: once per other type seen on its topic.

    rclcpp's and rclpy's default incompatible-type handlers' text; a peer under another type
    name never matches in DDS and so is only visible in the graph, a peer with another
    definition under the same name is refused by Cyclone (reported as type consistency).
    """

    def __init__(self, topic: str, typename: str, peer_kind: str) -> None:
        self.topic, self.typename, self._peer_kind = topic, typename, peer_kind
        self._seen: set[str] = set()
        self._lock = threading.Lock()

    def warn(self, other: str) -> None:
        with self._lock:
            if other in self._seen:
                return
            self._seen.add(other)
        log.warning("Incompatible type on topic '%s', no messages will be sent to it.", self.topic)

    def on_entity(self, _key: str, entity: Entity | None) -> None:
        if (entity is not None and entity.topic == self.topic and entity.kind.value == self._peer_kind
                and entity.typename and entity.typename != self.typename):
            self.warn(entity.typename)


def _qos_listener(on_qos_event: QoSEventCallback | None, topic: str, offered: bool,
                  types: _TypeCheck | None = None) -> dict[str, Any]:
    if on_qos_event is None and types is None:
        return {}

    def on_status(_entity: Any, status: Any) -> None:
        if int(status.last_policy_id) == _TYPE_CONSISTENCY:
            if types is not None:
                types.warn(f"{types.typename} (another definition)")
            return
        if on_qos_event is None:
            return
        policy = POLICY_NAMES.get(int(status.last_policy_id), "INVALID")
        try:
            on_qos_event(QoSEvent(int(status.total_count), int(status.total_count_change), policy, topic))
        except Exception:  # a user callback must not unwind into Cyclone's thread
            log.exception("incompatible-QoS callback on '%s' failed", topic)

    key = "on_offered_incompatible_qos" if offered else "on_requested_incompatible_qos"
    return {key: on_status}


class DdsBackend(Backend):
    """A DDS participant speaking ROS 2's conventions (see the module docstring)."""

    name = "dds"
    encoding = CDR

    def __init__(self, domain_id: int, participant: Any) -> None:
        super().__init__(domain_id)
        self.participant = participant
        self.graph = DdsGraph(participant)
        self._topics: dict[tuple[str, str, bool], Any] = {}
        self._nodes: NodeBook[DdsNode] = NodeBook("DDS")
        self._lock = threading.RLock()

    @classmethod
    def open(cls, domain_id: int, connect: Sequence[str] = ()) -> DdsBackend:
        """See :meth:`Backend.open` (``connect``: extra unicast peers, as ROS_STATIC_PEERS)."""
        if not 0 <= domain_id <= 232:
            raise BusError(f"ROS_DOMAIN_ID {domain_id} is out of DDS's range 0..232")
        check_peers(connect)
        _enter_domain(domain_id, connect)
        try:
            # rmw_cyclonedds_cpp puts the enclave into the participant's USER_DATA.
            participant = DomainParticipant(domain_id, qos=Qos(Policy.Userdata(b"enclave=/;")))
            return cls(domain_id, participant)
        except DDSException as exc:
            _leave_domain(domain_id)
            raise BusError(f"cannot join DDS domain {domain_id}: {exc}") from None

    def topic(self, topic: str, typename: str) -> Any:
        """The DDS topic of a ROS topic and type in this participant (made once)."""
        return self.dds_topic(dds_topic_name(topic), typename)

    def dds_topic(self, dds_name: str, typename: str, request_header: bool = False) -> Any:
        """The DDS topic ``dds_name`` of a ROS type (with rmw_cyclonedds' request header: services)."""
        key = (dds_name, typename, request_header)  # a service's two forms are two types of one name
        with self._lock:
            found = self._topics.get(key)
            if found is None:
                found = self._topics[key] = Topic(self.participant, dds_name, idl_type(typename, request_header))
            return found

    def create_node(self, name: str, namespace: str, enclave: str = "/") -> DdsNode:
        """See :meth:`Backend.create_node`."""
        return self._nodes.add(lambda: DdsNode(self, name, namespace))

    def forget(self, node: DdsNode) -> None:
        """Drop a closed node from the session's list."""
        self._nodes.forget(node)

    def watch_graph(self, callback: GraphCallback) -> Handle:
        """See :meth:`Backend.watch_graph`: ros_discovery_info joined with DDS's built-in topics."""
        self.graph.watch(callback)
        return OnClose(lambda: self.graph.unwatch(callback))

    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """See :meth:`Backend.qos_incompatibility`: rmw_dds_common's rules, which DDS enforces."""
        return incompatible_policy(publisher, subscription)

    def close(self) -> None:
        """See :meth:`Backend.close`: the participant leaves, taking every entity with it."""
        nodes = self._nodes.close()
        if nodes is None:
            return
        for node in nodes:
            node.close()
        self.graph.close()
        destroy(self.participant)
        _leave_domain(self.domain_id)


class DdsNode(NodeHandle):
    """A node: its entry in ros_discovery_info and the readers and writers made for it."""

    def __init__(self, backend: DdsBackend, name: str, namespace: str) -> None:
        self.backend = backend
        self.record = LocalNode(namespace, name)
        self._children: list[Handle] = []
        self._params = LocalParameters()
        self._closed = False
        backend.graph.add_node(self.record)

    def declare_publisher(self, topic: str, mtype: MessageType, qos: QoS,
                          on_qos_event: QoSEventCallback | None = None) -> DdsPublisher:
        """See :meth:`NodeHandle.declare_publisher`."""
        pub = DdsPublisher(self, topic, mtype, qos, on_qos_event)
        self._children.append(pub)
        with self.backend.graph.lock:
            self.record.writers.append(pub.gid)
        self.backend.graph.publish()
        return pub

    def declare_subscription(self, topic: str, mtype: MessageType | None, qos: QoS, callback: SampleCallback,
                             on_qos_event: QoSEventCallback | None = None) -> Handle:
        """See :meth:`NodeHandle.declare_subscription`."""
        sub: Handle
        if mtype is None:
            sub = _AnySubscription(self, topic, qos, callback, on_qos_event)
        else:
            typed = DdsSubscription(self, topic, mtype.typename, qos, callback, on_qos_event, mtype.type_hash)
            with self.backend.graph.lock:
                self.record.readers.append(typed.gid)
            self.backend.graph.publish()
            sub = typed
        self._children.append(sub)
        return sub

    def forget(self, child: Handle, gid: bytes) -> None:
        """A child closed: take its GID out of the node's announcement."""
        with self.backend.graph.lock:
            for gids in (self.record.readers, self.record.writers):
                if gid in gids:
                    gids.remove(gid)
        if child in self._children:
            self._children.remove(child)
        if not self._closed:
            self.backend.graph.publish()

    def parameters(self) -> ParameterStore:
        """See :meth:`NodeHandle.parameters` (node-local)."""
        return self._params

    def declare_service(self, name: str, stype: ServiceType, on_request: RequestCallback) -> Handle:
        """See :meth:`NodeHandle.declare_service` (rmw_cyclonedds_cpp's request/reply topics)."""
        from robotmodel.bus._dds_service import DdsService

        return self._adopt(DdsService(self, name, stype, on_request))

    def declare_client(self, name: str, stype: ServiceType) -> ClientHandle:
        """See :meth:`NodeHandle.declare_client`."""
        from robotmodel.bus._dds_service import DdsClient

        client = DdsClient(self, name, stype)
        self._adopt(client)
        return client

    def _adopt(self, endpoint: Any) -> Handle:
        # A service's or client's reader and writer are the node's in ros_discovery_info, as rmw lists them.
        self._children.append(endpoint)
        with self.backend.graph.lock:
            self.record.readers.append(endpoint.reader_gid)
            self.record.writers.append(endpoint.writer_gid)
        self.backend.graph.publish()
        return cast(Handle, endpoint)

    def replace_reader(self, old: bytes, new: bytes) -> None:
        """A service's or client's reader replaced by another: announce the new one in its place."""
        with self.backend.graph.lock:
            readers = self.record.readers
            if old in readers:
                readers[readers.index(old)] = new
        if not self._closed:
            self.backend.graph.publish()

    def forget_pair(self, child: Handle, reader_gid: bytes, writer_gid: bytes) -> None:
        """A service or client closed: take its reader and writer out of the node's announcement."""
        with self.backend.graph.lock:
            if reader_gid in self.record.readers:
                self.record.readers.remove(reader_gid)
            if writer_gid in self.record.writers:
                self.record.writers.remove(writer_gid)
        if child in self._children:
            self._children.remove(child)
        if not self._closed:
            self.backend.graph.publish()

    def close(self) -> None:
        """Close the node's endpoints, then withdraw it from ros_discovery_info."""
        if self._closed:
            return
        self._closed = True
        for child in reversed(list(self._children)):
            child.close()
        self._children.clear()
        self.backend.graph.remove_node(self.record)
        self.backend.forget(self)


class DdsPublisher(PublisherHandle):
    """A DDS writer on ``rt/<topic>`` writing the seam's CDR as it is."""

    def __init__(self, node: DdsNode, topic: str, mtype: MessageType, qos: QoS,
                 on_qos_event: QoSEventCallback | None) -> None:
        backend = node.backend
        self._node = node
        self.topic = topic
        self.typename = mtype.typename
        self._types = _TypeCheck(topic, mtype.typename, "subscription")
        self._listener = make_listener(**_qos_listener(on_qos_event, topic, offered=True, types=self._types))
        self._writer: Any = DataWriter(backend.participant, backend.topic(topic, mtype.typename),
                                       qos_to_dds(qos, mtype.type_hash), listener=self._listener)
        self._gid: bytes = self._writer.guid.bytes
        self._lock = threading.Lock()
        backend.graph.watch(self._types.on_entity)

    @property
    def gid(self) -> bytes:
        """See :attr:`PublisherHandle.gid` (the writer's GUID, as rmw's GID)."""
        return self._gid

    def publish(self, payload: bytes) -> None:
        """See :meth:`PublisherHandle.publish`."""
        writer = self._writer
        if writer is None:
            raise BusError(f"publisher on '{self.topic}' is closed")
        write_raw(writer, payload, self.topic, self.typename)

    def matched(self) -> bool:
        """See :meth:`PublisherHandle.matched`."""
        writer = self._writer
        return writer is not None and writer.get_publication_matched_status().current_count > 0

    def close(self) -> None:
        """Delete the writer (its readers see it leave)."""
        with self._lock:
            writer, self._writer = self._writer, None
        if writer is not None:
            self._node.backend.graph.unwatch(self._types.on_entity)
            destroy(writer)
            self._node.forget(self, self._gid)


class DdsSubscription(Handle):
    """A DDS reader on ``rt/<topic>``; a pump thread takes its raw samples and runs the callback."""

    def __init__(self, node: DdsNode, topic: str, typename: str, qos: QoS, callback: SampleCallback,
                 on_qos_event: QoSEventCallback | None, type_hash: str = "", announce: bool = True) -> None:
        backend = node.backend
        self._node = node if announce else None
        self.topic = topic
        self.typename = typename
        self._callback = callback
        self._gids: dict[int, bytes] = {}
        self._seqs: dict[int, int] = {}
        # Cyclone may call the listener (and so the pump) before DataReader() returns: the
        # drain must find no reader then, not a missing attribute; the poke below catches up.
        self._reader: Any = None
        self._pump = Pump(f"dds-sub {topic}", self._drain)
        # An untyped subscription's reader is one of several types on purpose: no type warnings.
        self._types = _TypeCheck(topic, typename, "publisher") if announce else None
        self._listener = self._pump.listener(**_qos_listener(on_qos_event, topic, offered=False, types=self._types))
        self._reader = DataReader(backend.participant, backend.topic(topic, typename),
                                  qos_to_dds(qos, type_hash), listener=self._listener)
        self.gid: bytes = self._reader.guid.bytes
        self._warner = Warner()
        self._graph = backend.graph
        if self._types is not None:
            self._graph.watch(self._types.on_entity)
        self._pump.poke()

    def _writer_gid(self, handle: int) -> bytes:
        gid = self._gids.get(handle)
        if gid is None:
            reader = self._reader
            data = reader.get_matched_publication_data(handle) if reader is not None else None
            gid = data.key.bytes if data is not None else b""
            if gid:
                self._gids[handle] = gid
        return gid

    def _drain(self) -> None:
        while (reader := self._reader) is not None and (batch := take_raw(reader)):
            self._deliver(batch)
        # The batches' payloads are let go by now (a callback may have asked for the heap back).
        sample_released()

    def _deliver(self, batch: list[tuple[bytes, Any]]) -> None:
        for data, info in batch:
            if not info.valid_data:
                continue
            handle = info.publication_handle
            seq = self._seqs[handle] = self._seqs.get(handle, 0) + 1
            sample = Sample(self.topic, self.typename, data,
                            SampleInfo(seq, int(info.source_timestamp), self._writer_gid(handle)))
            try:
                self._callback(sample)
            except Exception:  # one bad callback must not stop the subscription
                log.exception("subscription callback on '%s' failed", self.topic)

    def close(self) -> None:
        """Delete the reader and stop its pump."""
        reader, self._reader = self._reader, None
        if reader is None:
            return
        if self._types is not None:
            self._graph.unwatch(self._types.on_entity)
        self._pump.close()
        destroy(reader)
        if self._node is not None:
            self._node.forget(self, self.gid)


class _AnySubscription(Handle):
    """Every type on a topic: one unannounced reader per type the graph shows published there."""

    def __init__(self, node: DdsNode, topic: str, qos: QoS, callback: SampleCallback,
                 on_qos_event: QoSEventCallback | None) -> None:
        self._node = node
        self._topic = topic
        self._qos = qos
        self._callback = callback
        self._on_qos_event = on_qos_event
        self._readers: dict[str, DdsSubscription] = {}
        self._skipped: set[str] = set()
        self._lock = threading.Lock()
        self._open = True
        self._graph = node.backend.graph
        self._graph.watch(self._on_entity)

    def _on_entity(self, _key: str, entity: Entity | None) -> None:
        if entity is None or entity.topic != self._topic or entity.kind.value != "publisher":
            return
        with self._lock:
            if not self._open or entity.typename in self._readers or entity.typename in self._skipped:
                return
            try:
                self._readers[entity.typename] = DdsSubscription(
                    self._node, self._topic, entity.typename, self._qos, self._callback, self._on_qos_event,
                    announce=False)
            except BusError as exc:
                self._skipped.add(entity.typename)
                log.warning("not echoing '%s' of type '%s': %s", self._topic, entity.typename, exc)

    def close(self) -> None:
        self._graph.unwatch(self._on_entity)
        with self._lock:
            self._open = False
            readers, self._readers = list(self._readers.values()), {}
        for reader in readers:
            reader.close()
