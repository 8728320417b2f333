"""The ROS graph as one session sees it: nodes, topics, types and QoS, from whatever wire it is on."""

from __future__ import annotations

import threading
from collections.abc import Callable

from robotmodel.bus._backend import Backend, Entity, EntityKind, Handle

__all__ = ["Graph"]


class Graph:
    """A live cache of one domain's entities, filled by the wire's :meth:`Backend.watch_graph`.

    It starts with the entities the wire knows and then follows arrivals and departures,
    as rmw's graph caches do.
    """

    def __init__(self, backend: Backend) -> None:
        self._lock = threading.Condition()
        self._entities: dict[str, Entity] = {}
        self._by_gid: dict[bytes, Entity] = {}
        self._watch: Handle = backend.watch_graph(self._on_change)

    def _on_change(self, key: str, entity: Entity | None) -> None:
        with self._lock:
            if entity is None:
                gone = self._entities.pop(key, None)
                if gone is not None and gone.gid:
                    self._by_gid.pop(gone.gid, None)
            else:
                self._entities[key] = entity
                if entity.gid:
                    self._by_gid[entity.gid] = entity
            self._lock.notify_all()

    def entities(self) -> list[Entity]:
        """Every live entity (nodes, publishers, subscriptions, services, clients)."""
        with self._lock:
            return list(self._entities.values())

    def by_gid(self, gid: bytes) -> Entity | None:
        """The live entity with this GID (as a sample's info carries it), if any."""
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

        As in rmw's graph caches, a node is one ``node_key`` (zenoh: session and node id),
        known from any of its entities; nodes sharing a name are each listed. An endpoint no
        node claims (DDS: none in ``ros_discovery_info``) has no ``node_key`` and adds no node.
        """
        nodes = {e.node_key: (e.node_name, e.namespace) for e in self.entities() if e.node_key}
        return sorted(nodes.values())

    def endpoints(self, topic: str, kind: EntityKind) -> list[Entity]:
        """The publishers or subscriptions on one fully qualified topic (each with its node and QoS)."""
        return [e for e in self.entities() if e.kind is kind and e.topic == topic]

    def close(self) -> None:
        """Stop following the wire's graph."""
        self._watch.close()
