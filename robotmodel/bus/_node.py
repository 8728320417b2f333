"""rclpy's shape on the bus: a Context (one session), Nodes, Publishers and Subscriptions."""

from __future__ import annotations

import itertools
import logging
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any, Generic, NamedTuple, TypeVar

from robotmodel.bus._attachment import Attachment, AttachmentWriter, is_attachment
from robotmodel.bus._backend import Backend, Handle, RawPublisher, RawSample
from robotmodel.bus._codec import Codec, codec_for
from robotmodel.bus._domain import default_domain_id
from robotmodel.bus._graph import Graph
from robotmodel.bus._names import (
    Entity,
    EntityKind,
    resolve_topic,
    ros_type_name,
    topic_keyexpr,
    validate_namespace,
    validate_node_name,
)
from robotmodel.bus._qos import QOS_DEFAULT, QoS
from robotmodel.bus._remap import RemapRule, node_name_of, node_namespace_of, parse_rules, remap_topic
from robotmodel.errors import BusError, MessageError

__all__ = ["Context", "Node", "Publisher", "RawMessage", "Subscription", "default_domain_id"]

log = logging.getLogger("robotmodel.bus")
M = TypeVar("M")
QoSLike = QoS | int


def _qos(qos: QoSLike) -> QoS:
    return QoS(qos) if isinstance(qos, int) else qos


class Context:
    """One transport session shared by nodes (rclpy's context, rmw_zenoh's zenoh session).

    ``backend`` is ``"zenoh"`` (the default: processes and machines), ``"inprocess"``
    (this process only) or a :class:`Backend`. ``connect`` lists zenoh endpoints to use
    instead of the loopback rendezvous (see :mod:`robotmodel.bus` for the topology).
    """

    def __init__(self, *, domain_id: int | None = None, connect: Sequence[str] = (),
                 backend: str | Backend = "zenoh") -> None:
        self.domain_id = default_domain_id() if domain_id is None else int(domain_id)
        if self.domain_id < 0:
            raise BusError(f"domain id must be >= 0, got {self.domain_id}")
        if isinstance(backend, Backend):
            self.backend = backend
        elif backend == "inprocess":
            from robotmodel.bus._inprocess import InProcessBackend

            self.backend = InProcessBackend()
        elif backend == "zenoh":
            from robotmodel.bus._zenoh import ZenohBackend

            self.backend = ZenohBackend(connect=list(connect))
        else:
            raise BusError(f"unknown bus backend '{backend}' (expected 'zenoh' or 'inprocess')")
        self._ids = itertools.count()
        self._lock = threading.Lock()
        self._graph: Graph | None = None
        self._closed = False

    def next_id(self) -> int:
        """The next entity id (rmw_zenoh numbers nodes and their entities with one counter)."""
        with self._lock:
            return next(self._ids)

    @property
    def graph(self) -> Graph:
        """The live graph of this domain (started on first use)."""
        with self._lock:
            if self._graph is None:
                self._graph = Graph(self.backend, self.domain_id)
            return self._graph

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
    """A sample before decoding: the topic, its ROS type, the CDR payload and the attachment."""

    topic: str
    typename: str
    payload: bytes
    attachment: Attachment


class _Warner:
    """At most one warning per reason every ``period`` seconds, counting those held back."""

    def __init__(self, period: float = 5.0) -> None:
        self._period = period
        self._last: dict[str, float] = {}
        self._held: dict[str, int] = {}
        self._lock = threading.Lock()

    def warn(self, reason: str, text: str) -> None:
        now = time.monotonic()
        with self._lock:
            if now - self._last.get(reason, -1e9) < self._period:
                self._held[reason] = self._held.get(reason, 0) + 1
                return
            self._last[reason] = now
            held = self._held.pop(reason, 0)
        log.warning("%s%s", text, f" ({held} more since the last warning)" if held else "")


class Publisher(Generic[M]):
    """Publishes messages of one type on one topic (create it with :meth:`Node.create_publisher`)."""

    def __init__(self, node: Node, codec: Codec, topic: str, qos: QoS) -> None:
        self.topic_name = topic
        self.qos = qos
        self.codec = codec
        ctx = node.context
        self.entity = Entity(ctx.domain_id, ctx.backend.zid, node.node_id, ctx.next_id(), EntityKind.PUBLISHER,
                             node.namespace, node.name, node.enclave, topic, codec.typename, codec.type_hash,
                             qos.resolved())
        self.key = topic_keyexpr(ctx.domain_id, topic, codec.typename, codec.type_hash)
        self.gid = self.entity.gid
        self._node = node
        codec.warm()
        self._lock = threading.Lock()
        self._seq = 1
        self._attachment = AttachmentWriter(self.gid)
        self._pub: RawPublisher | None = ctx.backend.declare_publisher(self.key, qos)
        self._token: Handle | None = ctx.backend.declare_token(self.entity.keyexpr)

    def publish(self, msg: M) -> None:
        """Serialize and send one message."""
        self.publish_raw(self.codec.encode(msg))

    def publish_raw(self, payload: bytes) -> None:
        """Send already-serialized CDR (with its 4-byte header) under this publisher's attachment."""
        with self._lock:
            pub = self._pub
            if pub is None:
                raise BusError(f"publisher on '{self.topic_name}' is closed")
            seq = self._seq
            self._seq = seq + 1
            pub.put(payload, self._attachment(seq, time.time_ns()))

    def matched(self) -> bool:
        """Whether any subscriber matches this publisher's key now (plain zenoh ones included).

        Samples published before a subscriber is matched do not reach it (unless latched).
        """
        with self._lock:
            pub = self._pub
        return pub is not None and pub.matched()

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
        """Undeclare the publisher and its liveliness token."""
        with self._lock:
            pub, self._pub = self._pub, None
            token, self._token = self._token, None
        if pub is not None:
            pub.close()
        if token is not None:
            token.close()


