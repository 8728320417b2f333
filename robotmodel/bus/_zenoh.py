"""The zenoh wire: ROS 2 nodes, topics and graph in rmw_zenoh's form, behind the backend seam.

What goes on the wire is rmw_zenoh's (Jazzy and later): a publisher puts CDR on the key
:func:`topic_keyexpr` gives, with the 33-byte attachment (sequence number, source time, GID);
every node, publisher and subscription declares a liveliness token (:class:`Token`), from
which every session builds the graph. Node and entity ids come from one counter per session,
as rmw_zenoh numbers them. As in rmw_zenoh, any publisher and subscription of one topic and
type match whatever their QoS (zenoh's keys carry no QoS), so no incompatible-QoS event is
ever raised. Parameters are node-local. Services are rmw_zenoh's queryables (:mod:`._zenoh_service`).
"""

from __future__ import annotations

import itertools
import threading
import time
from collections.abc import Sequence
from functools import partial
from typing import Any

from robotmodel.bus._attachment import (
    ATTACHMENT_SIZE,
    LABELLED_PREFIX,
    AttachmentWriter,
    read_attachment,
    unpack_attachment,
)
from robotmodel.bus._backend import (
    CDR,
    Backend,
    ClientHandle,
    EntityKind,
    GraphCallback,
    Handle,
    LocalParameters,
    MessageType,
    NodeHandle,
    ParameterStore,
    PublisherHandle,
    QoSEventCallback,
    RequestCallback,
    Sample,
    SampleCallback,
    SampleInfo,
    ServiceType,
)
from robotmodel.bus._names import ros_type_name
from robotmodel.bus._qos import QoS
from robotmodel.bus._warn import Warner
from robotmodel.bus._zenoh_names import ADMIN_SPACE, Token, topic_keyexpr
from robotmodel.bus._zenoh_session import RawPublisher, ZenohSession
from robotmodel.errors import BusError

__all__ = ["ZenohBackend"]

# How long the graph's first query waits for the tokens already out there.
_GRAPH_QUERY_S = 1.0
# tuple.__new__ bound to the classes: a third of a NamedTuple's own constructor on the receive path.
_new_sample = partial(tuple.__new__, Sample)
_new_info = partial(tuple.__new__, SampleInfo)


class ZenohBackend(Backend):
    """A zenoh session speaking rmw_zenoh's wire (see :mod:`robotmodel.bus._config` for the topology)."""

    name = "zenoh"
    encoding = CDR

    def __init__(self, domain_id: int, session: ZenohSession) -> None:
        super().__init__(domain_id)
        self.zenoh = session
        self._ids = itertools.count()
        self._lock = threading.Lock()

    @classmethod
    def open(cls, domain_id: int, connect: Sequence[str] = ()) -> ZenohBackend:
        """See :meth:`Backend.open` (``connect``: zenoh endpoints instead of the loopback rendezvous)."""
        return cls(domain_id, ZenohSession(connect=list(connect)))

    @property
    def session(self) -> Any:
        """The underlying ``zenoh.Session``."""
        return self.zenoh.session

    @property
    def zid(self) -> str:
        """The session id as rmw_zenoh writes it in tokens."""
        return self.zenoh.zid

    def next_id(self) -> int:
        """The next node or entity id (rmw_zenoh numbers them with one counter per session)."""
        with self._lock:
            return next(self._ids)

    def create_node(self, name: str, namespace: str, enclave: str = "/") -> ZenohNode:
        """See :meth:`Backend.create_node`."""
        return ZenohNode(self, name, namespace, enclave)

    def watch_graph(self, callback: GraphCallback) -> Handle:
        """See :meth:`Backend.watch_graph`: the domain's liveliness tokens, read as rmw_zenoh reads them."""

        def on_token(token: str, alive: bool) -> None:
            if not alive:
                callback(token, None)
                return
            try:
                parsed = Token.parse(token)
            except BusError:
                return  # not ours to read (another tool's token under @ros2_lv)
            callback(token, parsed.entity())

        pattern = f"{ADMIN_SPACE}/{self.domain_id}/**"
        watch = self.zenoh.watch_tokens(pattern, on_token)
        for token in self.zenoh.get_tokens(pattern, _GRAPH_QUERY_S):
            on_token(token, True)
        return watch

    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """See :meth:`Backend.qos_incompatibility`: never, as rmw_zenoh (keys carry no QoS)."""
        del publisher, subscription
        return ""

    def close(self) -> None:
        """See :meth:`Backend.close`."""
        self.zenoh.close()


