"""The Slave API server: the XML-RPC endpoint every ROS 1 node serves (wiki.ros.org/ROS/Slave_API).

The server only frames calls: a table maps each method name to a function returning ROS's
``[code, statusMessage, value]``. A call with an unknown method or the wrong arguments gets
``[-1, "ERROR: ...", 0]`` and one log line; a failing handler gets ``[0, text, 0]``. Neither
stops the server.
"""

from __future__ import annotations

import inspect
import logging
import socketserver
import threading
from collections.abc import Callable, Mapping
from typing import Any
from xmlrpc.server import SimpleXMLRPCRequestHandler, SimpleXMLRPCServer

from robotmodel.errors import Ros1Error

__all__ = ["SLAVE_METHODS", "SlaveServer"]

_log = logging.getLogger("robotmodel.ros1")

#: The Slave API's methods, each taking ``caller_id`` first.
SLAVE_METHODS = ("requestTopic", "publisherUpdate", "getBusInfo", "getBusStats", "getPid", "getMasterUri",
                 "getSubscriptions", "getPublications", "shutdown", "paramUpdate")

Handler = Callable[..., list[Any]]


class _QuietHandler(SimpleXMLRPCRequestHandler):
    """No access log on stderr, and HTTP keep-alive off as rospy's server has it."""

    def log_message(self, format: str, *args: Any) -> None:
        pass


class _Server(socketserver.ThreadingMixIn, SimpleXMLRPCServer):
    daemon_threads = True
    allow_reuse_address = True


class SlaveServer:
    """A threaded XML-RPC server on ``bind``:(``port`` or a free one) dispatching to ``handlers``.

    ``uri`` is the address peers use: ``http://HOST:PORT/`` with ``host`` as advertised.
    """

    def __init__(self, handlers: Mapping[str, Handler], *, host: str, bind: str, port: int = 0,
                 name: str = "ros1-slave") -> None:
        self._handlers = dict(handlers)
        try:
            self._server = _Server((bind, port), requestHandler=_QuietHandler, logRequests=False,
                                   allow_none=True)
        except OSError as exc:
            raise Ros1Error(f"cannot serve the slave API on {bind}:{port}: {exc}") from None
        self._server.register_instance(self)
        self.port = int(self._server.server_address[1])
        self.uri = f"http://{host}:{self.port}/"
        self._thread = threading.Thread(target=self._server.serve_forever, kwargs={"poll_interval": 0.1},
                                        name=name, daemon=True)
        self._thread.start()

    def _dispatch(self, method: str, params: tuple[Any, ...]) -> list[Any]:
        """Entry point of :class:`SimpleXMLRPCServer` for every call."""
        handler = self._handlers.get(method)
        if handler is None:
            _log.warning("slave API %s: unknown method %r called with %r", self.uri, method, params)
            return [-1, f"ERROR: unknown method [{method}]", 0]
        try:
            inspect.signature(handler).bind(*params)
        except TypeError as exc:
            _log.warning("slave API %s: %s%r: wrong arguments (%s)", self.uri, method, params, exc)
            return [-1, f"ERROR: wrong arguments for {method}: {exc}", 0]
        try:
            return handler(*params)
        except Exception as exc:  # a bug or bad input in one call must not stop the server
            _log.warning("slave API %s: %s%r failed: %s", self.uri, method, params, exc)
            return [0, f"ERROR: {method} failed: {exc}", 0]

    def close(self) -> None:
        """Stop serving and close the socket."""
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(timeout=5)
