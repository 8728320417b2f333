"""rclpy's shape on the bus: a Context (one session on a wire), Nodes, Publishers and Subscriptions.

Everything here speaks ROS (names, types, QoS) through the backend seam
(:mod:`robotmodel.bus._backend`) and works the same on every wire.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Callable, Sequence
from functools import partial
from typing import Any, Generic, NamedTuple, TypeVar

from robotmodel.bus._backend import (
    Backend,
    EntityKind,
    Handle,
    NodeHandle,
    ParameterStore,
    PublisherHandle,
    QoSEvent,
    RequestId,
    Sample,
    SampleInfo,
    open_backend,
)
from robotmodel.bus._codec import Codec, codec_for
from robotmodel.bus._domain import default_domain_id
from robotmodel.bus._graph import Graph
from robotmodel.bus._names import resolve_topic, validate_namespace, validate_node_name
from robotmodel.bus._qos import QOS_DEFAULT, QoS
from robotmodel.bus._remap import RemapRule, node_name_of, node_namespace_of, parse_rules, remap_topic
from robotmodel.bus._ros1remaps import RemapWatch
from robotmodel.bus._select import default_wire
from robotmodel.bus._service import Respond, ServiceClient, ServiceServer
from robotmodel.bus._warn import Warner
from robotmodel.errors import BusError, MessageError

__all__ = ["Context", "Node", "Publisher", "RawMessage", "Subscription", "default_domain_id"]

log = logging.getLogger("robotmodel.bus")
M = TypeVar("M")
QoSLike = QoS | int
QoSEventHandler = Callable[[QoSEvent], None]


def _qos(qos: QoSLike) -> QoS:
    return QoS(qos) if isinstance(qos, int) else qos


class Context:
    """One session on one wire, shared by nodes (rclpy's context).

    ``backend`` names the wire (``"dds"`` and ``"zenoh"``: ROS 2's, processes and machines;
    ``"ros1"``: a ROS 1 master and TCPROS; ``"inprocess"``: this process only; see
    :data:`robotmodel.bus.BACKENDS`) or is an open :class:`Backend`, whose domain the context
    then takes. Without it the environment chooses as ROS's setup does
    (:func:`robotmodel.bus.default_wire`: ``"ros1"`` in a sourced ROS 1, ``"zenoh"`` with
    ``RMW_IMPLEMENTATION=rmw_zenoh_cpp``, else ``"dds"``). ``connect`` says where to meet the
    others (zenoh: endpoints instead of the loopback rendezvous; DDS: hosts, as
    ROS_STATIC_PEERS; see :mod:`robotmodel.bus`).
    """

    def __init__(self, *, domain_id: int | None = None, connect: Sequence[str] = (),
                 backend: str | Backend | None = None) -> None:
        if backend is None:
            backend = default_wire()
        if isinstance(backend, Backend):
            self.backend = backend
            self.domain_id = backend.domain_id
        else:
            domain = default_domain_id() if domain_id is None else int(domain_id)
            if domain < 0:
                raise BusError(f"domain id must be >= 0, got {domain}")
            self.backend = open_backend(backend, domain, connect)
            self.domain_id = domain
        self._lock = threading.Lock()
        self._graph: Graph | None = None
        self._closed = False

    @property
    def encoding(self) -> str:
        """The serialization the wire's payloads are in (``"cdr"``, ``"ros1"``)."""
        return self.backend.encoding

    @property
    def graph(self) -> Graph:
        """The live graph of this domain (started on first use)."""
        with self._lock:
            if self._graph is None:
                self._graph = Graph(self.backend)
            return self._graph

    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """The policy that keeps such a publisher and subscription apart on this wire ('' if none)."""
        return self.backend.qos_incompatibility(publisher, subscription)

    def close(self) -> None:
        """End the session: every node, publisher and subscription on it goes away."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            graph, self._graph = self._graph, None
        if graph is not None:
            graph.close()
        self.backend.close()

    def __enter__(self) -> Context:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class RawMessage(NamedTuple):
    """A sample before decoding: topic, ROS type, payload (in ``encoding``) and the wire's sample info."""

    topic: str
    typename: str
    payload: bytes
    info: SampleInfo
    encoding: str


# tuple.__new__ bound to the class: a third of the NamedTuple constructor's cost per sample.
_new_raw = partial(tuple.__new__, RawMessage)


def _warn_incompatible(event: QoSEvent, publisher: bool) -> None:
    # rclcpp's and rclpy's default incompatible-QoS handlers' texts.
    if publisher:
        log.warning("New subscription discovered on topic '%s', requesting incompatible QoS. "
                    "No messages will be sent to it. Last incompatible policy: %s", event.topic, event.last_policy)
    else:
        log.warning("New publisher discovered on topic '%s', offering incompatible QoS. "
                    "No messages will be received from it. Last incompatible policy: %s",
                    event.topic, event.last_policy)


class Publisher(Generic[M]):
    """Publishes messages of one type on one topic (create it with :meth:`Node.create_publisher`).

    A subscription whose QoS cannot match on this wire (see :meth:`Context.qos_incompatibility`)
    gets nothing; ``on_incompatible_qos(event)`` is then called, by default rclpy's warning.
    ``incompatible_qos`` holds the latest such event.
    """

    def __init__(self, node: Node, codec: Codec, topic: str, qos: QoS,
                 on_incompatible_qos: QoSEventHandler | None = None) -> None:
        self.topic_name = topic
        self.qos = qos
        self.codec = codec
        self.incompatible_qos: QoSEvent | None = None
        self._on_incompatible = on_incompatible_qos
        self._node = node
        codec.warm()
        self.handle: PublisherHandle | None = node.handle.declare_publisher(
            topic, codec.message_type(), qos, self._on_qos_event)
        self.gid = self.handle.gid

    def _on_qos_event(self, event: QoSEvent) -> None:
        self.incompatible_qos = event
        if self._on_incompatible is None:
            _warn_incompatible(event, publisher=True)
        else:
            self._on_incompatible(event)

    def publish(self, msg: M) -> None:
        """Serialize and send one message."""
        self.publish_raw(self.codec.encode(msg))

    def publish_raw(self, payload: bytes) -> None:
        """Send an already-serialized message (in the wire's encoding)."""
        handle = self.handle
        if handle is None:
            raise BusError(f"publisher on '{self.topic_name}' is closed")
        handle.publish(payload)

    def matched(self) -> bool:
        """Whether a compatible subscription receives this publisher's samples now (on zenoh: any subscriber).

        Samples published before a subscription is matched do not reach it (unless latched).
        """
        handle = self.handle
        return handle is not None and handle.matched()

    def get_subscription_count(self) -> int:
        """How many subscriptions on this topic the graph shows (any type)."""
        return len(self._node.context.graph.endpoints(self.topic_name, EntityKind.SUBSCRIPTION))

    def wait_for_subscriptions(self, count: int = 1, timeout: float = 5.0) -> bool:
        """Wait until at least ``count`` subscriptions are on the topic; False at the timeout."""
        graph = self._node.context.graph
        return graph.wait_for(
            lambda es: sum(e.kind is EntityKind.SUBSCRIPTION and e.topic == self.topic_name for e in es) >= count,
            timeout)

    def close(self) -> None:
        """Withdraw the publisher."""
        handle, self.handle = self.handle, None
        if handle is not None:
            handle.close()


class Subscription(Generic[M]):
    """Calls back for each message on a topic (create it with :meth:`Node.create_subscription`).

    Callbacks run on the wire's receive thread. A payload that does not decode is dropped with
    a rate-limited warning. Incompatible publishers are reported as for :class:`Publisher`.
    """

    def __init__(self, node: Node, codec: Codec | None, topic: str, qos: QoS,
                 callback: Callable[[Any], None], raw: bool,
                 on_incompatible_qos: QoSEventHandler | None = None) -> None:
        self.topic_name = topic
        self.qos = qos
        self.codec = codec
        self.incompatible_qos: QoSEvent | None = None
        self._on_incompatible = on_incompatible_qos
        self._callback = callback
        self._encoding = node.context.encoding
        # Set before the subscription exists: latched samples can arrive during its declaration.
        self._decode: Callable[[bytes], Any] | None = None if raw or codec is None else codec.decode
        self._warner = Warner()
        if codec is not None:
            codec.warm()
        self.handle: Handle | None = node.handle.declare_subscription(
            topic, None if codec is None else codec.message_type(), qos, self._on_sample, self._on_qos_event)

    def _on_qos_event(self, event: QoSEvent) -> None:
        self.incompatible_qos = event
        if self._on_incompatible is None:
            _warn_incompatible(event, publisher=False)
        else:
            self._on_incompatible(event)

    def _on_sample(self, sample: Sample) -> None:
        decode = self._decode
        if decode is None:
            item: Any = _new_raw((self.topic_name, sample.typename, sample.payload, sample.info, self._encoding))
        else:
            try:
                item = decode(sample.payload)
            except MessageError as exc:  # a bad payload is dropped, never a crash
                self._warner.warn("decode", f"dropped a message on '{self.topic_name}' that does not decode as "
                                            f"{self.codec.typename if self.codec else '?'}: "
                                            f"{type(exc).__name__}: {exc}")
                return
        try:
            self._callback(item)
        except Exception:
            # The wire's thread must survive a failing user callback; say so loudly.
            log.exception("subscription callback on '%s' raised", self.topic_name)

    def close(self) -> None:
        """Withdraw the subscription."""
        handle, self.handle = self.handle, None
        if handle is not None:
            handle.close()


class Node:
    """A ROS node on the bus, rclpy-shaped.

    >>> from robotmodel.bus import Node, typestore
    >>> String = typestore().types["std_msgs/msg/String"]
    >>> got = []
    >>> with Node("talker", backend="inprocess", domain_id=42) as node:
    ...     sub = node.create_subscription(String, "chatter", got.append, 10)
    ...     pub = node.create_publisher(String, "chatter", 10)
    ...     pub.publish(String(data="hello"))
    >>> got[0].data
    'hello'

    Without ``context``, the node opens (and on close, ends) a session of its own; pass
    ``domain_id``, ``connect`` and ``backend`` as for :class:`Context`. Message types are
    classes with ``__msgtype__`` or ROS type names (meaning rosbags' classes).
    ``remappings`` are ROS 2 remap rules (``"joint_states:=/arm/joint_states"``,
    ``"__ns:=/r1"``, ``"rsp:/tf:=/r1/tf"``), applied as rcl applies ``--ros-args -r`` rules
    to every topic the node names; see :mod:`robotmodel.bus._remap`.
    """

    def __init__(self, name: str, namespace: str = "/", *, context: Context | None = None,
                 domain_id: int | None = None, connect: Sequence[str] = (), backend: str | Backend | None = None,
                 enclave: str = "/", remappings: Sequence[str | RemapRule] = ()) -> None:
        self.remappings = parse_rules(remappings)
        # rcl renames and moves the node by the name it was created with, then remaps topics by the new one.
        self.name = validate_node_name(node_name_of(self.remappings, name))
        self.namespace = validate_namespace(node_namespace_of(self.remappings, name, namespace))
        self.enclave = validate_namespace(enclave)
        self._owns_context = context is None
        self.context = context if context is not None else Context(
            domain_id=domain_id, connect=connect, backend=backend)
        self._children: list[Publisher[Any] | Subscription[Any] | ServiceServer | ServiceClient] = []
        try:
            self.handle: NodeHandle = self.context.backend.create_node(self.name, self.namespace, self.enclave)
        except BaseException:
            if self._owns_context:
                self.context.close()
            raise
        self._closed = False
        # On ROS 1 every NAME:=VALUE word is a remap: name those that match nothing (robotmodel.bus._ros1remaps).
        self._remap_watch: RemapWatch | None = None
        if self.remappings and self.context.backend.name == "ros1":
            self._remap_watch = RemapWatch(self.remappings, self.name, self.namespace)

    @property
    def fully_qualified_name(self) -> str:
        """``/namespace/name`` (rclpy's property)."""
        return self.namespace.rstrip("/") + "/" + self.name

    @property
    def parameters(self) -> ParameterStore:
        """The node's parameter store on its wire (node-local on zenoh and in-process)."""
        return self.handle.parameters()

    def get_name(self) -> str:
        """The node's name (rclpy spelling)."""
        return self.name

    def get_namespace(self) -> str:
        """The node's namespace (rclpy spelling)."""
        return self.namespace

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """The fully qualified topic name, expanded as rcl does, then remapped (unless ``only_expand``)."""
        full = resolve_topic(topic, self.namespace, self.name)
        if only_expand:
            return full
        if self._remap_watch is not None:
            self._remap_watch.saw(full)
        return remap_topic(self.remappings, full, self.name, self.namespace)

    def create_publisher(self, msg_type: type[M] | str, topic: str, qos: QoSLike = QOS_DEFAULT, *,
                         on_incompatible_qos: QoSEventHandler | None = None) -> Publisher[M]:
        """A publisher of ``msg_type`` on ``topic``."""
        self._check_open()
        pub: Publisher[M] = Publisher(self, codec_for(msg_type, self.context.encoding),
                                      self.resolve_topic_name(topic), _qos(qos), on_incompatible_qos)
        self._children.append(pub)
        return pub

    def create_subscription(self, msg_type: type[M] | str, topic: str, callback: Callable[[M], None],
                            qos: QoSLike = QOS_DEFAULT, *, raw: bool = False,
                            on_incompatible_qos: QoSEventHandler | None = None) -> Subscription[M]:
        """Call ``callback(msg)`` for each message on ``topic`` (``callback(RawMessage)`` with ``raw``)."""
        self._check_open()
        sub: Subscription[M] = Subscription(self, codec_for(msg_type, self.context.encoding),
                                            self.resolve_topic_name(topic), _qos(qos), callback, raw,
                                            on_incompatible_qos)
        self._children.append(sub)
        return sub

    def create_raw_subscription(self, topic: str, callback: Callable[[RawMessage], None],
                                qos: QoSLike = QOS_DEFAULT) -> Subscription[RawMessage]:
        """Receive every sample on ``topic`` whatever its type, undecoded (for ``topic echo``)."""
        self._check_open()
        sub: Subscription[RawMessage] = Subscription(self, None, self.resolve_topic_name(topic), _qos(qos),
                                                     callback, True)
        self._children.append(sub)
        return sub

    def create_service(self, srv_type: str, name: str, on_request: Callable[[Any, Respond, RequestId], None], *,
                       request_type: Any = None, response_type: Any = None) -> ServiceServer:
        """Serve ``srv_type`` (``pkg/srv/Name``) as ``name``: ``on_request(request, respond, request_id)``."""
        self._check_open()
        server = ServiceServer(self, srv_type, self.resolve_service_name(name), on_request, request_type,
                               response_type)
        self._children.append(server)
        return server

    def create_client(self, srv_type: str, name: str, *, request_type: Any = None,
                      response_type: Any = None) -> ServiceClient:
        """A client of the service ``name`` of ``srv_type``."""
        self._check_open()
        client = ServiceClient(self, srv_type, self.resolve_service_name(name), request_type, response_type)
        self._children.append(client)
        return client

    def resolve_service_name(self, name: str) -> str:
        """The fully qualified service name (expanded and remapped as a topic name, as rcl does)."""
        return self.resolve_topic_name(name)

    def _check_open(self) -> None:
        if self._closed:
            raise BusError(f"node '{self.fully_qualified_name}' is closed")

    def get_topic_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every topic of the domain with its types, sorted (rclpy's list)."""
        return self.context.graph.topic_names_and_types()

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """Every node of the domain as (name, namespace)."""
        return self.context.graph.node_names_and_namespaces()

    def count_publishers(self, topic: str) -> int:
        """How many publishers the graph shows on ``topic``."""
        return len(self.context.graph.endpoints(self.resolve_topic_name(topic), EntityKind.PUBLISHER))

    def count_subscribers(self, topic: str) -> int:
        """How many subscriptions the graph shows on ``topic``."""
        return len(self.context.graph.endpoints(self.resolve_topic_name(topic), EntityKind.SUBSCRIPTION))

    def close(self) -> None:
        """Withdraw everything this node made, then the node; end its session if it opened one."""
        for child in reversed(self._children):
            child.close()
        self._children.clear()
        if self._remap_watch is not None:
            self._remap_watch.close()
        if not self._closed:
            self._closed = True
            self.handle.close()
        if self._owns_context:
            self.context.close()

    def destroy_node(self) -> None:
        """Same as :meth:`close` (rclpy's spelling)."""
        self.close()

    def __enter__(self) -> Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