class ZenohNode(NodeHandle):
    """A node: its liveliness token, and the publishers and subscriptions declared on it."""

    def __init__(self, backend: ZenohBackend, name: str, namespace: str, enclave: str) -> None:
        self.backend = backend
        self.node_id = backend.next_id()
        self.token = Token(backend.domain_id, backend.zid, self.node_id, self.node_id, EntityKind.NODE,
                           namespace, name, enclave)
        self._children: list[Handle] = []
        self._params = LocalParameters()
        self._closed = False
        self._token: Handle | None = backend.zenoh.declare_token(self.token.keyexpr)

    def entity_token(self, kind: EntityKind, topic: str, mtype: MessageType, qos: QoS) -> Token:
        """The token of a new endpoint of this node (it takes the next entity id)."""
        t = self.token
        return Token(t.domain_id, t.zid, self.node_id, self.backend.next_id(), kind, t.namespace, t.node_name,
                     t.enclave, topic, mtype.typename, mtype.type_hash, qos.resolved())

    def declare_publisher(self, topic: str, mtype: MessageType, qos: QoS,
                          on_qos_event: QoSEventCallback | None = None) -> ZenohPublisher:
        """See :meth:`NodeHandle.declare_publisher`."""
        del on_qos_event  # rmw_zenoh raises no incompatible-QoS events
        pub = ZenohPublisher(self, topic, mtype, qos)
        self._children.append(pub)
        return pub

    def declare_subscription(self, topic: str, mtype: MessageType | None, qos: QoS, callback: SampleCallback,
                             on_qos_event: QoSEventCallback | None = None) -> Handle:
        """See :meth:`NodeHandle.declare_subscription`."""
        del on_qos_event
        sub = _ZenohSubscription(self, topic, mtype, qos, callback)
        self._children.append(sub)
        return sub

    def parameters(self) -> ParameterStore:
        """See :meth:`NodeHandle.parameters` (node-local)."""
        return self._params

    def declare_service(self, name: str, stype: ServiceType, on_request: RequestCallback) -> Handle:
        """See :meth:`NodeHandle.declare_service` (rmw_zenoh's queryable; :mod:`._zenoh_service`)."""
        from robotmodel.bus._zenoh_service import ZenohService

        service = ZenohService(self, name, stype, on_request)
        self._children.append(service)
        return service

    def declare_client(self, name: str, stype: ServiceType) -> ClientHandle:
        """See :meth:`NodeHandle.declare_client`."""
        from robotmodel.bus._zenoh_service import ZenohClient

        client = ZenohClient(self, name, stype)
        self._children.append(client)
        return client

    def close(self) -> None:
        """Undeclare the node's endpoints, then its token."""
        for child in reversed(self._children):
            child.close()
        self._children.clear()
        token, self._token = self._token, None
        if token is not None:
            token.close()


class ZenohPublisher(PublisherHandle):
    """A publisher: a zenoh publisher on the topic's key, its token, and the attachment per sample."""

    def __init__(self, node: ZenohNode, topic: str, mtype: MessageType, qos: QoS) -> None:
        session = node.backend.zenoh
        self.topic = topic
        self.token = node.entity_token(EntityKind.PUBLISHER, topic, mtype, qos)
        self.key = topic_keyexpr(node.backend.domain_id, topic, mtype.typename, mtype.type_hash)
        self._gid = self.token.gid
        self._attachment = AttachmentWriter(self._gid)
        self._lock = threading.Lock()
        self._seq = 1
        self.raw: RawPublisher | None = session.declare_publisher(self.key, qos)
        self._token: Handle | None = session.declare_token(self.token.keyexpr)

    @property
    def gid(self) -> bytes:
        """See :attr:`PublisherHandle.gid` (XXH3-128 of the token, as rmw_zenoh)."""
        return self._gid

    def publish(self, payload: bytes) -> None:
        """See :meth:`PublisherHandle.publish`."""
        with self._lock:
            raw = self.raw
            if raw is None:
                raise BusError(f"publisher on '{self.topic}' is closed")
            seq = self._seq
            self._seq = seq + 1
            raw.put(payload, self._attachment(seq, time.time_ns()))

    def matched(self) -> bool:
        """See :meth:`PublisherHandle.matched` (plain zenoh subscribers count too)."""
        with self._lock:
            raw = self.raw
        return raw is not None and raw.matched()

    def close(self) -> None:
        """Undeclare the publisher and its token."""
        with self._lock:
            raw, self.raw = self.raw, None
            token, self._token = self._token, None
        if raw is not None:
            raw.close()
        if token is not None:
            token.close()


class _ZenohSubscription(Handle):
    """A subscriber on the topic's key (any type's with ``mtype`` None) and, when typed, its token."""

    def __init__(self, node: ZenohNode, topic: str, mtype: MessageType | None, qos: QoS,
                 callback: SampleCallback) -> None:
        session = node.backend.zenoh
        domain = node.backend.domain_id
        self._topic = topic
        self._callback = callback
        self._typename = mtype.typename if mtype is not None else ""
        self._warner = Warner()
        self._token: Handle | None = None
        key = (topic_keyexpr(domain, topic, mtype.typename, mtype.type_hash) if mtype is not None
               else f"{domain}/{topic.strip('/')}/*/*")
        self._sub: Handle | None = session.declare_subscriber(key, qos, self._on_raw)
        if mtype is not None:
            # A type-agnostic echo is not an endpoint of one type, so it announces nothing.
            self._token = session.declare_token(node.entity_token(EntityKind.SUBSCRIPTION, topic, mtype, qos).keyexpr)

    def _on_raw(self, key: str, payload: bytes, attachment: bytes | None) -> None:
        typename = self._typename or self._typename_of(key)
        # The hot path, inlined: today's 33-byte form read in one unpack.
        if attachment is not None and len(attachment) >= ATTACHMENT_SIZE and \
                not attachment.startswith(LABELLED_PREFIX):
            seq, stamp, n, gid = unpack_attachment(attachment)
            if n == 16:
                self._callback(_new_sample((self._topic, typename, payload, _new_info((seq, stamp, gid, "")))))
                return
        fields = read_attachment(attachment)
        if fields is None:
            what = "without an attachment" if attachment is None else f"with a {len(attachment)}-byte attachment"
            self._warner.warn("attachment", f"dropped a message on '{self._topic}' {what} "
                                            "(rmw_zenoh's is 33 bytes)")
            return
        self._callback(_new_sample((self._topic, typename, payload, _new_info((*fields, "")))))

    @staticmethod
    def _typename_of(key: str) -> str:
        chunks = key.split("/")
        return ros_type_name(chunks[-2]) if len(chunks) >= 3 else ""

    def close(self) -> None:
        sub, self._sub = self._sub, None
        token, self._token = self._token, None
        if sub is not None:
            sub.close()
        if token is not None:
            token.close()
