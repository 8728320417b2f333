"""The ROS 1 wire: nodes of :mod:`robotmodel.ros1` on a master, TCPROS payloads, the master's graph.

Each node of the layer above is one ROS 1 node (:class:`robotmodel.ros1.Ros1Node`: its slave
API, TCPROS server and ``/rosout``), registered under its namespace and name; the session
is the master ``connect[0]`` names, else ``ROS_MASTER_URI`` (default
``http://localhost:11311``), reached from the address ROS 1 picks (``ROS_IP`` /
``ROS_HOSTNAME``). Payloads are ROS 1 serialization (:data:`ROS1`).

QoS in ROS 1 terms: transient local is ``latch=True`` (ROS 1 keeps the last message only,
and gives it to every new subscriber, volatile or not); the depth is the publisher's
``queue_size`` per subscriber (keep-all: unbounded); reliability has no counterpart (TCP
is reliable); no pair of endpoints is incompatible. A subscription of no type is rospy's
AnyMsg (md5sum ``*``) and names each sample's type from its publisher's connection header.

Samples carry no sequence number or stamp on ROS 1: :class:`SampleInfo` counts per
publisher on receipt and stamps the receive time; the GID is derived from the publisher's
caller id and the topic (:func:`ros1_gid`), as the graph's publisher entity gets it.

The graph is the master's: getSystemState and getTopicTypes, polled every
:data:`GRAPH_PERIOD_S` and right after this session changes its own registrations. Nodes
are caller ids split into namespace and name; endpoints carry the topic's type in ROS 2
form (``pkg/msg/Type``) and no QoS (the master has none). As ROS 1's master does, a killed
node stays registered until ``rosnode cleanup`` (this wire prunes nothing). Parameters are
the master's parameter server (:class:`Ros1Parameters`). A node told to shut down
(``rosnode kill``) unregisters and stops the tool running it as Ctrl-C would
(:func:`robotmodel.signals.request_stop`, what rospy's ``signal_shutdown`` is to rospy).
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Mapping, Sequence
from typing import Any

from robotmodel.bus._backend import (
    ROS1,
    Backend,
    GraphCallback,
    Handle,
    MessageType,
    NodeHandle,
    ParameterStore,
    PublisherHandle,
    QoSEventCallback,
    Sample,
    SampleCallback,
    SampleInfo,
)
from robotmodel.bus._book import NodeBook
from robotmodel.bus._qos import DEFAULT_DEPTH, History, QoS
from robotmodel.bus._ros1_graph import GRAPH_PERIOD_S, GraphPoller, GraphWatch, ros1_gid, ros2_type_name
from robotmodel.errors import BusError, MasterError

__all__ = ["GRAPH_PERIOD_S", "Ros1Backend", "Ros1Parameters", "ros1_gid"]

_log = logging.getLogger("robotmodel.bus")

# A keep-all publisher's per-subscriber queue: never drops in practice (rospy: queue_size=None).
_UNBOUNDED = 2**31 - 1


class Ros1Parameters(ParameterStore):
    """The master's parameter server as one node sees it (names resolved in its namespace, ``~`` private)."""

    def __init__(self, node: Any) -> None:
        self._node = node

    def _key(self, name: str) -> str:
        return str(self._node.resolve(name))

    def _relative(self, full: str) -> str:
        prefix = self._node.namespace.rstrip("/") + "/"
        return full[len(prefix):] if full.startswith(prefix) else full

    def get(self, name: str) -> Any:
        """See :meth:`ParameterStore.get` (getParam)."""
        try:
            return self._node.params.get_param(self._key(name))
        except MasterError as exc:
            if exc.code == -1:
                raise KeyError(name) from None
            raise

    def set(self, name: str, value: Any) -> None:
        """See :meth:`ParameterStore.set` (setParam: every node sees it)."""
        self._node.params.set_param(self._key(name), value)

    def has(self, name: str) -> bool:
        """See :meth:`ParameterStore.has` (hasParam)."""
        return bool(self._node.params.has_param(self._key(name)))

    def delete(self, name: str) -> None:
        """See :meth:`ParameterStore.delete` (deleteParam)."""
        try:
            self._node.params.delete_param(self._key(name))
        except MasterError as exc:
            if exc.code == -1:
                raise KeyError(name) from None
            raise

    def names(self) -> list[str]:
        """Every parameter on the server, relative to the node's namespace where under it, sorted."""
        return sorted(self._relative(n) for n in self._node.params.get_param_names())

    def search(self, name: str) -> str | None:
        """searchParam: ``name`` looked up the node's namespace, as ROS 1 does (None when not found)."""
        found = self._node.params.search_param(name)
        return None if found is None else self._relative(found)


