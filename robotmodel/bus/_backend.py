"""The backend seam: what one wire gives the ROS layer above it, whichever wire it is.

Above this module sit :mod:`._node` (Context, Node, Publisher, Subscription) and
:mod:`._graph` (the graph cache); they speak ROS (resolved names, ROS type names, QoS,
nodes) and never know which wire carries them. Below it sit the wires: :mod:`._inprocess`
(one process, no sockets), :mod:`._zenoh` (rmw_zenoh's key expressions, attachments and
liveliness tokens), :mod:`._dds` (ROS 2's DDS conventions on Cyclone DDS: ``rt/``
topics, ``ros_discovery_info``) and :mod:`._ros1` (a ROS 1 master's XML-RPC, TCPROS, the
parameter server). A wire is chosen by name with :func:`open_backend`; :data:`BACKENDS`
lists the names, :func:`default_wire` picks one from the environment as ROS does.

Contract every wire keeps (the conformance suite in ``tests/bus/conformance`` checks it):

Session. A :class:`Backend` is one session on one wire in one ROS domain (rmw's context):
``open(domain_id, connect)`` makes it (``connect``: where to meet the others, e.g. zenoh
endpoints, a ROS 1 master URI, DDS static peers; empty means the wire's default) and
:meth:`Backend.close` ends it, taking with it every node, publisher and subscription it
made (peers see them leave). Closing twice is harmless.

Payloads. The wire carries bytes in one serialization, named by :attr:`Backend.encoding`
with MCAP's message-encoding names: ``"cdr"`` (CDR with its 4-byte encapsulation header,
as ROS 2 writes it: zenoh, DDS, in-process) or ``"ros1"`` (ROS 1 serialization). The layer
above picks the codec for that encoding (:func:`robotmodel.bus.codec_for`) and hands the
wire bytes; it never branches on the wire. A :class:`MessageType` names the type with all
a wire may need: the ROS type name, the RIHS01 hash (ROS 2 keys and user data), and for
ROS 1 the md5sum and full message definition (connection header); a wire uses the fields
it needs and must not require the others.

Nodes. :meth:`Backend.create_node` registers a node (name, namespace, enclave; names
already validated and remapped above) and returns a :class:`NodeHandle`; the node is in the
graph until the handle is closed or the session ends or its process dies. Publishers and
subscriptions are made on a node and carry its name into the graph.

Publishing. :meth:`NodeHandle.declare_publisher` (fully qualified topic, type, QoS) returns
a :class:`PublisherHandle`. ``publish(payload)`` sends one sample; the wire adds what it
carries per sample (zenoh: sequence number, source time and GID in the attachment; ROS 1:
nothing). ``matched()`` says whether a compatible subscription is known to receive now.
Samples are delivered to each matched subscription in publish order (reliable wires lose
none: a reliable keep-all publisher blocks rather than drop). QoS, per policy:

- reliability: RELIABLE or BEST_EFFORT (ROS 1 is always reliable, TCP);
- durability: TRANSIENT_LOCAL keeps the last ``depth`` samples and gives them to every
  subscription matched later that asks for them (a transient-local subscription); VOLATILE
  subscriptions never get a sample published before they matched. ROS 1 has durability on
  the publisher only (``latch=True``, its last sample to every new subscriber), so there a
  volatile subscription gets the latched sample too, as rospy's does;
- history and depth: KEEP_LAST(depth) or KEEP_ALL.

Subscribing. :meth:`NodeHandle.declare_subscription` (topic, type or None for any type,
QoS, callback) calls ``callback(Sample)`` on a thread of the wire's for each sample, one
at a time per subscription, in order per publisher; callbacks of different subscriptions
may run at the same time (executors that serialize them belong above the seam). A typed subscription only gets samples
of its type; an untyped one (``ros2 topic echo`` without a type) gets every type on the
topic, each :class:`Sample` naming its type, and is not announced in the graph. With each
sample comes a :class:`SampleInfo`: the publisher's 16-byte GID (equal to the
:attr:`Entity.gid` of that publisher in the graph, so the layer above can name its node;
ROS 1 has no GID: the wire derives one from the publisher's callerid and topic), the
publisher's per-sample sequence number (from 1) and its source timestamp (ns) where the
wire carries them (else the wire's receive-side count and receive time), and the
publishing node's name where the wire carries it (ROS 1's callerid).

QoS compatibility. :meth:`Backend.qos_incompatibility` answers, for a publisher's and a
subscription's QoS, which policy keeps them from matching on this wire ('' when they
match), as that wire's ROS does: DDS and the in-process wire follow rmw_dds_common's
rules (best-effort publisher / reliable subscription: RELIABILITY; volatile publisher /
transient-local subscription: DURABILITY; deadline, liveliness and lease likewise);
rmw_zenoh matches every pair of one topic and type ("In Zenoh, there are no QoS
incompatibilities"), and so does ROS 1 (no QoS). Endpoints that do not match exchange no
sample, and both get a :class:`QoSEvent` through the ``on_qos_event`` callback they were
declared with, once per incompatible peer (rmw's OFFERED/REQUESTED_INCOMPATIBLE_QOS).

Graph. :meth:`Backend.watch_graph` calls ``callback(key, entity)`` for every entity of the
domain it knows (nodes, publishers, subscriptions; its own included), then for each
arrival, and ``callback(key, None)`` for each departure; ``key`` is the wire's unique text
for the entity. An :class:`Entity` names its node (name, namespace, enclave and a
``node_key`` telling apart nodes that share a name), and for an endpoint the topic, type
and QoS. The entities of a node whose process dies leave within the wire's liveliness
deadline (zenoh: when the link drops; DDS: the participant's lease; in-process: when its
session closes). ROS 1's master keeps a killed node registered until cleaned up (``rosnode
cleanup``); the ROS 1 wire keeps them as its master does (it prunes nothing).

Parameters. :meth:`NodeHandle.parameters` is the node's parameter store
(:class:`ParameterStore`: get/set/has/delete/names, names as the node sees them). The
in-process and zenoh wires keep a node-local store (:class:`LocalParameters`), as rclpy
keeps parameters in the node; ROS 2's parameter services are served above the seam, over
:meth:`NodeHandle.declare_service` (:mod:`robotmodel.rclpy`). A ROS 1 wire answers with the
master's parameter server: names resolved against the node's namespace (``~name``
private), ``search`` up the namespace as ROS 1's searchParam does, and set/delete visible
to every node.

Services. :meth:`NodeHandle.declare_service` (fully qualified name, :class:`ServiceType`,
``on_request``) serves requests: the wire calls ``on_request(payload, request_id, respond)``
on a thread of its own for each request, and ``respond(payload)`` (from any thread, at any
time later, at most once) sends the response to the client that asked. A
:class:`ClientHandle` from :meth:`NodeHandle.declare_client` sends requests
(``request(payload, on_response)``, returning the request's sequence number, from 1 per
client) and calls ``on_response(payload)`` once with the response to that request and to no
other; ``server_ready()`` says whether a server of the name and type is known. Services and
clients are in the graph (:attr:`EntityKind.SERVICE`, :attr:`EntityKind.CLIENT`, ``topic``
being the service name). Each wire carries the request id as its ROS 2 does: in-process
directly; zenoh as rmw_zenoh (a queryable on the service's key, the request's attachment
naming the client's GID and sequence number); DDS as rmw_cyclonedds_cpp (``rq/<name>Request``
and ``rr/<name>Reply`` topics, each payload starting with the client's 64-bit id and the
sequence number). The ROS 1 wire has none here (:class:`robotmodel.errors.BusError`).

Nothing above this module imports a wire's module (``tests/bus/test_seam.py`` checks it);
the wires import only this module and the shared ROS vocabulary (:mod:`._qos`,
:mod:`._names`, :mod:`._warn`).
"""

