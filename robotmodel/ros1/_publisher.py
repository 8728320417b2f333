"""The TCPROS publisher side: one TCP server per node, one queue and thread per subscriber.

As rospy does, a node serves every topic it publishes on one port; an inbound connection
names its topic in the header. The header is checked as rospy checks it and refused with
rospy's texts (``Client [...] wants topic [...] to have datatype/md5sum [...]``); a refusal is
sent back in an ``error`` field, and any refusal, garbage or header without fields closes that
connection with one log line. Each subscriber has its own queue that drops the oldest message
when the subscriber falls behind (a message goes straight to the socket while the queue is
empty and the socket takes it); a latched topic sends its last message to a late subscriber.
"""

from __future__ import annotations

import collections
import contextlib
import itertools
import logging
import socket
import struct
import threading
from collections.abc import Callable, Mapping
from typing import Any

from robotmodel.errors import Ros1Error
from robotmodel.ros1._header import read_header, write_header
from robotmodel.ros1._msgs import Ros1Type

__all__ = ["Publication", "TcprosServer"]

_log = logging.getLogger("robotmodel.ros1")
_LEN = struct.Struct("<I")

#: Seconds a new connection may take to send its header.
HEADER_TIMEOUT = 10.0

#: Connection ids are unique within the process, as getBusInfo wants them per node.
_connection_ids = itertools.count(1)


class _Outbound:
    """One subscriber's connection: a bounded queue and a writer thread."""

    def __init__(self, sock: socket.socket, topic: str, callerid: str, queue_size: int) -> None:
        self.sock = sock
        self.topic = topic
        self.callerid = callerid
        self.id = next(_connection_ids)
        self.bytes_sent = 0
        self.messages_sent = 0
        self.dropped = 0
        self.closed = False
        self._queue: collections.deque[bytes] = collections.deque(maxlen=max(1, queue_size))
        self._partial = b""  # the unsent rest of a frame begun in enqueue
        self._writing = True  # until the writer thread first waits
        self._wake = threading.Condition()
        peer = sock.getpeername()
        self.info = (f"TCPROS connection on port {sock.getsockname()[1]} to [{peer[0]}:{peer[1]} "
                     f"on socket {sock.fileno()}]")
        threading.Thread(target=self._write_loop, name=f"ros1-pub{topic}", daemon=True).start()
        threading.Thread(target=self._watch, name=f"ros1-watch{topic}", daemon=True).start()

    def enqueue(self, frame: bytes) -> None:
        with self._wake:
            if self.closed:
                return
            if not self._queue and not self._writing:
                # Idle connection: send now in the caller's thread, as far as the socket takes it
                # without waiting; handing every message to the writer thread costs a thread switch
                # (tens of microseconds) of latency. The writer sends what the socket did not take.
                try:
                    sent = self.sock.send(frame, socket.MSG_DONTWAIT)
                except (BlockingIOError, InterruptedError):
                    sent = 0
                except OSError:
                    sent = 0  # the writer meets the error and closes the connection
                self.bytes_sent += sent
                if sent == len(frame):
                    self.messages_sent += 1
                    return
                # The rest of a frame begun on the wire must follow it whole, never be dropped.
                self._partial = frame[sent:]
                self._writing = True
                self._wake.notify()
                return
            if len(self._queue) == self._queue.maxlen:
                self.dropped += 1
            self._queue.append(frame)
            self._wake.notify()

    def _write_loop(self) -> None:
        while True:
            with self._wake:
                while not self._queue and not self._partial and not self.closed:
                    self._writing = False
                    self._wake.wait()
                if self.closed:
                    return
                self._writing = True
                if self._partial:
                    frame, self._partial = self._partial, b""
                else:
                    frame = self._queue.popleft()
            try:
                self.sock.sendall(frame)
            except OSError as exc:
                if not self.closed:
                    _log.info("topic %s: subscriber %s went away: %s", self.topic, self.callerid, exc)
                self.close()
                return
            self.bytes_sent += len(frame)
            self.messages_sent += 1

    def _watch(self) -> None:
        """A subscriber sends nothing after its header: EOF (or anything else) ends the connection."""
        try:
            data = self.sock.recv(1)
        except OSError:
            data = b""
        if data and not self.closed:
            _log.warning("topic %s: subscriber %s sent data after its header; closing", self.topic, self.callerid)
        self.close()

    def close(self) -> None:
        with self._wake:
            if self.closed:
                return
            self.closed = True
            self._wake.notify_all()
        with contextlib.suppress(OSError):
            self.sock.shutdown(socket.SHUT_RDWR)
        self.sock.close()


