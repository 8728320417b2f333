"""``ros2 topic info [-v]`` and ``ros2 topic type``: a topic's type and its endpoints, from the graph."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

__all__ = ["run_topic_info", "run_topic_type"]

_INFINITE = 0x7FFFFFFFFFFFFFFF


def _duration(ns: int) -> str:
    return "Infinite" if ns <= 0 or ns >= _INFINITE else f"{ns} nanoseconds"


def _endpoint_text(entity: Any, kind: str) -> str:
    qos = entity.qos
    lines = [f"Node name: {entity.node_name or '_NODE_NAME_UNKNOWN_'}",
             f"Node namespace: {entity.namespace if entity.node_name else '_NODE_NAMESPACE_UNKNOWN_'}",
             f"Topic type: {entity.typename}",
             f"Topic type hash: {entity.type_hash or 'INVALID'}",
             f"Endpoint type: {kind}",
             f"GID: {'.'.join(f'{b:02x}' for b in entity.gid)}",
             "QoS profile:"]
    if qos is not None:
        lines += [f"  Reliability: {qos.reliability.name}",
                  f"  History (Depth): {qos.history.name} ({qos.depth})",
                  f"  Durability: {qos.durability.name}",
                  f"  Lifespan: {_duration(qos.lifespan_ns)}",
                  f"  Deadline: {_duration(qos.deadline_ns)}",
                  f"  Liveliness: {qos.liveliness.name}",
                  f"  Liveliness lease duration: {_duration(qos.liveliness_lease_ns)}"]
    return "\n".join(lines) + "\n"


def _found(node: Any, topic_name: str, spin_time: float) -> tuple[str, list[str]]:
    from robotmodel.errors import BusError
    from robotmodel.topic._tools import _discover

    topic = node.resolve_topic_name(topic_name)
    found = dict(_discover(node, spin_time))
    if topic not in found:
        raise BusError(f"Unknown topic '{topic}'")
    return topic, found[topic]


def run_topic_info(topic_name: str, *, verbose: bool = False, connect: Sequence[str] = (),
                   spin_time: float = 0.5) -> int:
    """``ros2 topic info``: print the type and publisher/subscription counts (``verbose``: each endpoint)."""
    from robotmodel.bus import EntityKind, Node

    with Node("_robotmodel_topic_info", connect=list(connect)) as node:
        topic, types = _found(node, topic_name, spin_time)
        pubs = node.context.graph.endpoints(topic, EntityKind.PUBLISHER)
        subs = [s for s in node.context.graph.endpoints(topic, EntityKind.SUBSCRIPTION)
                if s.node_name != node.get_name()]
    print(f"Type: {'; '.join(types)}")
    if verbose:
        print()
    print(f"Publisher count: {len(pubs)}")
    if verbose:
        print()
        for pub in pubs:
            print(_endpoint_text(pub, "PUBLISHER"))
    print(f"Subscription count: {len(subs)}")
    if verbose:
        print()
        for sub in subs:
            print(_endpoint_text(sub, "SUBSCRIPTION"))
    return 0


def run_topic_type(topic_name: str, *, connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 topic type``: print the topic's type(s), one a line."""
    from robotmodel.bus import Node

    with Node("_robotmodel_topic_type", connect=list(connect)) as node:
        _topic, types = _found(node, topic_name, spin_time)
    for t in types:
        print(t)
    return 0