from __future__ import annotations

import importlib
import threading
from abc import ABC, abstractmethod
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, ClassVar, NamedTuple

from robotmodel.bus._qos import QoS
from robotmodel.errors import BusError

__all__ = [
    "BACKENDS",
    "CDR",
    "ROS1",
    "Backend",
    "ClientHandle",
    "Entity",
    "EntityKind",
    "GraphCallback",
    "Handle",
    "LocalParameters",
    "MessageType",
    "NodeHandle",
    "ParameterStore",
    "PublisherHandle",
    "QoSEvent",
    "QoSEventCallback",
    "RequestCallback",
    "RequestId",
    "Responder",
    "ResponseCallback",
    "Sample",
    "SampleCallback",
    "SampleInfo",
    "ServiceType",
    "open_backend",
]

#: Payload encodings, by MCAP's message-encoding names.
CDR = "cdr"
ROS1 = "ros1"


@dataclass(frozen=True, slots=True)
class MessageType:
    """A message type as the wires name it (each uses the fields it needs)."""

    typename: str
    type_hash: str = ""
    md5sum: str = ""
    definition: str = ""


@dataclass(frozen=True, slots=True)
class ServiceType:
    """A service type as the wires name it: ``pkg/srv/Name``, its two messages and its RIHS01 hash."""

    typename: str
    request: MessageType
    response: MessageType
    type_hash: str = ""