class Publication:
    """A topic this node publishes: its subscribers' connections and, when latched, the last message."""

    def __init__(self, topic: str, msg_type: Ros1Type, callerid: str, *, latch: bool = False,
                 queue_size: int = 100) -> None:
        self.topic = topic
        self.type = msg_type
        self.callerid = callerid
        self.latch = latch
        self.queue_size = queue_size
        self.bytes_published = 0
        self._last: bytes | None = None
        self._connections: list[_Outbound] = []
        self._lock = threading.Lock()
        self.closed = False

    def publish(self, data: bytes) -> None:
        """Send serialized message ``data`` to every subscriber (and keep it when latched)."""
        frame = _LEN.pack(len(data)) + data
        with self._lock:
            if self.closed:
                raise Ros1Error(f"publisher of {self.topic} is closed")
            if self.latch:
                self._last = frame
            self._connections = [c for c in self._connections if not c.closed]
            connections = list(self._connections)
            self.bytes_published += len(data)
        for conn in connections:
            conn.enqueue(frame)

    @property
    def subscriber_count(self) -> int:
        """Subscribers connected now."""
        with self._lock:
            return sum(not c.closed for c in self._connections)

    def check(self, header: Mapping[str, str]) -> str | None:
        """The refusal text rospy gives for an inbound ``header``, or None when it may subscribe."""
        for required in ("topic", "md5sum", "callerid"):
            if required not in header:
                return f"Missing required '{required}' field"
        md5sum = header["md5sum"]
        if md5sum not in ("*", self.type.md5sum):
            requested = header.get("type", self.type.name)
            if requested != self.type.name:
                return f"topic types do not match: [{requested}] vs. [{self.type.name}]"
            return (f"Client [{header['callerid']}] wants topic [{self.topic}] to have datatype/md5sum "
                    f"[{requested}/{md5sum}], but our version has [{self.type.name}/{self.type.md5sum}] "
                    "Dropping connection.")
        return None

    def response_header(self) -> dict[str, str]:
        """The header this side answers an accepted subscriber with."""
        return {"callerid": self.callerid, "md5sum": self.type.md5sum, "type": self.type.name, "topic": self.topic,
                "message_definition": self.type.definition, "latching": "1" if self.latch else "0"}

    def add(self, sock: socket.socket, header: Mapping[str, str]) -> None:
        """Take an accepted connection: answer its header, send the latched message, queue the rest."""
        if header.get("tcp_nodelay", "0").strip() == "1":
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        write_header(sock, self.response_header())
        conn = _Outbound(sock, self.topic, header["callerid"], self.queue_size)
        with self._lock:
            if self.closed:
                conn.close()
                return
            if self._last is not None:
                conn.enqueue(self._last)
            self._connections.append(conn)

    def bus_info(self) -> list[list[Any]]:
        """Rows for getBusInfo: ``[id, subscriber callerid, 'o', 'TCPROS', topic, connected, text]``."""
        with self._lock:
            return [[c.id, c.callerid, "o", "TCPROS", self.topic, not c.closed, c.info] for c in self._connections
                    if not c.closed]

    def bus_stats(self) -> list[Any]:
        """The publisher row of getBusStats: ``[topic, bytes published, [[id, bytes, messages, connected], ...]]``."""
        with self._lock:
            return [self.topic, self.bytes_published,
                    [[c.id, c.bytes_sent, c.messages_sent, not c.closed] for c in self._connections]]

    def close(self) -> None:
        """Close every subscriber's connection."""
        with self._lock:
            self.closed = True
            connections, self._connections = self._connections, []
        for conn in connections:
            conn.close()


class TcprosServer:
    """The node's TCPROS server on ``bind``; ``lookup(topic)`` gives the :class:`Publication` of a topic."""

    def __init__(self, lookup: Callable[[str], Publication | None], *, host: str, bind: str,
                 callerid: str, topics: Callable[[], list[list[str]]]) -> None:
        self._lookup = lookup
        self._topics = topics
        self.callerid = callerid
        self.host = host
        try:
            self._sock = socket.create_server((bind, 0), backlog=64)
        except OSError as exc:
            raise Ros1Error(f"cannot serve TCPROS on {bind}: {exc}") from None
        self.port = int(self._sock.getsockname()[1])
        self._closed = threading.Event()
        threading.Thread(target=self._accept_loop, name="ros1-tcpros", daemon=True).start()

    def _accept_loop(self) -> None:
        while not self._closed.is_set():
            try:
                sock, addr = self._sock.accept()
            except OSError:
                return
            threading.Thread(target=self._handshake, args=(sock, addr), name="ros1-handshake", daemon=True).start()

    def _handshake(self, sock: socket.socket, addr: Any) -> None:
        peer = f"{addr[0]}:{addr[1]}"
        try:
            sock.settimeout(HEADER_TIMEOUT)
            header = read_header(sock)
        except (Ros1Error, EOFError, OSError) as exc:
            _log.warning("TCPROS connection from %s to %s closed: %s", peer, self.callerid, exc)
            sock.close()
            return
        error = self._refusal(header)
        if error is not None:
            _log.warning("Could not process inbound connection from %s: %s", peer, error)
            with contextlib.suppress(OSError):
                write_header(sock, {"error": error})
            sock.close()
            return
        publication = self._lookup(header["topic"])
        if publication is None:  # closed between the check and now
            sock.close()
            return
        try:
            sock.settimeout(None)
            publication.add(sock, header)
        except OSError as exc:
            _log.warning("TCPROS connection from %s closed during the handshake: %s", peer, exc)
            sock.close()

    def _refusal(self, header: Mapping[str, str]) -> str | None:
        if self._closed.is_set():
            return "node shutting down"
        if "topic" not in header:
            return "no topic or service name detected"
        publication = self._lookup(header["topic"])
        if publication is None:
            return f"[{self.callerid}] is not a publisher of [{header['topic']}]. Topics are {self._topics()}"
        return publication.check(header)

    def close(self) -> None:
        """Stop accepting connections."""
        self._closed.set()
        with contextlib.suppress(OSError):
            self._sock.shutdown(socket.SHUT_RDWR)
        self._sock.close()