class Subscription(Generic[M]):
    """Calls back for each message on a topic (create it with :meth:`Node.create_subscription`).

    Callbacks run on the transport's receive thread. A payload that does not decode, or a
    sample without rmw_zenoh's attachment, is dropped with a rate-limited warning.
    """

    def __init__(self, node: Node, codec: Codec | None, topic: str, qos: QoS,
                 callback: Callable[[Any], None], raw: bool) -> None:
        self.topic_name = topic
        self.qos = qos
        self.codec = codec
        self._callback = callback
        # Set before the subscriber exists: latched samples can arrive during its declaration.
        self._decode: Callable[[bytes], Any] | None = None if raw or codec is None else codec.decode
        self._warner = _Warner()
        ctx = node.context
        typename = codec.typename if codec else ""
        type_hash = codec.type_hash if codec else ""
        if codec is not None:
            codec.warm()
            key = topic_keyexpr(ctx.domain_id, topic, typename, type_hash)
        else:
            key = f"{ctx.domain_id}/{topic.strip('/')}/*/*"
        self.key = key
        self._token: Handle | None = None
        self._sub: Handle | None = ctx.backend.declare_subscriber(key, qos, self._on_sample)
        if codec is not None:
            # A type-agnostic echo is not an endpoint of one type, so it announces nothing.
            self.entity: Entity | None = Entity(
                ctx.domain_id, ctx.backend.zid, node.node_id, ctx.next_id(), EntityKind.SUBSCRIPTION,
                node.namespace, node.name, node.enclave, topic, typename, type_hash, qos.resolved())
            self._token = ctx.backend.declare_token(self.entity.keyexpr)
        else:
            self.entity = None

    def _on_sample(self, sample: RawSample) -> None:
        attachment = sample.attachment
        if attachment is None or not is_attachment(attachment):
            what = "without an attachment" if attachment is None else f"with a {len(attachment)}-byte attachment"
            self._warner.warn("attachment", f"dropped a message on '{self.topic_name}' {what} "
                                            "(rmw_zenoh's is 33 bytes)")
            return
        decode = self._decode
        if decode is None:
            att = Attachment.decode(attachment)
            chunks = sample.key.split("/")
            typename = ros_type_name(chunks[-2]) if len(chunks) >= 3 else ""
            item: Any = RawMessage(self.topic_name, typename, sample.payload, att)
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
            # The transport thread must survive a failing user callback; say so loudly.
            log.exception("subscription callback on '%s' raised", self.topic_name)

    def close(self) -> None:
        """Undeclare the subscription and its liveliness token."""
        sub, self._sub = self._sub, None
        token, self._token = self._token, None
        if sub is not None:
            sub.close()
        if token is not None:
            token.close()


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
                 domain_id: int | None = None, connect: Sequence[str] = (), backend: str | Backend = "zenoh",
                 enclave: str = "/", remappings: Sequence[str | RemapRule] = ()) -> None:
        self.remappings = parse_rules(remappings)
        # rcl renames and moves the node by the name it was created with, then remaps topics by the new one.
        self.name = validate_node_name(node_name_of(self.remappings, name))
        self.namespace = validate_namespace(node_namespace_of(self.remappings, name, namespace))
        self.enclave = validate_namespace(enclave)
        self._owns_context = context is None
        self.context = context if context is not None else Context(
            domain_id=domain_id, connect=connect, backend=backend)
        self.node_id = self.context.next_id()
        self.entity = Entity(self.context.domain_id, self.context.backend.zid, self.node_id, self.node_id,
                             EntityKind.NODE, self.namespace, self.name, self.enclave)
        self._children: list[Publisher[Any] | Subscription[Any]] = []
        self._token: Handle | None = self.context.backend.declare_token(self.entity.keyexpr)

    def get_name(self) -> str:
        """The node's name (rclpy spelling)."""
        return self.name

    def get_namespace(self) -> str:
        """The node's namespace (rclpy spelling)."""
        return self.namespace

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """The fully qualified topic name, expanded as rcl does, then remapped (unless ``only_expand``)."""
        full = resolve_topic(topic, self.namespace, self.name)
        return full if only_expand else remap_topic(self.remappings, full, self.name, self.namespace)

    def create_publisher(self, msg_type: type[M] | str, topic: str, qos: QoSLike = QOS_DEFAULT) -> Publisher[M]:
        """A publisher of ``msg_type`` on ``topic``."""
        self._check_open()
        pub: Publisher[M] = Publisher(self, codec_for(msg_type), self.resolve_topic_name(topic), _qos(qos))
        self._children.append(pub)
        return pub

    def create_subscription(self, msg_type: type[M] | str, topic: str, callback: Callable[[M], None],
                            qos: QoSLike = QOS_DEFAULT, *, raw: bool = False) -> Subscription[M]:
        """Call ``callback(msg)`` for each message on ``topic`` (``callback(RawMessage)`` with ``raw``)."""
        self._check_open()
        sub: Subscription[M] = Subscription(self, codec_for(msg_type), self.resolve_topic_name(topic), _qos(qos),
                                            callback, raw)
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

    def _check_open(self) -> None:
        if self._token is None:
            raise BusError(f"node '{self.entity.node_fqn}' is closed")

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
        """Undeclare everything this node made; end its session if it opened one."""
        for child in reversed(self._children):
            child.close()
        self._children.clear()
        token, self._token = self._token, None
        if token is not None:
            token.close()
        if self._owns_context:
            self.context.close()

    def destroy_node(self) -> None:
        """Same as :meth:`close` (rclpy's spelling)."""
        self.close()

    def __enter__(self) -> Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