class _Publisher(PublisherHandle):
    def __init__(self, node: Ros1NodeHandle, topic: str, mtype: MessageType, qos: QoS) -> None:
        q = qos.resolved()
        depth = _UNBOUNDED if q.history == History.KEEP_ALL else (q.depth or DEFAULT_DEPTH)
        self.topic = topic
        self._node = node
        self._pub: Any = node.ros1.advertise(topic, mtype.typename, latch=q.transient_local, queue_size=depth)
        self._gid = ros1_gid(node.ros1.name, topic)

    @property
    def gid(self) -> bytes:
        """See :attr:`PublisherHandle.gid` (:func:`ros1_gid` of the node and topic)."""
        return self._gid

    def publish(self, payload: bytes) -> None:
        """See :meth:`PublisherHandle.publish`."""
        pub = self._pub
        if pub is None:
            raise BusError(f"publisher on '{self.topic}' is closed")
        pub.publish_raw(payload)

    def matched(self) -> bool:
        """Whether a subscriber is connected over TCPROS now."""
        pub = self._pub
        return pub is not None and pub.subscriber_count > 0

    def close(self) -> None:
        """Unadvertise (the last handle on the topic unregisters it at the master)."""
        pub, self._pub = self._pub, None
        if pub is not None:
            pub.close()
            self._node.backend.graph_changed()


class _Subscription(Handle):
    def __init__(self, node: Ros1NodeHandle, topic: str, mtype: MessageType | None, callback: SampleCallback) -> None:
        self.topic = topic
        self._node = node
        self._callback = callback
        self._typename = mtype.typename if mtype is not None else ""
        self._counts: dict[str, int] = {}
        self._gids: dict[str, bytes] = {}
        # one sample at a time per subscription (each publisher has its own connection thread)
        self._serial = threading.Lock()
        self._open = True
        self._sub: Any = node.ros1.subscribe(topic, mtype.typename if mtype is not None else "*", self._on_data,
                                             raw=True, with_header=True, tcp_nodelay=True)

    def _on_data(self, data: bytes, header: Mapping[str, str]) -> None:
        callerid = header.get("callerid", "")
        with self._serial:
            if not self._open:
                return
            seq = self._counts[callerid] = self._counts.get(callerid, 0) + 1
            gid = self._gids.get(callerid)
            if gid is None:
                gid = self._gids[callerid] = ros1_gid(callerid, self.topic)
            typename = self._typename or ros2_type_name(header.get("type", ""))
            self._callback(Sample(self.topic, typename, data, SampleInfo(seq, time.time_ns(), gid, callerid)))

    def close(self) -> None:
        with self._serial:
            self._open = False
        sub, self._sub = self._sub, None
        if sub is not None:
            sub.close()
            self._node.backend.graph_changed()


