"""TCPROS framing: the connection header and length-prefixed frames.

A header is a 4-byte little-endian length followed by fields, each a 4-byte little-endian
length and ``key=value`` bytes (wiki.ros.org/ROS/Connection Header). Messages travel the same
way: a 4-byte length, then the serialized message.
"""

from __future__ import annotations

import socket
import struct
from collections.abc import Mapping

from robotmodel.errors import Ros1Error

__all__ = ["MAX_HEADER", "MAX_MESSAGE", "FrameReader", "decode_header", "encode_header", "read_frame", "read_header",
           "recv_exact", "write_header"]

#: Largest header accepted: definitions of big message types are tens of KiB; garbage such as
#: ``GET / HTTP`` reads as a length of half a gigabyte and must not be waited for.
MAX_HEADER = 1 << 20
#: Largest message accepted (roscpp refuses above 1 GB as well).
MAX_MESSAGE = 1 << 30

_LEN = struct.Struct("<I")


def encode_header(fields: Mapping[str, str]) -> bytes:
    """The header bytes (outer length included) of ``fields``."""
    body = bytearray()
    for key, value in fields.items():
        if not key or "=" in key:
            raise Ros1Error(f"connection header field name {key!r} is empty or holds '='")
        field = f"{key}={value}".encode()
        body += _LEN.pack(len(field)) + field
    return _LEN.pack(len(body)) + bytes(body)


def decode_header(body: bytes) -> dict[str, str]:
    """The fields of a header's ``body`` (the bytes after its outer length).

    Raises :class:`Ros1Error` for a header without fields, a field running past the end, a
    field without ``=`` or bytes that are not UTF-8.
    """
    if not body:
        raise Ros1Error("connection header without fields")
    fields: dict[str, str] = {}
    off = 0
    while off < len(body):
        if off + 4 > len(body):
            raise Ros1Error(f"connection header truncated at byte {off} of {len(body)}")
        (size,) = _LEN.unpack_from(body, off)
        off += 4
        if off + size > len(body):
            raise Ros1Error(f"connection header field of {size} bytes runs past the header's {len(body)} bytes")
        raw = body[off : off + size]
        off += size
        try:
            text = raw.decode()
        except UnicodeDecodeError:
            raise Ros1Error(f"connection header field {raw[:40]!r} is not UTF-8") from None
        key, sep, value = text.partition("=")
        if not sep or not key:
            raise Ros1Error(f"connection header field {text[:60]!r} is not key=value")
        fields[key] = value
    return fields


def recv_exact(sock: socket.socket, size: int) -> bytes:
    """Exactly ``size`` bytes from ``sock``; :class:`EOFError` when the peer closes first."""
    chunks = bytearray()
    while len(chunks) < size:
        chunk = sock.recv(min(size - len(chunks), 1 << 20))
        if not chunk:
            raise EOFError(f"connection closed after {len(chunks)} of {size} bytes")
        chunks += chunk
    return bytes(chunks)


def read_frame(sock: socket.socket, limit: int = MAX_MESSAGE) -> bytes:
    """One length-prefixed frame; :class:`Ros1Error` when its length exceeds ``limit``."""
    (size,) = _LEN.unpack(recv_exact(sock, 4))
    if size > limit:
        raise Ros1Error(f"frame of {size} bytes exceeds the limit of {limit}")
    return recv_exact(sock, size)


class FrameReader:
    """Length-prefixed frames from ``sock`` through one buffer: one ``recv`` serves many small frames.

    Reading each frame as two exact reads costs two system calls per message, which bounds a
    /tf subscriber's rate; a buffer takes whatever the socket holds and cuts frames from it.
    """

    _CHUNK = 1 << 16

    def __init__(self, sock: socket.socket, limit: int = MAX_MESSAGE) -> None:
        self._sock = sock
        self._limit = limit
        self._buf = b""
        self._pos = 0

    def _fill(self) -> None:
        chunk = self._sock.recv(self._CHUNK)
        if not chunk:
            raise EOFError(f"connection closed with {len(self._buf) - self._pos} bytes of a frame read")
        self._buf = self._buf[self._pos:] + chunk
        self._pos = 0

    def read(self) -> bytes:
        """The next frame; :class:`Ros1Error` when its length exceeds the limit, EOFError at the end."""
        while len(self._buf) - self._pos < 4:
            self._fill()
        (size,) = _LEN.unpack_from(self._buf, self._pos)
        if size > self._limit:
            raise Ros1Error(f"frame of {size} bytes exceeds the limit of {self._limit}")
        start = self._pos + 4
        have = len(self._buf) - start
        if have < size and size > self._CHUNK:
            # a large message: read its rest exactly rather than through the buffer
            frame = self._buf[start:] + recv_exact(self._sock, size - have)
            self._buf, self._pos = b"", 0
            return frame
        while len(self._buf) - self._pos - 4 < size:
            self._fill()
        start = self._pos + 4
        self._pos = start + size
        return self._buf[start:self._pos]


def read_header(sock: socket.socket) -> dict[str, str]:
    """Read and decode one connection header from ``sock``."""
    return decode_header(read_frame(sock, MAX_HEADER))


def write_header(sock: socket.socket, fields: Mapping[str, str]) -> None:
    """Send the connection header of ``fields`` on ``sock``."""
    sock.sendall(encode_header(fields))
