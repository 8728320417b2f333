"""The TCPROS subscriber side: one connection per publisher, kept up while the master lists it.

For each publisher URI the master gives (registerSubscriber, then publisherUpdate) a thread
asks the publisher's slave API for a TCPROS endpoint (requestTopic), connects, exchanges
headers and reads length-prefixed messages. A dropped connection is retried with a short
backoff while the publisher is still listed, asking requestTopic again so a publisher that
restarted on a new port is found; a publisher whose slave API refuses connections is gone, and
the next publisherUpdate that lists it (or its successor) starts a new connection. A refusal
(``error`` in the publisher's header), a type/md5sum mismatch or a header that does not parse
is one log line, and that publisher is not tried again while the master keeps listing it.
"""

from __future__ import annotations

import contextlib
import errno
import http.client
import itertools
import logging
import socket
import threading
import xmlrpc.client
from collections.abc import Callable, Mapping
from typing import Any

from robotmodel.errors import Ros1Error
from robotmodel.ros1._header import FrameReader, read_header, write_header
from robotmodel.ros1._master import xmlrpc_call
from robotmodel.ros1._msgs import Ros1Type

__all__ = ["MessageCallback", "Subscription"]

_log = logging.getLogger("robotmodel.ros1")

#: Called with each message's bytes and the publisher's connection header.
MessageCallback = Callable[[bytes, Mapping[str, str]], None]

_connection_ids = itertools.count(1_000_000)
_BACKOFF = (0.05, 0.1, 0.2, 0.4, 0.8, 1.0)
_CONNECT_TIMEOUT = 10.0


class _Refused(Exception):
    """The publisher refused us (or we refused it): log once, do not retry."""


class _Inbound:
    """The connection to one publisher, with its own thread."""

    def __init__(self, sub: Subscription, pub_uri: str) -> None:
        self.sub = sub
        self.pub_uri = pub_uri
        self.id = next(_connection_ids)
        self.callerid = ""
        self.bytes_received = 0
        self.messages_received = 0
        self.connected = False
        self.info = ""
        self.header: Mapping[str, str] = {}
        self._stop = threading.Event()
        self._sock: socket.socket | None = None
        self.thread = threading.Thread(target=self._run, name=f"ros1-sub{sub.topic}", daemon=True)
        self.thread.start()

    def _endpoint(self) -> tuple[str, int]:
        answer = xmlrpc_call(self.pub_uri, "requestTopic", self.sub.callerid, self.sub.topic, [["TCPROS"]],
                             timeout=_CONNECT_TIMEOUT)
        if not isinstance(answer, list) or len(answer) != 3:
            raise _Refused(f"requestTopic at {self.pub_uri} returned {answer!r}, not [code, statusMessage, value]")
        code, status, protocol = answer
        if code != 1:
            raise _Refused(f"requestTopic at {self.pub_uri} failed: {status}")
        if not isinstance(protocol, list) or len(protocol) != 3 or protocol[0] != "TCPROS":
            raise _Refused(f"publisher {self.pub_uri} returned invalid protocol choice: {protocol!r}")
        return str(protocol[1]), int(protocol[2])

    def _connect(self) -> socket.socket:
        host, port = self._endpoint()
        sock = socket.create_connection((host, port), timeout=_CONNECT_TIMEOUT)
        try:
            if self.sub.tcp_nodelay:
                sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            write_header(sock, self.sub.request_header())
            header = read_header(sock)
            self.sub.check(header, self.pub_uri)
            self.callerid = header.get("callerid", "")
            self.header = header
            sock.settimeout(None)
            local = sock.getsockname()
            self.info = f"TCPROS connection on port {local[1]} to [{host}:{port} on socket {sock.fileno()}]"
        except BaseException:
            sock.close()
            raise
        return sock

    def _run(self) -> None:
        attempt = 0
        refused = False
        while not self._stop.is_set():
            try:
                sock = self._connect()
            except _Refused as exc:
                _log.warning("topic %s: %s", self.sub.topic, exc)
                refused = True
                break
            except Ros1Error as exc:  # a header that does not parse: the peer is not TCPROS
                _log.warning("topic %s: publisher %s: %s; dropping it", self.sub.topic, self.pub_uri, exc)
                refused = True
                break
            except (OSError, EOFError, http.client.HTTPException, xmlrpc.client.Error, ValueError) as exc:
                if getattr(exc, "errno", None) == errno.ECONNREFUSED and not self.connected and attempt > 0:
                    # the publisher's slave API is gone: it died; a publisherUpdate brings its successor
                    _log.info("topic %s: publisher %s is gone: %s", self.sub.topic, self.pub_uri, exc)
                    break
                if self._stop.wait(_BACKOFF[min(attempt, len(_BACKOFF) - 1)]):
                    break
                attempt += 1
                continue
            with self.sub.lock:
                if self._stop.is_set():
                    sock.close()
                    break
                self._sock = sock
            self.connected = True
            attempt = 0
            self._receive(sock)
            self.connected = False
            attempt = 1
        self._stop.set()
        if not refused:  # a refused publisher stays known (and not retried) while the master lists it
            self.sub.forget(self)

    def _receive(self, sock: socket.socket) -> None:
        header = self.header
        frames = FrameReader(sock)
        while not self._stop.is_set():
            try:
                data = frames.read()
            except (OSError, EOFError) as exc:
                if not self._stop.is_set():
                    _log.info("topic %s: connection to %s lost: %s", self.sub.topic, self.pub_uri, exc)
                break
            except Ros1Error as exc:
                _log.warning("topic %s: publisher %s sent garbage (%s); reconnecting", self.sub.topic,
                             self.pub_uri, exc)
                break
            self.bytes_received += len(data)
            self.messages_received += 1
            try:
                self.sub.callback(data, header)
            except Exception as exc:  # a subscriber's callback must not end the connection
                _log.warning("topic %s: callback failed: %s", self.sub.topic, exc)
        sock.close()

    def close(self) -> None:
        self._stop.set()
        sock = self._sock
        if sock is not None:
            with contextlib.suppress(OSError):
                sock.shutdown(socket.SHUT_RDWR)