class Ros1NodeHandle(NodeHandle):
    """One ROS 1 node on the backend's master."""

    def __init__(self, backend: Ros1Backend, name: str, namespace: str) -> None:
        from robotmodel.ros1 import Ros1Node

        self.backend = backend
        self.ros1 = Ros1Node(name, master_uri=backend.master_uri, namespace=namespace)
        self.ros1.on_shutdown = self._on_shutdown
        self._params = Ros1Parameters(self.ros1)
        self._children: list[Handle] = []
        self._closed = False

    def declare_publisher(self, topic: str, mtype: MessageType, qos: QoS,
                          on_qos_event: QoSEventCallback | None = None) -> PublisherHandle:
        """See :meth:`NodeHandle.declare_publisher` (ROS 1 has no QoS events)."""
        del on_qos_event
        pub = _Publisher(self, topic, mtype, qos)
        self._children.append(pub)
        self.backend.graph_changed()
        return pub

    def declare_subscription(self, topic: str, mtype: MessageType | None, qos: QoS, callback: SampleCallback,
                             on_qos_event: QoSEventCallback | None = None) -> Handle:
        """See :meth:`NodeHandle.declare_subscription`."""
        del on_qos_event, qos
        sub = _Subscription(self, topic, mtype, callback)
        self._children.append(sub)
        self.backend.graph_changed()
        return sub

    def parameters(self) -> ParameterStore:
        """The master's parameter server, seen from this node."""
        return self._params

    def _on_shutdown(self, reason: str) -> None:
        # As rospy's signal_shutdown: the tool running this node stops as on Ctrl-C.
        from robotmodel.signals import request_stop

        _log.warning("%s: %s; stopping", self.ros1.name, reason)
        self.backend.graph_changed()
        request_stop()

    @property
    def shutdown_requested(self) -> threading.Event:
        """Set when ``rosnode kill`` asked this node to stop."""
        return self.ros1.shutdown_requested

    def close(self) -> None:
        """Unregister everything at the master and stop the node's servers."""
        if self._closed:
            return
        self._closed = True
        for child in reversed(self._children):
            child.close()
        self._children.clear()
        self.ros1.close()
        self.backend.forget(self)


class Ros1Backend(Backend):
    """A session on a ROS 1 master (see the module docstring)."""

    name = "ros1"
    encoding = ROS1

    def __init__(self, domain_id: int, master_uri: str) -> None:
        super().__init__(domain_id)
        self.master_uri = master_uri
        self._nodes: NodeBook[Ros1NodeHandle] = NodeBook("ROS 1")
        self._poller = GraphPoller(self.master_uri)

    @classmethod
    def open(cls, domain_id: int, connect: Sequence[str] = ()) -> Ros1Backend:
        """A session on the master ``connect[0]`` (else ROS_MASTER_URI, else ``http://localhost:11311``).

        ROS 1 has no domains: ``domain_id`` is kept for the layer above and means nothing here.
        Raises :class:`robotmodel.errors.MasterError` naming the master when it does not answer.
        """
        from robotmodel.ros1 import MasterClient, master_uri_from_env

        uri = connect[0] if connect else master_uri_from_env()
        MasterClient(uri, "/robotmodel").get_uri()
        return cls(domain_id, uri)

    def create_node(self, name: str, namespace: str, enclave: str = "/") -> NodeHandle:
        """See :meth:`Backend.create_node` (ROS 1 has no enclaves)."""
        del enclave
        node = self._nodes.add(lambda: Ros1NodeHandle(self, name, namespace))
        self.graph_changed()
        return node

    def forget(self, node: Ros1NodeHandle) -> None:
        """A node closed: drop it from the session."""
        self._nodes.forget(node)
        self.graph_changed()

    def graph_changed(self) -> None:
        """Poll the master now rather than at the next period (this session changed its registrations)."""
        self._poller.wake()

    def watch_graph(self, callback: GraphCallback) -> Handle:
        """See :meth:`Backend.watch_graph` (the master's graph, polled)."""
        self._poller.add(callback)
        return GraphWatch(self._poller, callback)

    def qos_incompatibility(self, publisher: QoS, subscription: QoS) -> str:
        """ROS 1 has no QoS: every pair matches."""
        del publisher, subscription
        return ""

    def close(self) -> None:
        """Close every node (unregistering all at the master), then stop following the graph."""
        nodes = self._nodes.close()
        if nodes is None:
            return
        for node in nodes:
            node.close()
        self._poller.close()
