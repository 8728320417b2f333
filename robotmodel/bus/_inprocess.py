"""The in-process wire: every session of this process shares one local bus, no sockets.

It keeps the backend contract as a stock ROS 2 (DDS) graph would: endpoints of one topic,
type and domain match when rmw_dds_common's rules say their QoS do (else both get an
incompatible-QoS event and exchange nothing); transient-local publishers keep their last
``depth`` samples for transient-local subscriptions that come later. Each sample is
delivered synchronously in the publishing thread, one at a time per subscription.
Closing a session withdraws its nodes from the graph (what a killed process is here).
A request goes to the first server of the name and type in the domain, synchronously in the
requesting thread; its response goes to the client whenever the server responds.
"""

from __future__ import annotations

import itertools
import secrets
import threading
import time
from collections import deque
from collections.abc import Callable, Sequence

from robotmodel.bus._backend import (
    CDR,
    Backend,
    ClientHandle,
    Entity,
    EntityKind,
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
    RequestId,
    ResponseCallback,
    Sample,
    SampleCallback,
    SampleInfo,
    ServiceType,
)
from robotmodel.bus._book import NodeBook, OnClose
from robotmodel.bus._qos import QoS, incompatible_policy
from robotmodel.errors import BusError

__all__ = ["InProcessBackend"]


class _Endpoint:
    """What publishers and subscriptions share: where they are, their QoS, their event count."""

    def __init__(self, domain: int, topic: str, typename: str | None, qos: QoS,
                 on_qos_event: QoSEventCallback | None) -> None:
        self.domain = domain
        self.topic = topic
        self.typename = typename
        self.qos = qos.resolved()
        self.on_qos_event = on_qos_event
        self.incompatible = 0

    def event(self, policy: str) -> Callable[[], None] | None:
        # Counted under the bus lock; the callback runs after it is released.
        self.incompatible += 1
        cb, total = self.on_qos_event, self.incompatible
        return None if cb is None else (lambda: cb(QoSEvent(total, 1, policy, self.topic)))


class _Pub(_Endpoint):
    def __init__(self, domain: int, topic: str, typename: str, qos: QoS, gid: bytes,
                 on_qos_event: QoSEventCallback | None) -> None:
        super().__init__(domain, topic, typename, qos, on_qos_event)
        self.gid = gid
        self.cache: deque[Sample] | None = deque(maxlen=self.qos.depth) if self.qos.transient_local else None
        self.seq = 0
        self.targets: list[_Sub] = []


class _Sub(_Endpoint):
    def __init__(self, domain: int, topic: str, typename: str | None, qos: QoS, callback: SampleCallback,
                 on_qos_event: QoSEventCallback | None) -> None:
        super().__init__(domain, topic, typename, qos, on_qos_event)
        self.callback = callback
        # One sample at a time per subscription, as the contract says; re-entrant so that a
        # callback may publish on its own topic.
        self.serial = threading.RLock()
        self.open = True

    def deliver(self, sample: Sample) -> None:
        with self.serial:
            if self.open:
                self.callback(sample)


def _meet(pub: _Pub, sub: _Sub) -> str | None:
    """None: not on one topic; '': they match; else the incompatible policy."""
    if pub.domain != sub.domain or pub.topic != sub.topic or sub.typename not in (None, pub.typename):
        return None
    return incompatible_policy(pub.qos, sub.qos)


class _LocalBus:
    """State shared by all in-process sessions (guarded by one re-entrant lock)."""

    def __init__(self) -> None:
        self.lock = threading.RLock()
        self.pubs: list[_Pub] = []
        self.subs: list[_Sub] = []
        self.services: list[tuple[int, str, str, RequestCallback]] = []
        self.entities: dict[tuple[int, str], Entity] = {}
        self.watchers: list[tuple[int, GraphCallback]] = []

    def announce(self, domain: int, key: str, entity: Entity | None) -> None:
        """Add (or with None remove) an entity and tell the domain's watchers, in order, under the lock."""
        with self.lock:
            if entity is None:
                if self.entities.pop((domain, key), None) is None:
                    return
            else:
                self.entities[(domain, key)] = entity
            for watcher_domain, callback in list(self.watchers):
                if watcher_domain == domain:
                    callback(key, entity)


_BUS = _LocalBus()
_SESSIONS = itertools.count()