class RequestId(NamedTuple):
    """Who asked (the client's 16-byte GID) and which of its requests (from 1): rmw's request id."""

    client_gid: bytes
    sequence_number: int


class SampleInfo(NamedTuple):
    """What the wire says about a received sample (rmw's message info)."""

    sequence_number: int
    source_timestamp_ns: int
    gid: bytes
    publisher: str = ""


class Sample(NamedTuple):
    """A received sample: fully qualified topic, ROS type name, payload in the wire's encoding."""

    topic: str
    typename: str
    payload: bytes
    info: SampleInfo


class EntityKind(StrEnum):
    """What an entity of the ROS graph is."""

    NODE = "node"
    PUBLISHER = "publisher"
    SUBSCRIPTION = "subscription"
    SERVICE = "service"
    CLIENT = "client"


@dataclass(frozen=True, slots=True)
class Entity:
    """One node, publisher, subscription, service or client of the ROS graph.

    ``namespace`` and ``enclave`` are ROS names ('/' for the root). For endpoints, ``topic``
    is the fully qualified topic, ``typename`` the ROS type (``pkg/msg/Name``), ``type_hash``
    its RIHS01 text where the wire has one, ``qos`` the endpoint's QoS and ``gid`` the
    16-byte id its samples carry. ``node_key`` tells apart nodes of one name (zenoh: session
    and node id; ROS 1: the caller id, as the master keeps one node per name; DDS:
    participant GID and the node's place in it); it is '' for an endpoint whose node the wire
    does not know (DDS: no ``ros_discovery_info`` names it; rmw shows it under
    ``_NODE_NAME_UNKNOWN_``).
    """

    kind: EntityKind
    node_name: str
    namespace: str
    enclave: str = "/"
    topic: str = ""
    typename: str = ""
    type_hash: str = ""
    qos: QoS | None = None
    gid: bytes = b""
    node_key: str = ""

    @property
    def node_fqn(self) -> str:
        """The node's fully qualified name, e.g. ``/ns/talker``."""
        return self.namespace.rstrip("/") + "/" + self.node_name


class QoSEvent(NamedTuple):
    """An incompatible-QoS status (rmw's ``rmw_qos_incompatible_event_status_t``)."""

    total_count: int
    total_count_change: int
    last_policy: str
    topic: str


SampleCallback = Callable[[Sample], None]
Responder = Callable[[bytes], None]
RequestCallback = Callable[[bytes, RequestId, Responder], None]
ResponseCallback = Callable[[bytes], None]
QoSEventCallback = Callable[[QoSEvent], None]
GraphCallback = Callable[[str, "Entity | None"], None]


class Handle(ABC):
    """Something declared on a wire that must be released."""

    @abstractmethod
    def close(self) -> None:
        """Undeclare it; closing twice is harmless."""


class PublisherHandle(Handle):
    """A declared publisher."""

    @property
    @abstractmethod
    def gid(self) -> bytes:
        """The 16-byte id its samples carry (equal to its graph entity's ``gid``)."""

    @abstractmethod
    def publish(self, payload: bytes) -> None:
        """Send one sample (bytes in the wire's encoding); raises BusError once closed."""

    @abstractmethod
    def matched(self) -> bool:
        """Whether a compatible subscription is known to receive its samples now."""


class ClientHandle(Handle):
    """A declared service client (see the module docstring's Services)."""

    @property
    @abstractmethod
    def gid(self) -> bytes:
        """The client's 16-byte id, as its requests' ids carry it."""

    @abstractmethod
    def request(self, payload: bytes, on_response: ResponseCallback) -> int:
        """Send one request; ``on_response(payload)`` gets its response. Returns its sequence number."""

    @abstractmethod
    def server_ready(self) -> bool:
        """Whether a server of this service is known now."""


class ParameterStore(ABC):
    """A node's parameters, by the names the node uses (see the module docstring)."""

    @abstractmethod
    def get(self, name: str) -> Any:
        """The value; raises KeyError when it is not set."""

    @abstractmethod
    def set(self, name: str, value: Any) -> None:
        """Set (or replace) a value."""

    @abstractmethod
    def has(self, name: str) -> bool:
        """Whether ``name`` is set."""

    @abstractmethod
    def delete(self, name: str) -> None:
        """Remove ``name``; raises KeyError when it is not set."""

    @abstractmethod
    def names(self) -> list[str]:
        """Every name set, sorted."""

    def search(self, name: str) -> str | None:
        """The name under which ``name`` is found, or None (ROS 1 searches up the namespace)."""
        return name if self.has(name) else None


