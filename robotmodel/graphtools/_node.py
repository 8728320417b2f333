"""``ros2 node list`` and ``ros2 node info``: the nodes of the graph and what one offers."""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["run_node_info", "run_node_list"]


def _fqn(name: str, namespace: str) -> str:
    return namespace.rstrip("/") + "/" + name


def run_node_list(*, count_nodes: bool = False, all_nodes: bool = False, connect: Sequence[str] = (),
                  spin_time: float = 0.5) -> int:
    """``ros2 node list``: the nodes' fully qualified names, sorted (hidden ones with ``all_nodes``)."""
    from robotmodel.bus import Node
    from robotmodel.topic._tools import _discover, _hidden

    with Node("_robotmodel_node_list", connect=list(connect)) as node:
        _discover(node, spin_time)
        names = sorted({_fqn(n, ns) for n, ns in node.get_node_names_and_namespaces()})
    names = [n for n in names if all_nodes or not _hidden(n)]
    if count_nodes:
        print(len(names))
        return 0
    for name in names:
        print(name)
    return 0


def run_node_info(node_name: str, *, connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 node info``: the node's subscribers, publishers, service servers and clients."""
    from robotmodel.bus import EntityKind, Node
    from robotmodel.errors import BusError
    from robotmodel.topic._tools import _discover

    with Node("_robotmodel_node_info", connect=list(connect)) as node:
        _discover(node, spin_time)
        entities = [e for e in node.context.graph.entities() if e.node_fqn == node_name]
    if not entities:
        raise BusError(f"Unable to find node '{node_name}'")
    print(node_name)
    for title, kind in (("Subscribers", EntityKind.SUBSCRIPTION), ("Publishers", EntityKind.PUBLISHER),
                        ("Service Servers", EntityKind.SERVICE), ("Service Clients", EntityKind.CLIENT)):
        print(f"  {title}:")
        for topic, typename in sorted({(e.topic, e.typename) for e in entities if e.kind == kind}):
            print(f"    {topic}: {typename}" if typename else f"    {topic}")  # ROS 1's master has no service types
    print("  Action Servers:")
    print("  Action Clients:")
    return 0