class InProcessBackend(Backend):
    """A session on this process's local bus."""

    name = "inprocess"
    encoding = CDR

    def __init__(self, domain_id: int) -> None:
        super().__init__(domain_id)
        self.session_id = f"inprocess{next(_SESSIONS)}"
        self._bus = _BUS
        self._ids = itertools.count()
        self._nodes: NodeBook[_LocalNode] = NodeBook("in-process")
        self._watches: list[Handle] = []
        self._lock = threading.Lock()

    @classmethod
    def open(cls, domain_id: int, connect: Sequence[str] = ()) -> InProcessBackend:
        """See :meth:`Backend.open` (``connect`` has no meaning here and is ignored)."""
        del connect
        return cls(domain_id)

    def next_key(self) -> str:
        """A key for a new entity of this session."""
        with self._lock:
            return f"{self.session_id}/{next(self._ids)}"

    def create_node(self, name: str, namespace: str, enclave: str = "/") -> NodeHandle:
        """See :meth:`Backend.create_node`."""
        return self._nodes.add(lambda: _LocalNode(self, name, namespace, enclave))

    def forget(self, node: _LocalNode) -> None:
        """Drop a closed node from the session's list."""
        self._nodes.forget(node)

    def watch_graph(self, callback: GraphCallback) -> Handle:
        """See :meth:`Backend.watch_graph`."""
        bus = self._bus
        entry = (self.domain_id, callback)
        with bus.lock:
            for (domain, key), entity in list(bus.entities.items()):
                if domain == self.domain_id:
                    callback(key, entity)
            bus.watchers.append(entry)

        def remove() -> None:
            with bus.lock:
                if entry in bus.watchers:
                    bus.watchers.remove(entry)

        handle = OnClose(remove)
        with self._lock:
            self._watches.append(handle)
        return handle

    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """See :meth:`Backend.qos_incompatibility`: rmw_dds_common's rules, as a stock ROS 2 graph."""
        return incompatible_policy(publisher, subscription)

    def close(self) -> None:
        """See :meth:`Backend.close`."""
        nodes = self._nodes.close()
        if nodes is None:
            return
        with self._lock:
            watches, self._watches = self._watches, []
        for node in nodes:
            node.close()
        for watch in watches:
            watch.close()


class _LocalNode(NodeHandle):
    def __init__(self, backend: InProcessBackend, name: str, namespace: str, enclave: str) -> None:
        self.backend = backend
        self.key = backend.next_key()
        self.entity = Entity(EntityKind.NODE, name, namespace, enclave, node_key=self.key)
        self._children: list[Handle] = []
        self._params = LocalParameters()
        self._closed = False
        backend._bus.announce(backend.domain_id, self.key, self.entity)

    def _endpoint_entity(self, kind: EntityKind, topic: str, mtype: MessageType, qos: QoS, gid: bytes) -> Entity:
        n = self.entity
        return Entity(kind, n.node_name, n.namespace, n.enclave, topic, mtype.typename, mtype.type_hash,
                      qos.resolved(), gid, self.key)

    def declare_publisher(self, topic: str, mtype: MessageType, qos: QoS,
                          on_qos_event: QoSEventCallback | None = None) -> PublisherHandle:
        """See :meth:`NodeHandle.declare_publisher`."""
        backend, bus = self.backend, self.backend._bus
        pub = _Pub(backend.domain_id, topic, mtype.typename, qos, secrets.token_bytes(16), on_qos_event)
        key = backend.next_key()
        events: list[Callable[[], None] | None] = []
        with bus.lock:
            for sub in bus.subs:
                verdict = _meet(pub, sub)
                if verdict == "":
                    pub.targets.append(sub)
                elif verdict:
                    events += [pub.event(verdict), sub.event(verdict)]
            bus.pubs.append(pub)
            bus.announce(backend.domain_id, key, self._endpoint_entity(EntityKind.PUBLISHER, topic, mtype, qos,
                                                                       pub.gid))
        _fire(events)

        def remove() -> None:
            with bus.lock:
                if pub in bus.pubs:
                    bus.pubs.remove(pub)
                pub.targets = []
                bus.announce(backend.domain_id, key, None)

        handle = _LocalPublisher(bus, pub, remove)
        self._children.append(handle)
        return handle

    def declare_subscription(self, topic: str, mtype: MessageType | None, qos: QoS, callback: SampleCallback,
                             on_qos_event: QoSEventCallback | None = None) -> Handle:
        """See :meth:`NodeHandle.declare_subscription`."""
        backend, bus = self.backend, self.backend._bus
        sub = _Sub(backend.domain_id, topic, None if mtype is None else mtype.typename, qos, callback, on_qos_event)
        key = backend.next_key()
        events: list[Callable[[], None] | None] = []
        history: list[Sample] = []
        with bus.lock:
            for pub in bus.pubs:
                verdict = _meet(pub, sub)
                if verdict == "":
                    pub.targets.append(sub)
                    if pub.cache is not None and sub.qos.transient_local:
                        history.extend(list(pub.cache)[-sub.qos.depth:])
                elif verdict:
                    events += [pub.event(verdict), sub.event(verdict)]
            bus.subs.append(sub)
            if mtype is not None:
                # A type-agnostic echo is not an endpoint of one type, so it announces nothing.
                bus.announce(backend.domain_id, key,
                             self._endpoint_entity(EntityKind.SUBSCRIPTION, topic, mtype, qos, b""))
            # Held until the history is delivered, so no newer sample overtakes it.
            sub.serial.acquire()
        try:
            _fire(events)
            for sample in history:
                sub.deliver(sample)
        finally:
            sub.serial.release()

        def remove() -> None:
            with bus.lock:
                sub.open = False
                if sub in bus.subs:
                    bus.subs.remove(sub)
                for pub in bus.pubs:
                    if sub in pub.targets:
                        pub.targets.remove(sub)
                if mtype is not None:
                    bus.announce(backend.domain_id, key, None)

        handle = OnClose(remove)
        self._children.append(handle)
        return handle

    def parameters(self) -> ParameterStore:
        """See :meth:`NodeHandle.parameters` (node-local)."""
        return self._params

    def _service_entity(self, kind: EntityKind, name: str, stype: ServiceType, gid: bytes) -> Entity:
        n = self.entity
        return Entity(kind, n.node_name, n.namespace, n.enclave, name, stype.typename, stype.type_hash,
                      None, gid, self.key)

    def declare_service(self, name: str, stype: ServiceType, on_request: RequestCallback) -> Handle:
        """See :meth:`NodeHandle.declare_service`."""
        backend, bus = self.backend, self.backend._bus
        entry = (backend.domain_id, name, stype.typename, on_request)
        key = backend.next_key()
        with bus.lock:
            bus.services.append(entry)
            bus.announce(backend.domain_id, key,
                         self._service_entity(EntityKind.SERVICE, name, stype, secrets.token_bytes(16)))

        def remove() -> None:
            with bus.lock:
                if entry in bus.services:
                    bus.services.remove(entry)
                bus.announce(backend.domain_id, key, None)

        handle = OnClose(remove)
        self._children.append(handle)
        return handle

    def declare_client(self, name: str, stype: ServiceType) -> ClientHandle:
        """See :meth:`NodeHandle.declare_client`."""
        client = _LocalClient(self, name, stype)
        self._children.append(client)
        return client

    def close(self) -> None:
        """Withdraw the node's endpoints, then the node."""
        if self._closed:
            return
        self._closed = True
        for child in reversed(self._children):
            child.close()
        self._children.clear()
        self.backend._bus.announce(self.backend.domain_id, self.key, None)
        self.backend.forget(self)