class Subscription:
    """A topic this node subscribes to: one :class:`_Inbound` per publisher the master lists."""

    def __init__(self, topic: str, msg_type: Ros1Type, callerid: str, callback: MessageCallback, *,
                 tcp_nodelay: bool = False) -> None:
        self.topic = topic
        self.type = msg_type
        self.callerid = callerid
        self.callback = callback
        self.tcp_nodelay = tcp_nodelay
        self.lock = threading.Lock()
        self._inbound: dict[str, _Inbound] = {}
        self.closed = False

    def request_header(self) -> dict[str, str]:
        """The header this side opens a connection with."""
        return {"callerid": self.callerid, "topic": self.topic, "md5sum": self.type.md5sum, "type": self.type.name,
                "message_definition": self.type.definition, "tcp_nodelay": "1" if self.tcp_nodelay else "0"}

    def check(self, header: Mapping[str, str], pub_uri: str) -> None:
        """Refuse a publisher's header that reports an error or another type/md5sum (raises :class:`_Refused`)."""
        if "error" in header:
            raise _Refused(f"publisher {pub_uri}: remote error reported: {header['error']}")
        for required in ("md5sum", "type"):
            if required not in header:
                raise _Refused(f"publisher {pub_uri}: header missing required field [{required}]")
        if header["md5sum"] not in ("*", self.type.md5sum) and self.type.md5sum != "*":
            raise _Refused(f"publisher [{header.get('callerid', pub_uri)}] has topic [{self.topic}] with "
                           f"datatype/md5sum [{header['type']}/{header['md5sum']}], but we want "
                           f"[{self.type.name}/{self.type.md5sum}] Dropping connection.")

    def update_publishers(self, uris: list[str]) -> None:
        """Make the connections follow the master's publisher list (registerSubscriber, publisherUpdate)."""
        wanted = set(uris)
        with self.lock:
            if self.closed:
                return
            gone = [conn for uri, conn in self._inbound.items() if uri not in wanted]
            for conn in gone:
                del self._inbound[conn.pub_uri]
            for uri in uris:
                if uri not in self._inbound:
                    self._inbound[uri] = _Inbound(self, uri)
        for conn in gone:
            conn.close()

    def add_publishers(self, uris: list[str]) -> None:
        """Connect to the publishers in ``uris`` not connected yet, keeping every other connection.

        For a master that restarted: publishers that have not registered again yet (rospy's
        never do) keep their connections until a publisherUpdate leaves them out.
        """
        with self.lock:
            known = list(self._inbound)
        self.update_publishers(known + [uri for uri in uris if uri not in known])

    def forget(self, conn: _Inbound) -> None:
        """A connection thread ended: drop it so a later publisherUpdate can start a new one."""
        with self.lock:
            if self._inbound.get(conn.pub_uri) is conn:
                del self._inbound[conn.pub_uri]

    @property
    def publisher_uris(self) -> list[str]:
        """The publishers with a live connection now."""
        with self.lock:
            return [uri for uri, conn in self._inbound.items() if conn.connected]

    def bus_info(self) -> list[list[Any]]:
        """Rows for getBusInfo: ``[id, publisher callerid, 'i', 'TCPROS', topic, connected, text]``."""
        with self.lock:
            # the publisher's callerid once known, as roscpp reports it (rosnode info: "from: /talker")
            return [[c.id, c.callerid or c.pub_uri, "i", "TCPROS", self.topic, c.connected, c.info]
                    for c in self._inbound.values()]

    def bus_stats(self) -> list[Any]:
        """The subscriber row of getBusStats: ``[topic, [[id, bytes, drop estimate, connected], ...]]``."""
        with self.lock:
            return [self.topic, [[c.id, c.bytes_received, -1, c.connected] for c in self._inbound.values()]]

    def close(self) -> None:
        """Close every connection and wait for their threads."""
        with self.lock:
            self.closed = True
            conns, self._inbound = list(self._inbound.values()), {}
        for conn in conns:
            conn.close()
        for conn in conns:
            if conn.thread is not threading.current_thread():
                conn.thread.join(timeout=5)