class LocalParameters(ParameterStore):
    """A node-local store (in-process and zenoh wires; rclpy keeps parameters in the node)."""

    def __init__(self) -> None:
        self._values: dict[str, Any] = {}
        self._lock = threading.Lock()

    def get(self, name: str) -> Any:
        """See :meth:`ParameterStore.get`."""
        with self._lock:
            return self._values[name]

    def set(self, name: str, value: Any) -> None:
        """See :meth:`ParameterStore.set`."""
        with self._lock:
            self._values[name] = value

    def has(self, name: str) -> bool:
        """See :meth:`ParameterStore.has`."""
        with self._lock:
            return name in self._values

    def delete(self, name: str) -> None:
        """See :meth:`ParameterStore.delete`."""
        with self._lock:
            del self._values[name]

    def names(self) -> list[str]:
        """See :meth:`ParameterStore.names`."""
        with self._lock:
            return sorted(self._values)


class NodeHandle(Handle):
    """A node registered on the wire; closing it withdraws the node and all it declared."""

    @abstractmethod
    def declare_publisher(self, topic: str, mtype: MessageType, qos: QoS,
                          on_qos_event: QoSEventCallback | None = None) -> PublisherHandle:
        """A publisher of ``mtype`` on the fully qualified ``topic``."""

    @abstractmethod
    def declare_subscription(self, topic: str, mtype: MessageType | None, qos: QoS, callback: SampleCallback,
                             on_qos_event: QoSEventCallback | None = None) -> Handle:
        """Call ``callback(sample)`` for each sample on ``topic`` (of ``mtype``; None: any type)."""

    @abstractmethod
    def parameters(self) -> ParameterStore:
        """The node's parameter store."""

    def declare_service(self, name: str, stype: ServiceType, on_request: RequestCallback) -> Handle:
        """Serve ``name``: ``on_request(payload, request_id, respond)`` for each request."""
        raise BusError(f"cannot serve '{name}': this wire has no ROS 2 services")

    def declare_client(self, name: str, stype: ServiceType) -> ClientHandle:
        """A client of the service ``name``."""
        raise BusError(f"cannot call '{name}': this wire has no ROS 2 services")


class Backend(ABC):
    """One session on one wire in one ROS domain (see the module docstring for the contract)."""

    #: The wire's name, as :func:`open_backend` takes it.
    name: ClassVar[str] = ""
    #: The serialization its payloads are in (:data:`CDR` or :data:`ROS1`).
    encoding: ClassVar[str] = CDR

    def __init__(self, domain_id: int) -> None:
        self.domain_id = domain_id

    @classmethod
    @abstractmethod
    def open(cls, domain_id: int, connect: Sequence[str] = ()) -> Backend:
        """Open a session in ``domain_id``; ``connect`` names where to meet the others."""

    @abstractmethod
    def create_node(self, name: str, namespace: str, enclave: str = "/") -> NodeHandle:
        """Register a node (valid, remapped names) and return its handle."""

    @abstractmethod
    def watch_graph(self, callback: GraphCallback) -> Handle:
        """Call ``callback(key, entity)`` for the graph's entities now and as they come, ``(key, None)`` as they go."""

    @abstractmethod
    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """The policy that keeps these two from matching on this wire ('' when they match)."""

    @abstractmethod
    def close(self) -> None:
        """End the session and everything declared on it."""


#: Wire name -> "module:class" of its backend (imported only when opened).
BACKENDS: dict[str, str] = {
    "inprocess": "robotmodel.bus._inprocess:InProcessBackend",
    "ros1": "robotmodel.bus._ros1:Ros1Backend",
    "zenoh": "robotmodel.bus._zenoh:ZenohBackend",
    "dds": "robotmodel.bus._dds:DdsBackend",
}


def open_backend(name: str, domain_id: int, connect: Sequence[str] = ()) -> Backend:
    """Open a session on the wire called ``name`` (a key of :data:`BACKENDS`)."""
    target = BACKENDS.get(name)
    if target is None:
        known = "', '".join(sorted(BACKENDS))
        raise BusError(f"unknown bus backend '{name}' (expected '{known}')")
    module, _, cls_name = target.partition(":")
    cls: type[Backend] = getattr(importlib.import_module(module), cls_name)
    return cls.open(domain_id, connect)