def _fire(events: list[Callable[[], None] | None]) -> None:
    for event in events:
        if event is not None:
            event()


class _LocalPublisher(PublisherHandle):
    def __init__(self, bus: _LocalBus, pub: _Pub, remove: Callable[[], None]) -> None:
        self._bus = bus
        self._pub: _Pub | None = pub
        self._remove = remove

    @property
    def gid(self) -> bytes:
        """See :attr:`PublisherHandle.gid`."""
        pub = self._pub
        return b"" if pub is None else pub.gid

    def publish(self, payload: bytes) -> None:
        """See :meth:`PublisherHandle.publish`."""
        pub = self._pub
        if pub is None:
            raise BusError("publisher is closed")
        with self._bus.lock:
            pub.seq += 1
            sample = Sample(pub.topic, pub.typename or "", bytes(payload), SampleInfo(pub.seq, time.time_ns(), pub.gid))
            if pub.cache is not None:
                pub.cache.append(sample)
            targets = list(pub.targets)
        for sub in targets:
            sub.deliver(sample)

    def matched(self) -> bool:
        """See :meth:`PublisherHandle.matched`."""
        pub = self._pub
        with self._bus.lock:
            return pub is not None and bool(pub.targets)

    def close(self) -> None:
        """Withdraw the publisher."""
        pub, self._pub = self._pub, None
        if pub is not None:
            self._remove()


class _LocalClient(ClientHandle):
    def __init__(self, node: _LocalNode, name: str, stype: ServiceType) -> None:
        backend = node.backend
        self._bus = backend._bus
        self._domain = backend.domain_id
        self._name = name
        self._typename = stype.typename
        self._gid = secrets.token_bytes(16)
        self._seq = itertools.count(1)
        self._key = backend.next_key()
        self._open = True
        self._bus.announce(self._domain, self._key,
                           node._service_entity(EntityKind.CLIENT, name, stype, self._gid))

    @property
    def gid(self) -> bytes:
        """See :attr:`ClientHandle.gid`."""
        return self._gid

    def _server(self) -> RequestCallback | None:
        with self._bus.lock:
            for domain, name, typename, on_request in self._bus.services:
                if (domain, name, typename) == (self._domain, self._name, self._typename):
                    return on_request
        return None

    def request(self, payload: bytes, on_response: ResponseCallback) -> int:
        """See :meth:`ClientHandle.request` (no server: the request is lost, as on a real wire)."""
        if not self._open:
            raise BusError(f"client of '{self._name}' is closed")
        seq = next(self._seq)
        server = self._server()
        answered = threading.Event()

        def respond(response: bytes) -> None:
            if self._open and not answered.is_set():
                answered.set()
                on_response(bytes(response))

        if server is not None:
            server(bytes(payload), RequestId(self._gid, seq), respond)
        return seq

    def server_ready(self) -> bool:
        """See :meth:`ClientHandle.server_ready`."""
        return self._server() is not None

    def close(self) -> None:
        """Withdraw the client; responses still to come are dropped."""
        if self._open:
            self._open = False
            self._bus.announce(self._domain, self._key, None)
