"""Clients of the ROS master's XML-RPC APIs: the Master API and the Parameter Server API.

Every call returns ROS's ``[code, statusMessage, value]``; code 1 is success, anything else
(and a master that cannot be reached) raises one :class:`MasterError` naming the master URI,
the method and ROS's status text (wiki.ros.org/ROS/Master_API, /ROS/Parameter Server).
"""

from __future__ import annotations

import http.client
import os
import socket
import xmlrpc.client
from typing import Any, cast

from robotmodel.errors import MasterError

__all__ = ["DEFAULT_MASTER_URI", "MasterClient", "ParamClient", "master_uri_from_env", "xmlrpc_call"]

#: ROS 1's default when ROS_MASTER_URI is unset.
DEFAULT_MASTER_URI = "http://localhost:11311"

#: Seconds an XML-RPC call may take before the peer counts as unreachable.
DEFAULT_TIMEOUT = 10.0


def master_uri_from_env() -> str:
    """ROS_MASTER_URI, else ROS 1's default ``http://localhost:11311``."""
    return os.environ.get("ROS_MASTER_URI") or DEFAULT_MASTER_URI


class _TimeoutTransport(xmlrpc.client.Transport):
    """An XML-RPC transport whose connections time out (the stock one waits forever)."""

    def __init__(self, timeout: float) -> None:
        super().__init__()
        self._timeout = timeout

    def make_connection(self, host: Any) -> http.client.HTTPConnection:
        conn = super().make_connection(host)
        conn.timeout = self._timeout
        return conn


def xmlrpc_call(uri: str, method: str, *args: Any, timeout: float = DEFAULT_TIMEOUT) -> Any:
    """The raw answer of ``method(*args)`` at the XML-RPC server ``uri`` (a fresh connection per call)."""
    proxy = xmlrpc.client.ServerProxy(uri, transport=_TimeoutTransport(timeout))
    with proxy:
        return getattr(proxy, method)(*args)


class MasterClient:
    """The Master API of ``master_uri`` called as node ``caller_id``.

    Methods mirror rospy's ``rosgraph.masterapi.Master`` and return the ``value`` part.
    """

    def __init__(self, master_uri: str, caller_id: str, *, timeout: float = DEFAULT_TIMEOUT) -> None:
        self.master_uri = master_uri
        self.caller_id = caller_id
        self.timeout = timeout

    def call(self, method: str, *args: Any) -> Any:
        """``method(caller_id, *args)`` at the master; the value when the code is 1, else :class:`MasterError`."""
        where = f"master {self.master_uri}"
        try:
            answer = xmlrpc_call(self.master_uri, method, self.caller_id, *args, timeout=self.timeout)
        except (OSError, http.client.HTTPException) as exc:
            reason = "timed out" if isinstance(exc, socket.timeout) else str(exc)
            raise MasterError(f"{where} is unreachable ({method}): {reason}", master_uri=self.master_uri,
                              method=method) from None
        except xmlrpc.client.Fault as exc:
            raise MasterError(f"{where}: {method} failed: {exc.faultString}", master_uri=self.master_uri,
                              method=method) from None
        if not isinstance(answer, list) or len(answer) != 3 or not isinstance(answer[0], int):
            raise MasterError(f"{where}: {method} returned {answer!r}, not [code, statusMessage, value]",
                              master_uri=self.master_uri, method=method)
        code, status, value = answer
        if code != 1:
            raise MasterError(f"{where}: {method} failed: {status}", master_uri=self.master_uri, method=method,
                              code=code)
        return value

    def register_publisher(self, topic: str, topic_type: str, caller_api: str) -> list[str]:
        """registerPublisher; the URIs of the topic's current subscribers."""
        return cast(list[str], self.call("registerPublisher", topic, topic_type, caller_api))

    def unregister_publisher(self, topic: str, caller_api: str) -> int:
        """unregisterPublisher; the number of registrations removed (0 when there was none)."""
        return int(self.call("unregisterPublisher", topic, caller_api))

    def register_subscriber(self, topic: str, topic_type: str, caller_api: str) -> list[str]:
        """registerSubscriber; the XML-RPC URIs of the topic's current publishers."""
        return cast(list[str], self.call("registerSubscriber", topic, topic_type, caller_api))

    def unregister_subscriber(self, topic: str, caller_api: str) -> int:
        """unregisterSubscriber; the number of registrations removed."""
        return int(self.call("unregisterSubscriber", topic, caller_api))

    def lookup_node(self, node_name: str) -> str:
        """lookupNode; the XML-RPC URI of ``node_name``."""
        return str(self.call("lookupNode", node_name))

    def get_system_state(self) -> tuple[list[list[Any]], list[list[Any]], list[list[Any]]]:
        """getSystemState: (publishers, subscribers, services), each ``[[name, [node, ...]], ...]``."""
        pubs, subs, srvs = self.call("getSystemState")
        return pubs, subs, srvs

    def get_topic_types(self) -> list[list[str]]:
        """getTopicTypes: ``[[topic, type], ...]`` for every topic with a known type."""
        return cast(list[list[str]], self.call("getTopicTypes"))

    def get_published_topics(self, subgraph: str = "") -> list[list[str]]:
        """getPublishedTopics: ``[[topic, type], ...]`` of published topics under ``subgraph``."""
        return cast(list[list[str]], self.call("getPublishedTopics", subgraph))

    def get_uri(self) -> str:
        """getUri: the master's own URI."""
        return str(self.call("getUri"))


class ParamClient:
    """The Parameter Server API of ``master_uri`` called as node ``caller_id``."""

    def __init__(self, master_uri: str, caller_id: str, *, timeout: float = DEFAULT_TIMEOUT) -> None:
        self._master = MasterClient(master_uri, caller_id, timeout=timeout)

    @property
    def master_uri(self) -> str:
        """The master this client talks to."""
        return self._master.master_uri

    def get_param(self, key: str) -> Any:
        """getParam; :class:`MasterError` (code -1, ROS's "Parameter [...] is not set") when unset."""
        return self._master.call("getParam", key)

    def set_param(self, key: str, value: Any) -> None:
        """Call setParam (a dict value sets a tree of parameters, as ROS does)."""
        self._master.call("setParam", key, value)

    def delete_param(self, key: str) -> None:
        """deleteParam; :class:`MasterError` when ``key`` is not set."""
        self._master.call("deleteParam", key)

    def has_param(self, key: str) -> bool:
        """Call hasParam: whether ``key`` is set."""
        return bool(self._master.call("hasParam", key))

    def search_param(self, key: str) -> str | None:
        """Call searchParam: the full name of ``key`` found up the caller's namespace, or None (as rospy)."""
        try:
            found = self._master.call("searchParam", key)
        except MasterError as exc:
            if exc.code == -1:  # rosmaster's "Cannot find parameter [...] in an upwards search"
                return None
            raise
        return str(found) if found else None

    def get_param_names(self) -> list[str]:
        """getParamNames: every parameter's full name."""
        return cast(list[str], self._master.call("getParamNames"))

    def subscribe_param(self, key: str, caller_api: str) -> Any:
        """subscribeParam: the current value ({} when unset); paramUpdate calls ``caller_api`` on change."""
        return self._master.call("subscribeParam", caller_api, key)

    def unsubscribe_param(self, key: str, caller_api: str) -> int:
        """unsubscribeParam; the number of subscriptions removed."""
        return int(self._master.call("unsubscribeParam", caller_api, key))
