"""A ROS 1 node: master registration, the slave API, TCPROS publishers and subscribers, parameters.

:class:`Ros1Node` ties the pieces of this package together the way a rospy node does: it
serves the slave API and TCPROS on the address ROS 1 would pick (see :mod:`._address`),
registers each topic it publishes or subscribes to with the master, follows publisherUpdate,
honours ``shutdown`` (``rosnode kill``), and on :meth:`Ros1Node.close` unregisters everything so
the master keeps no stale registration. Like every rospy node it publishes ``/rosout``, which
is also what makes ``rosnode list`` show it.
"""

from __future__ import annotations

import logging
import os
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from robotmodel.errors import MasterError, Ros1Error
from robotmodel.ros1._address import node_address
from robotmodel.ros1._master import DEFAULT_MASTER_URI, MasterClient, ParamClient
from robotmodel.ros1._msgs import Ros1Type, deserialize, message_type, serialize
from robotmodel.ros1._publisher import Publication, TcprosServer
from robotmodel.ros1._slave import SlaveServer
from robotmodel.ros1._subscriber import Subscription

__all__ = ["ParamCallback", "Ros1Node", "Ros1Publisher", "Ros1Subscriber", "resolve_name"]

_log = logging.getLogger("robotmodel.ros1")

#: Called with a subscribed parameter's name and new value on paramUpdate.
ParamCallback = Callable[[str, Any], None]


def _join(namespace: str, name: str) -> str:
    return (namespace.rstrip("/") + "/" + name.strip("/")) if name.strip("/") else (namespace or "/")


def resolve_name(name: str, namespace: str, node_name: str) -> str:
    """ROS 1's resolution of a graph name: ``/x`` stays, ``~x`` is under the node, ``x`` under the namespace."""
    if not name:
        raise Ros1Error("empty graph name")
    if name.startswith("/"):
        resolved = name
    elif name.startswith("~"):
        resolved = _join(node_name, name[1:])
    else:
        resolved = _join(namespace if namespace.startswith("/") else "/" + namespace, name)
    return "/" + "/".join(part for part in resolved.split("/") if part)


class Ros1Publisher:
    """A handle on a topic the node publishes; :meth:`publish` takes a rosbags message of the type."""

    def __init__(self, node: Ros1Node, publication: Publication) -> None:
        self._node = node
        self._publication = publication
        self.topic = publication.topic
        self.type: Ros1Type = publication.type

    def publish(self, message: Any) -> None:
        """Serialize ``message`` and send it to every subscriber.

        After :meth:`close` this raises :class:`Ros1Error`; after the node shut down (``rosnode
        kill`` may come between a loop's check and its publish) it does nothing, as roscpp does.
        """
        self.publish_raw(serialize(message, self.type.name))

    def publish_raw(self, data: bytes) -> None:
        """Send already serialized ROS 1 bytes (see :meth:`publish`)."""
        try:
            self._publication.publish(data)
        except Ros1Error:
            if not self._node.is_shutdown:
                raise

    @property
    def subscriber_count(self) -> int:
        """TCPROS subscribers connected now."""
        return self._publication.subscriber_count

    def close(self) -> None:
        """Stop publishing; the last handle on a topic unregisters it at the master."""
        self._node._release_publication(self.topic, self)


class Ros1Subscriber:
    """A handle on a subscription; its callback gets each message (or its bytes when ``raw``)."""

    def __init__(self, node: Ros1Node, subscription: Subscription, callback: Callable[..., None],
                 raw: bool, with_header: bool = False) -> None:
        self._node = node
        self.subscription = subscription
        self.topic = subscription.topic
        self.type: Ros1Type = subscription.type
        self.callback = callback
        self.raw = raw
        self.with_header = with_header

    def deliver(self, data: bytes, header: Mapping[str, str]) -> None:
        """Hand ``data`` to the callback, decoded unless raw (with the publisher's header when asked)."""
        if self.with_header:
            self.callback(data, header)
        else:
            self.callback(data if self.raw else deserialize(data, self.type.name))

    @property
    def publisher_uris(self) -> list[str]:
        """Slave URIs of the publishers connected now."""
        return self.subscription.publisher_uris

    def close(self) -> None:
        """Stop receiving; the last handle on a topic unregisters it at the master."""
        self._node._release_subscription(self.topic, self)


