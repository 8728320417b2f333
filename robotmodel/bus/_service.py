"""ROS 2 services at the node layer: a server and a client of one service, messages in and out.

Made with :meth:`robotmodel.bus.Node.create_service` and :meth:`robotmodel.bus.Node.create_client`;
they speak through the backend seam (:meth:`robotmodel.bus.NodeHandle.declare_service`) and work
alike on every wire that has services. Requests and responses are encoded with the wire's codec
for the service's two message types (``pkg/srv/Name_Request``, ``pkg/srv/Name_Response``:
rosbags' classes unless ``request_type``/``response_type`` name other message classes).
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from robotmodel.bus._backend import ClientHandle, Handle, RequestId
from robotmodel.bus._codec import Codec, codec_for
from robotmodel.bus._srv import service_type
from robotmodel.errors import BusError, MessageError

if TYPE_CHECKING:
    from robotmodel.bus._node import Node

__all__ = ["Respond", "ServiceClient", "ServiceServer"]

log = logging.getLogger("robotmodel.bus")
#: How a server answers one request: ``respond(response_message)``.
Respond = Callable[[Any], None]


def _codecs(node: Node, srv_type: str, request_type: Any, response_type: Any) -> tuple[Codec, Codec]:
    stype = service_type(srv_type)
    encoding = node.context.encoding
    return (codec_for(request_type or stype.request.typename, encoding),
            codec_for(response_type or stype.response.typename, encoding))


class ServiceServer:
    """Serves one service: ``on_request(request, respond)`` per request, on the wire's thread.

    ``respond(response)`` may be called then or later, from any thread, once per request.
    A request that does not decode is dropped with a warning (the client gets no answer).
    """

    def __init__(self, node: Node, srv_type: str, name: str, on_request: Callable[[Any, Respond, RequestId], None],
                 request_type: Any = None, response_type: Any = None) -> None:
        self.srv_type = srv_type
        self.service_name = name
        self._on_request = on_request
        self._ready = threading.Event()
        # Declared first: a wire without services says so before any codec is asked for.
        self.handle: Handle | None = node.handle.declare_service(name, service_type(srv_type), self._on_raw)
        try:
            self._request, self._response = _codecs(node, srv_type, request_type, response_type)
        except BaseException:
            self.close()
            raise
        self._ready.set()

    def _on_raw(self, payload: bytes, request_id: RequestId, respond_raw: Callable[[bytes], None]) -> None:
        self._ready.wait()
        if self.handle is None:
            return
        try:
            request = self._request.decode(payload)
        except MessageError as exc:
            log.warning("dropped a request to '%s' that does not decode as %s: %s",
                        self.service_name, self._request.typename, exc)
            return

        def respond(response: Any) -> None:
            respond_raw(self._response.encode(response))

        try:
            self._on_request(request, respond, request_id)
        except Exception:
            # The wire's thread must survive a failing handler; say so loudly.
            log.exception("service '%s' failed on a request", self.service_name)

    def close(self) -> None:
        """Withdraw the service."""
        handle, self.handle = self.handle, None
        if handle is not None:
            handle.close()


class ServiceClient:
    """Calls one service: :meth:`call_async` sends a request, its callback gets the response."""

    def __init__(self, node: Node, srv_type: str, name: str, request_type: Any = None,
                 response_type: Any = None) -> None:
        self.srv_type = srv_type
        self.service_name = name
        self._node = node
        self.handle: ClientHandle | None = node.handle.declare_client(name, service_type(srv_type))
        try:
            self._request, self._response = _codecs(node, srv_type, request_type, response_type)
        except BaseException:
            self.close()
            raise

    def call_async(self, request: Any, on_response: Callable[[Any], None]) -> int:
        """Send ``request``; ``on_response(response)`` runs on the wire's thread. Returns the sequence number."""
        handle = self.handle
        if handle is None:
            raise BusError(f"client of '{self.service_name}' is closed")

        def on_raw(payload: bytes) -> None:
            try:
                response = self._response.decode(payload)
            except MessageError as exc:
                log.warning("dropped a response from '%s' that does not decode as %s: %s",
                            self.service_name, self._response.typename, exc)
                return
            on_response(response)

        return handle.request(self._request.encode(request), on_raw)

    def call(self, request: Any, timeout: float = 5.0) -> Any:
        """Send ``request`` and wait for its response; BusError at the timeout."""
        done = threading.Event()
        box: list[Any] = []

        def got(response: Any) -> None:
            box.append(response)
            done.set()

        self.call_async(request, got)
        if not done.wait(timeout):
            raise BusError(f"no response from '{self.service_name}' within {timeout} s")
        return box[0]

    def service_is_ready(self) -> bool:
        """Whether a server of this service is known now."""
        handle = self.handle
        return handle is not None and handle.server_ready()

    def wait_for_service(self, timeout: float | None = None) -> bool:
        """Wait until a server is known (None: for ever); False at the timeout."""
        end = None if timeout is None else time.monotonic() + timeout
        while not self.service_is_ready():
            if end is not None and time.monotonic() >= end:
                return False
            time.sleep(0.01)  # rmw's wait_for_service polls the graph too
        return True

    def close(self) -> None:
        """Withdraw the client."""
        handle, self.handle = self.handle, None
        if handle is not None:
            handle.close()
