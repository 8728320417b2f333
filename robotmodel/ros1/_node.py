"""A ROS 1 node: master registration, the slave API, TCPROS publishers and subscribers, parameters.

:class:`Ros1Node` ties the pieces of this package together the way a rospy node does: it
serves the slave API and TCPROS on the address ROS 1 would pick (see :mod:`._address`),
registers each topic it publishes or subscribes to with the master, follows publisherUpdate,
honours ``shutdown`` (``rosnode kill``), and on :meth:`Ros1Node.close` unregisters everything so
the master keeps no stale registration. Like every rospy node it publishes ``/rosout``, which
is also what makes ``rosnode list`` show it. Unlike rospy's, it registers everything again with
a master that restarted (:mod:`._keepalive`). The slave API's handlers are in :mod:`._api`,
the handles it gives out in :mod:`._handles`, name resolution in :mod:`._names`.
"""

from __future__ import annotations

import logging
import os
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from robotmodel.errors import MasterError, Ros1Error
from robotmodel.ros1._address import node_address
from robotmodel.ros1._api import slave_handlers
from robotmodel.ros1._handles import Ros1Publisher, Ros1Subscriber
from robotmodel.ros1._keepalive import MasterKeepalive
from robotmodel.ros1._master import DEFAULT_MASTER_URI, MasterClient, ParamClient
from robotmodel.ros1._msgs import message_type
from robotmodel.ros1._names import resolve_name
from robotmodel.ros1._publisher import Publication, TcprosServer
from robotmodel.ros1._slave import SlaveServer
from robotmodel.ros1._subscriber import Subscription

__all__ = ["ParamCallback", "Ros1Node"]

_log = logging.getLogger("robotmodel.ros1")

#: Called with a subscribed parameter's name and new value on paramUpdate.
ParamCallback = Callable[[str, Any], None]


class Ros1Node:
    """A ROS 1 node named ``name`` (resolved in ``namespace``) on the master ``master_uri``.

    ``master_uri`` defaults to ROS_MASTER_URI (else ``http://localhost:11311``), ``namespace``
    to ROS_NAMESPACE (else ``/``). ``args`` may carry ``__hostname:=``/``__ip:=``; ``bind_all``
    binds every interface instead of the advertised address only. ``keepalive`` registers the
    node again with a master that restarted (:mod:`._keepalive`); ``rosout`` publishes ``/rosout``.
    """

    def __init__(self, name: str, *, master_uri: str | None = None, namespace: str | None = None,
                 args: Sequence[str] = (), env: Mapping[str, str] | None = None, bind_all: bool = False,
                 rosout: bool = True, keepalive: bool = True) -> None:
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
        self._tcpros = TcprosServer(self.publication, host=address.host, bind=address.bind, callerid=self.name,
                                    topics=self.publication_list)
        self._slave = SlaveServer(slave_handlers(self), host=address.host, bind=address.bind)
        self.uri = self._slave.uri
        self._keepalive: MasterKeepalive | None = None
        try:
            self.master.get_uri()  # fail here, naming the master, rather than on the first advertise
            self.rosout = self.advertise("/rosout", "rosgraph_msgs/Log") if rosout else None
        except BaseException:
            self._stop_servers()
            raise
        self._keepalive = MasterKeepalive(self) if keepalive else None

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

    # -- what the slave API and the keepalive read ---------------------------------------------

    @property
    def tcpros_port(self) -> int:
        """The port of this node's TCPROS server."""
        return self._tcpros.port

    def publication(self, topic: str) -> Publication | None:
        """The publication of ``topic`` (None: this node does not publish it)."""
        with self._lock:
            entry = self._publications.get(topic)
            return entry[0] if entry else None

    def subscription(self, topic: str) -> Subscription | None:
        """The subscription to ``topic`` (None: this node does not subscribe to it)."""
        with self._lock:
            entry = self._subscriptions.get(topic)
            return entry[0] if entry else None

    def publications(self) -> list[Publication]:
        """Every topic this node publishes."""
        with self._lock:
            return [p for p, _ in self._publications.values()]

    def subscriptions(self) -> list[Subscription]:
        """Every topic this node subscribes to."""
        with self._lock:
            return [s for s, _ in self._subscriptions.values()]

    def publication_list(self) -> list[list[str]]:
        """``[[topic, type], ...]`` of the publications (getPublications)."""
        with self._lock:
            return [[topic, pub.type.name] for topic, (pub, _) in self._publications.items()]

    def param_callbacks(self, name: str) -> list[ParamCallback]:
        """The callbacks of every subscribed parameter that ``name`` is, holds or lies under."""
        with self._lock:
            return [cb for k, cbs in self._param_callbacks.items()
                    if name == k or name.startswith(k.rstrip("/") + "/") or k.startswith(name + "/") for cb in cbs]

    def request_shutdown(self, caller_id: str, msg: str) -> None:
        """The slave API's ``shutdown``: close (after the call answered), then tell :attr:`on_shutdown`."""
        _log.warning("%s: shutdown request from [%s]: %s", self.name, caller_id, msg)
        self.shutdown_reason = f"external shutdown request from [{caller_id}]: {msg}"
        self.shutdown_requested.set()

        def close_then_tell() -> None:
            self.close()
            if self.on_shutdown is not None:
                self.on_shutdown(self.shutdown_reason)

        # close after this call has answered: closing stops the server answering it
        threading.Thread(target=close_then_tell, name="ros1-shutdown", daemon=True).start()

    def reregister(self) -> int:
        """Register every publication, subscription and parameter subscription again; how many topics.

        For a master that restarted (:mod:`._keepalive`); subscriptions connect to the
        publishers it names, keeping the connections they have.
        """
        with self._lock:
            pubs = [(topic, pub.type.name) for topic, (pub, _) in self._publications.items()]
            subs = [sub for sub, _ in self._subscriptions.values()]
            params = list(self._param_callbacks)
        for topic, typename in pubs:
            self.master.register_publisher(topic, typename, self.uri)
        for sub in subs:
            sub.add_publishers(self.master.register_subscriber(sub.topic, sub.type.name, self.uri))
        for key in params:
            self.params.subscribe_param(key, self.uri)
        return len(pubs) + len(subs)

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
        if self._keepalive is not None:
            self._keepalive.close()
        self._tcpros.close()
        self._slave.close()

    def __enter__(self) -> Ros1Node:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
