"""The ROS 1 master's graph as the seam's entities: getSystemState and getTopicTypes, polled.

Nodes are caller ids split into namespace and name; endpoints carry the topic's type in
ROS 2 form and no QoS (the master has none); a publisher's GID is derived from its caller id
and topic (:func:`ros1_gid`), as the wire's samples carry it. The master is polled every
:data:`GRAPH_PERIOD_S` and whenever :meth:`GraphPoller.wake` is called (after this session
changes its own registrations).
"""

from __future__ import annotations

import hashlib
import logging
import threading

from robotmodel.bus._backend import Entity, EntityKind, GraphCallback, Handle
from robotmodel.bus._warn import Warner
from robotmodel.errors import MasterError

__all__ = ["GRAPH_PERIOD_S", "GraphPoller", "GraphWatch", "ros1_gid", "ros2_type_name"]

_log = logging.getLogger("robotmodel.bus")

#: Seconds between two polls of the master's graph.
GRAPH_PERIOD_S = 0.5


def ros1_gid(callerid: str, topic: str) -> bytes:
    """The 16-byte id of ``callerid``'s publisher of ``topic`` (ROS 1 has none: derived, stable)."""
    return hashlib.blake2b(f"{callerid}\0{topic}".encode(), digest_size=16).digest()


def ros2_type_name(name: str) -> str:
    """A ROS 1 type name (``pkg/Type``) in ROS 2 form (``pkg/msg/Type``); anything else unchanged."""
    parts = name.split("/")
    return f"{parts[0]}/msg/{parts[1]}" if len(parts) == 2 and all(parts) else name


def _split(callerid: str) -> tuple[str, str]:
    """(name, namespace) of a caller id: ``/a/b/talker`` -> ``("talker", "/a/b")``."""
    ns, _, name = callerid.rstrip("/").rpartition("/")
    return name, ns or "/"


class GraphPoller:
    """Follows the master's graph and tells the watchers what came and went."""

    def __init__(self, master_uri: str) -> None:
        from robotmodel.ros1 import MasterClient

        self._master = MasterClient(master_uri, "/robotmodel_graph", timeout=5.0)
        self._lock = threading.Lock()
        self._entities: dict[str, Entity] = {}
        self._watchers: list[GraphCallback] = []
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._warner = Warner()
        self._thread: threading.Thread | None = None

    def add(self, callback: GraphCallback) -> None:
        with self._lock:
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="ros1-graph", daemon=True)
                self._thread.start()
        self.poll()  # the watcher starts with the graph as the master has it now
        with self._lock:
            for key, entity in self._entities.items():
                callback(key, entity)
            self._watchers.append(callback)

    def remove(self, callback: GraphCallback) -> None:
        with self._lock:
            if callback in self._watchers:
                self._watchers.remove(callback)

    def _snapshot(self) -> dict[str, Entity]:
        pubs, subs, srvs = self._master.get_system_state()
        types = {topic: ros2_type_name(t) for topic, t in self._master.get_topic_types()}
        found: dict[str, Entity] = {}
        callers: set[str] = set()
        for kind, entries in ((EntityKind.PUBLISHER, pubs), (EntityKind.SUBSCRIPTION, subs),
                              (EntityKind.SERVICE, srvs)):
            for topic, nodes in entries:
                for caller in nodes:
                    callers.add(caller)
                    name, ns = _split(caller)
                    gid = ros1_gid(caller, topic) if kind is EntityKind.PUBLISHER else b""
                    found[f"{kind.value} {caller} {topic}"] = Entity(
                        kind, name, ns, topic=topic, typename=types.get(topic, ""), gid=gid, node_key=caller)
        for caller in callers:
            name, ns = _split(caller)
            found[f"node {caller}"] = Entity(EntityKind.NODE, name, ns, node_key=caller)
        return found

    def poll(self) -> None:
        try:
            now = self._snapshot()
        except (MasterError, ValueError, TypeError) as exc:
            if isinstance(exc, MasterError) and exc.code is None:
                # a master that went away: each node's keepalive says so once (robotmodel.ros1._keepalive)
                _log.debug("cannot read the ROS 1 graph: %s", exc)
            else:
                self._warner.warn("master", f"cannot read the ROS 1 graph: {exc}")
            return
        with self._lock:
            old, self._entities = self._entities, now
            watchers = list(self._watchers)
            changes: list[tuple[str, Entity | None]] = [(k, None) for k in old if k not in now]
            changes += [(k, e) for k, e in now.items() if old.get(k) != e]
            for key, entity in changes:
                for callback in watchers:
                    callback(key, entity)

    def _run(self) -> None:
        while not self._stop.is_set():
            self._wake.wait(GRAPH_PERIOD_S)
            self._wake.clear()
            if self._stop.is_set():
                return
            self.poll()

    def wake(self) -> None:
        self._wake.set()

    def close(self) -> None:
        self._stop.set()
        self._wake.set()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout=10)


class GraphWatch(Handle):
    """A watcher of a :class:`GraphPoller`, removed on close."""

    def __init__(self, poller: GraphPoller, callback: GraphCallback) -> None:
        self._poller = poller
        self._callback = callback

    def close(self) -> None:
        self._poller.remove(self._callback)
