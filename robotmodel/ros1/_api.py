"""The Slave API as a node answers it (wiki.ros.org/ROS/Slave_API): one function per method.

:func:`slave_handlers` builds the table a :class:`robotmodel.ros1.SlaveServer` dispatches to,
each handler answering ROS's ``[code, statusMessage, value]`` from the node's state.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robotmodel.ros1._node import Ros1Node

__all__ = ["slave_handlers"]


def slave_handlers(node: Ros1Node) -> dict[str, Callable[..., list[Any]]]:
    """The Slave API of ``node``: requestTopic, publisherUpdate, getBus*, shutdown, paramUpdate, ..."""

    def request_topic(caller_id: str, topic: str, protocols: list[Any]) -> list[Any]:
        if node.publication(topic) is None:
            return [-1, f"Not a publisher of [{topic}]", []]
        if not isinstance(protocols, list) or not any(isinstance(p, list) and p[:1] == ["TCPROS"]
                                                      for p in protocols):
            return [0, "no supported protocol implementations", []]
        port = node.tcpros_port
        return [1, f"ready on {node.host}:{port}", ["TCPROS", node.host, port]]

    def publisher_update(caller_id: str, topic: str, publishers: list[str]) -> list[Any]:
        if not isinstance(publishers, list) or not all(isinstance(p, str) for p in publishers):
            return [-1, "ERROR: param [publishers] must be a list of strings", 0]
        subscription = node.subscription(topic)
        if subscription is not None:
            subscription.update_publishers(publishers)
        return [1, "", 0]

    def bus_info(caller_id: str) -> list[Any]:
        pubs, subs = node.publications(), node.subscriptions()
        rows = [row for p in pubs for row in p.bus_info()] + [row for s in subs for row in s.bus_info()]
        return [1, "bus info", rows]

    def bus_stats(caller_id: str) -> list[Any]:
        pubs, subs = node.publications(), node.subscriptions()
        return [1, "", [[p.bus_stats() for p in pubs], [s.bus_stats() for s in subs], []]]

    def shutdown(caller_id: str, msg: str = "") -> list[Any]:
        node.request_shutdown(caller_id, msg)
        return [1, "shutdown", 0]

    def param_update(caller_id: str, key: str, value: Any) -> list[Any]:
        name = "/" + key.strip("/")
        targets = node.param_callbacks(name)
        if not targets:
            return [-1, "not subscribed", 0]
        for callback in targets:
            callback(name, value)
        return [1, "", 0]

    return {
        "requestTopic": request_topic,
        "publisherUpdate": publisher_update,
        "getBusInfo": bus_info,
        "getBusStats": bus_stats,
        "getPid": lambda caller_id: [1, "", os.getpid()],
        "getMasterUri": lambda caller_id: [1, node.master_uri, node.master_uri],
        "getSubscriptions": lambda caller_id: [1, "subscriptions",
                                               [[s.topic, s.type.name] for s in node.subscriptions()]],
        "getPublications": lambda caller_id: [1, "publications", node.publication_list()],
        "shutdown": shutdown,
        "paramUpdate": param_update,
    }
