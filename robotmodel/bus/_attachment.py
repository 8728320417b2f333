"""The attachment rmw_zenoh puts on every sample: sequence number, source time and publisher GID.

rmw_zenoh serializes ``(int64 sequence_number, int64 source_timestamp_ns, uint8[16] gid)``
with zenoh-ext's serializer: two little-endian int64, then the array as a sequence, i.e. a
LEB128 length (one byte, 0x10) followed by the 16 bytes. 33 bytes in all.
"""

from __future__ import annotations

import struct
from typing import NamedTuple

from robotmodel.bus._errors import BusError

__all__ = ["ATTACHMENT_SIZE", "Attachment"]

_HEAD = struct.Struct("<qqB")
ATTACHMENT_SIZE = _HEAD.size + 16
_GID_LEN = 16


class Attachment(NamedTuple):
    """A decoded attachment: per-publisher sequence number (from 1), send time (ns), GID."""

    sequence_number: int
    source_timestamp_ns: int
    gid: bytes

    def encode(self) -> bytes:
        """The 33 bytes rmw_zenoh writes."""
        if len(self.gid) != _GID_LEN:
            raise BusError(f"a GID is 16 bytes, got {len(self.gid)}")
        return _HEAD.pack(self.sequence_number, self.source_timestamp_ns, _GID_LEN) + self.gid

    @classmethod
    def decode(cls, data: bytes) -> Attachment:
        """Read the 33 bytes back; raises BusError when they are not an rmw_zenoh attachment."""
        if len(data) != ATTACHMENT_SIZE:
            raise BusError(f"attachment of {len(data)} bytes, expected {ATTACHMENT_SIZE}")
        seq, stamp, n = _HEAD.unpack_from(data)
        if n != _GID_LEN:
            raise BusError(f"attachment GID length {n}, expected {_GID_LEN}")
        return cls(seq, stamp, bytes(data[_HEAD.size:]))
