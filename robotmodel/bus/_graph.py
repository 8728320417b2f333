"""The ROS graph as seen through rmw_zenoh's liveliness tokens: nodes, topics and their types."""

from __future__ import annotations

import threading
from collections.abc import Callable

from robotmodel.bus._backend import Backend, Handle
from robotmodel.bus._names import ADMIN_SPACE, Entity, EntityKind
from robotmodel.errors import BusError

__all__ = ["Graph"]


class Graph:
    """A live cache of one domain's entities, filled from liveliness tokens.

    It starts with a query for the current tokens and then follows arrivals and
    departures, as rmw_zenoh's graph cache does.
    """

    def __init__(self, backend: Backend, domain_id: int, timeout: float = 1.0) -> None:
        self._lock = threading.Condition()
        self._entities: dict[str, Entity] = {}
        self._by_gid: dict[bytes, Entity] = {}
        pattern = f"{ADMIN_SPACE}/{domain_id}/**"
        self._watch: Handle = backend.watch_tokens(pattern, self._on_token)
        for token in backend.get_tokens(pattern, timeout):
            self._on_token(token, True)

    def _on_token(self, token: str, alive: bool) -> None:
        with self._lock:
            if not alive:
                gone = self._entities.pop(token, None)
                if gone is not None:
                    self._by_gid.pop(gone.gid, None)
            else:
                try:
                    entity = self._entities[token] = Entity.parse(token)
                except BusError:
                    return  # not ours to read (another tool's token under @ros2_lv)
                self._by_gid[entity.gid] = entity
            self._lock.notify_all()

    def entities(self) -> list[Entity]:
        """Every live entity (nodes, publishers, subscriptions, services, clients)."""
        with self._lock:
            return list(self._entities.values())

    def by_gid(self, gid: bytes) -> Entity | None:
        """The live entity with this GID (as a sample's attachment carries it), if any."""
        with self._lock:
            return self._by_gid.get(gid)

    def wait_for(self, predicate: Callable[[list[Entity]], bool], timeout: float) -> bool:
        """Wait until ``predicate(entities)`` holds; False at the timeout."""
        with self._lock:
            return self._lock.wait_for(lambda: predicate(list(self._entities.values())), timeout)

    def topic_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Sorted topics, each with its sorted types (rclpy's ``get_topic_names_and_types()``)."""
        topics: dict[str, set[str]] = {}
        for e in self.entities():
            if e.kind in (EntityKind.PUBLISHER, EntityKind.SUBSCRIPTION):
                topics.setdefault(e.topic, set()).add(e.typename)
        return [(name, sorted(types)) for name, types in sorted(topics.items())]

    def node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """Every node as (name, namespace), as rclpy's ``get_node_names_and_namespaces()``.

        As in rmw_zenoh's graph cache, a node is one (session id, node id), known from any of
        its tokens; nodes sharing a name are each listed.
        """
        nodes = {(e.zid, e.node_id): (e.node_name, e.namespace) for e in self.entities()}
        return sorted(nodes.values())

    def endpoints(self, topic: str, kind: EntityKind) -> list[Entity]:
        """The publishers or subscriptions on one fully qualified topic."""
        return [e for e in self.entities() if e.kind is kind and e.topic == topic]

    def close(self) -> None:
        """Stop following the tokens."""
        self._watch.close()