class Ros1Node:
    """A ROS 1 node named ``name`` (resolved in ``namespace``) on the master ``master_uri``.

    ``master_uri`` defaults to ROS_MASTER_URI (else ``http://localhost:11311``), ``namespace``
    to ROS_NAMESPACE (else ``/``). ``args`` may carry ``__hostname:=``/``__ip:=``; ``bind_all``
    binds every interface instead of the advertised address only.
    """

    def __init__(self, name: str, *, master_uri: str | None = None, namespace: str | None = None,
                 args: Sequence[str] = (), env: Mapping[str, str] | None = None, bind_all: bool = False,
                 rosout: bool = True) -> None:
        env = os.environ if env is None else env
        self.master_uri = master_uri or env.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI
        self.namespace = resolve_name(namespace or env.get("ROS_NAMESPACE") or "/", "/", "/")
        self.name = resolve_name(name, self.namespace, "/")
        address = node_address(self.master_uri, args=args, env=env, bind_all=bind_all)
        self.host = address.host
        self.master = MasterClient(self.master_uri, self.name)
        self.params = ParamClient(self.master_uri, self.name)
        self._lock = threading.RLock()
        self._publications: dict[str, tuple[Publication, list[Ros1Publisher]]] = {}
        self._subscriptions: dict[str, tuple[Subscription, list[Ros1Subscriber]]] = {}
        self._param_callbacks: dict[str, list[ParamCallback]] = {}
        self._closed = False
        self._close_done = threading.Event()
        self.shutdown_requested = threading.Event()
        self.shutdown_reason = ""
        #: Called (with the reason) on a ``shutdown`` request, after the node closed.
        self.on_shutdown: Callable[[str], None] | None = None
        self._tcpros = TcprosServer(self._publication, host=address.host, bind=address.bind, callerid=self.name,
                                    topics=self._publication_list)
        self._slave = SlaveServer(self._handlers(), host=address.host, bind=address.bind)
        self.uri = self._slave.uri
        try:
            self.master.get_uri()  # fail here, naming the master, rather than on the first advertise
            self.rosout = self.advertise("/rosout", "rosgraph_msgs/Log") if rosout else None
        except BaseException:
            self._stop_servers()
            raise

    def resolve(self, name: str) -> str:
        """``name`` resolved against this node's namespace and name."""
        return resolve_name(name, self.namespace, self.name)

    # -- topics -------------------------------------------------------------------------------

    def advertise(self, topic: str, typename: str, *, latch: bool = False, queue_size: int = 100) -> Ros1Publisher:
        """Publish ``topic`` as ``typename`` (registered at the master on the first handle)."""
        resolved = self.resolve(topic)
        msg_type = message_type(typename)
        with self._lock:
            self._check_open()
            entry = self._publications.get(resolved)
            if entry is not None:
                if entry[0].type != msg_type:
                    raise Ros1Error(f"{self.name} already publishes {resolved} as {entry[0].type.name}, "
                                    f"not {msg_type.name}")
                handle = Ros1Publisher(self, entry[0])
                entry[1].append(handle)
                return handle
            publication = Publication(resolved, msg_type, self.name, latch=latch, queue_size=queue_size)
            handle = Ros1Publisher(self, publication)
            self._publications[resolved] = (publication, [handle])
        try:
            self.master.register_publisher(resolved, msg_type.name, self.uri)
        except MasterError:
            with self._lock:
                self._publications.pop(resolved, None)
            raise
        return handle

    def subscribe(self, topic: str, typename: str, callback: Callable[..., None], *, raw: bool = False,
                  tcp_nodelay: bool = False, with_header: bool = False) -> Ros1Subscriber:
        """Receive ``topic`` as ``typename``; ``callback`` gets rosbags messages, or bytes when ``raw``.

        With ``with_header`` it gets ``(bytes, publisher's connection header)``. ``typename``
        ``"*"`` takes any type (rospy's AnyMsg; raw only): the header names each publisher's.
        """
        resolved = self.resolve(topic)
        msg_type = message_type(typename)
        with self._lock:
            self._check_open()
            entry = self._subscriptions.get(resolved)
            if entry is not None:
                if entry[0].type != msg_type:
                    raise Ros1Error(f"{self.name} already subscribes to {resolved} as {entry[0].type.name}, "
                                    f"not {msg_type.name}")
                handle = Ros1Subscriber(self, entry[0], callback, raw, with_header)
                entry[1].append(handle)
                return handle
            handles: list[Ros1Subscriber] = []

            def fan_out(data: bytes, header: Mapping[str, str]) -> None:
                for each in list(handles):
                    each.deliver(data, header)

            subscription = Subscription(resolved, msg_type, self.name, fan_out, tcp_nodelay=tcp_nodelay)
            handle = Ros1Subscriber(self, subscription, callback, raw, with_header)
            handles.append(handle)
            self._subscriptions[resolved] = (subscription, handles)
        try:
            publishers = self.master.register_subscriber(resolved, msg_type.name, self.uri)
        except MasterError:
            with self._lock:
                self._subscriptions.pop(resolved, None)
            raise
        subscription.update_publishers(publishers)
        return handle

    def _release_publication(self, topic: str, handle: Ros1Publisher) -> None:
        with self._lock:
            entry = self._publications.get(topic)
            if entry is None or handle not in entry[1]:
                return
            entry[1].remove(handle)
            if entry[1]:
                return
            del self._publications[topic]
        entry[0].close()
        self._unregister("unregisterPublisher", topic)

    def _release_subscription(self, topic: str, handle: Ros1Subscriber) -> None:
        with self._lock:
            entry = self._subscriptions.get(topic)
            if entry is None or handle not in entry[1]:
                return
            entry[1].remove(handle)
            if entry[1]:
                return
            del self._subscriptions[topic]
        self._unregister("unregisterSubscriber", topic)
        entry[0].close()

    def _unregister(self, method: str, key: str) -> None:
        try:
            if method == "unsubscribeParam":
                self.params.unsubscribe_param(key, self.uri)
            else:
                self.master.call(method, key, self.uri)
        except MasterError as exc:
            _log.warning("%s: %s", self.name, exc)

    # -- parameters ---------------------------------------------------------------------------

    def subscribe_param(self, key: str, callback: ParamCallback) -> Any:
        """subscribeParam: the current value ({} when unset); ``callback(key, value)`` on each paramUpdate."""
        resolved = self.resolve(key)
        with self._lock:
            self._check_open()
            first = resolved not in self._param_callbacks
            self._param_callbacks.setdefault(resolved, []).append(callback)
        if first:
            try:
                return self.params.subscribe_param(resolved, self.uri)
            except MasterError:
                with self._lock:
                    self._param_callbacks.pop(resolved, None)
                raise
        return self.params.get_param(resolved) if self.params.has_param(resolved) else {}

    def unsubscribe_param(self, key: str) -> None:
        """unsubscribeParam: no more callbacks for ``key``."""
        resolved = self.resolve(key)
        with self._lock:
            if self._param_callbacks.pop(resolved, None) is None:
                return
        self._unregister("unsubscribeParam", resolved)

    # -- the slave API ------------------------------------------------------------------------

    def _publication(self, topic: str) -> Publication | None:
        with self._lock:
            entry = self._publications.get(topic)
            return entry[0] if entry else None

    def _publication_list(self) -> list[list[str]]:
        with self._lock:
            return [[topic, pub.type.name] for topic, (pub, _) in self._publications.items()]

    def _handlers(self) -> dict[str, Callable[..., list[Any]]]:
        def request_topic(caller_id: str, topic: str, protocols: list[Any]) -> list[Any]:
            if self._publication(topic) is None:
                return [-1, f"Not a publisher of [{topic}]", []]
            if not isinstance(protocols, list) or not any(isinstance(p, list) and p[:1] == ["TCPROS"]
                                                          for p in protocols):
                return [0, "no supported protocol implementations", []]
            return [1, f"ready on {self.host}:{self._tcpros.port}", ["TCPROS", self.host, self._tcpros.port]]

        def publisher_update(caller_id: str, topic: str, publishers: list[str]) -> list[Any]:
            if not isinstance(publishers, list) or not all(isinstance(p, str) for p in publishers):
                return [-1, "ERROR: param [publishers] must be a list of strings", 0]
            with self._lock:
                entry = self._subscriptions.get(topic)
            if entry is not None:
                entry[0].update_publishers(publishers)
            return [1, "", 0]

        def bus_info(caller_id: str) -> list[Any]:
            with self._lock:
                pubs = [p for p, _ in self._publications.values()]
                subs = [s for s, _ in self._subscriptions.values()]
            rows = [row for p in pubs for row in p.bus_info()] + [row for s in subs for row in s.bus_info()]
            return [1, "bus info", rows]

        def bus_stats(caller_id: str) -> list[Any]:
            with self._lock:
                pubs = [p for p, _ in self._publications.values()]
                subs = [s for s, _ in self._subscriptions.values()]
            return [1, "", [[p.bus_stats() for p in pubs], [s.bus_stats() for s in subs], []]]

        def subscriptions(caller_id: str) -> list[Any]:
            with self._lock:
                return [1, "subscriptions", [[t, s.type.name] for t, (s, _) in self._subscriptions.items()]]

        def shutdown(caller_id: str, msg: str = "") -> list[Any]:
            _log.warning("%s: shutdown request from [%s]: %s", self.name, caller_id, msg)
            self.shutdown_reason = f"external shutdown request from [{caller_id}]: {msg}"
            self.shutdown_requested.set()

            def close_then_tell() -> None:
                self.close()
                if self.on_shutdown is not None:
                    self.on_shutdown(self.shutdown_reason)

            # close after this call has answered: closing stops the server answering it
            threading.Thread(target=close_then_tell, name="ros1-shutdown", daemon=True).start()
            return [1, "shutdown", 0]

        def param_update(caller_id: str, key: str, value: Any) -> list[Any]:
            name = "/" + key.strip("/")
            with self._lock:
                targets = [(k, list(cbs)) for k, cbs in self._param_callbacks.items()
                           if name == k or name.startswith(k.rstrip("/") + "/") or k.startswith(name + "/")]
            if not targets:
                return [-1, "not subscribed", 0]
            for _, callbacks in targets:
                for callback in callbacks:
                    callback(name, value)
            return [1, "", 0]

        return {
            "requestTopic": request_topic,
            "publisherUpdate": publisher_update,
            "getBusInfo": bus_info,
            "getBusStats": bus_stats,
            "getPid": lambda caller_id: [1, "", os.getpid()],
            "getMasterUri": lambda caller_id: [1, self.master_uri, self.master_uri],
            "getSubscriptions": subscriptions,
            "getPublications": lambda caller_id: [1, "publications", self._publication_list()],
            "shutdown": shutdown,
            "paramUpdate": param_update,
        }

    # -- life cycle ---------------------------------------------------------------------------

    def _check_open(self) -> None:
        if self._closed:
            raise Ros1Error(f"node {self.name} is shut down")

    @property
    def is_shutdown(self) -> bool:
        """True once the node was closed (by :meth:`close` or a ``shutdown`` call)."""
        return self._closed

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until ``rosnode kill`` (the slave API's shutdown) asks this node to stop."""
        return self.shutdown_requested.wait(timeout)

    def close(self) -> None:
        """Unregister every topic and parameter subscription at the master, then stop serving.

        Returns once that is done, also when another thread (a ``shutdown`` call) closes the node.
        """
        with self._lock:
            if self._closed:
                closing_elsewhere = True
            else:
                closing_elsewhere = False
                self._closed = True
        if closing_elsewhere:
            self._close_done.wait(30)
            return
        try:
            self._close()
        finally:
            self._close_done.set()

    def _close(self) -> None:
        with self._lock:
            pubs, self._publications = self._publications, {}
            subs, self._subscriptions = self._subscriptions, {}
            params, self._param_callbacks = self._param_callbacks, {}
        for topic, (publication, _) in pubs.items():
            self._unregister("unregisterPublisher", topic)
            publication.close()
        for topic, (subscription, _) in subs.items():
            self._unregister("unregisterSubscriber", topic)
            subscription.close()
        for key in params:
            self._unregister("unsubscribeParam", key)
        self._stop_servers()

    def _stop_servers(self) -> None:
        self._tcpros.close()
        self._slave.close()

    def __enter__(self) -> Ros1Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
