"""The attachment rmw_zenoh puts on every sample: sequence number, source time and publisher GID.

rmw_zenoh serializes ``(int64 sequence_number, int64 source_timestamp_ns, uint8[16] gid)``
with zenoh-ext's serializer: two little-endian int64, then the array as a sequence, i.e. a
LEB128 length (one byte, 0x10) followed by the 16 bytes. 33 bytes in all.

Reading, we do as rmw_zenoh's deserializer: the three fields are taken from the front and
whatever follows them is not looked at, so a longer attachment is still read. We also read
the form rmw_zenoh Jazzy wrote before 0.2.4 (ros2/rmw_zenoh#601), each field behind its
name as a zenoh-ext string: "sequence_number", int64, "source_timestamp", int64,
"source_gid", the GID sequence; 77 bytes. We never write it.
"""

from __future__ import annotations

import struct
from typing import NamedTuple

from robotmodel.errors import BusError

__all__ = ["ATTACHMENT_SIZE", "LABELLED_PREFIX", "Attachment", "AttachmentWriter", "is_attachment",
           "read_attachment", "unpack_attachment"]

_HEAD = struct.Struct("<qqB")
ATTACHMENT_SIZE = _HEAD.size + 16
_GID_LEN = 16
_GID_LEN_OFFSET = 16
_WHOLE = struct.Struct("<qqB16s")
# The labelled form: LEB128 length + name before each field.
_LABELLED = struct.Struct("<16sq17sq11sB16s")
_LABELS = (b"\x0fsequence_number", b"\x10source_timestamp", b"\x0asource_gid")


def _labelled(data: bytes) -> tuple[int, int, bytes] | None:
    # Its first 16 bytes read as today's int64 sequence number would be ~8e18: no clash.
    if len(data) < _LABELLED.size or not data.startswith(_LABELS[0]):
        return None
    seq_label, seq, stamp_label, stamp, gid_label, n, gid = _LABELLED.unpack_from(data)
    if (seq_label, stamp_label, gid_label) != _LABELS or n != _GID_LEN:
        return None
    return seq, stamp, gid


def is_attachment(data: bytes) -> bool:
    """Whether ``data`` starts with rmw_zenoh's attachment layout (the check on the hot path)."""
    return (len(data) >= ATTACHMENT_SIZE and data[_GID_LEN_OFFSET] == _GID_LEN) or _labelled(data) is not None


_unpack_whole = _WHOLE.unpack_from
#: How the labelled form starts (today's form never does unless its sequence number says so).
LABELLED_PREFIX = _LABELS[0]
#: Today's form in one call: (sequence number, source time, GID length, GID); the caller checks
#: the length (16), the size (>= ATTACHMENT_SIZE) and :data:`LABELLED_PREFIX` first.
unpack_attachment = _unpack_whole


def read_attachment(data: bytes | None) -> tuple[int, int, bytes] | None:
    """(sequence number, source time, GID) as rmw_zenoh reads them, or None where it drops the sample.

    The receive hot path: one unpack for today's form, :meth:`Attachment.decode` for the rest.
    """
    if data is None:
        return None
    if len(data) >= ATTACHMENT_SIZE and not data.startswith(_LABELS[0]):
        seq, stamp, n, gid = _unpack_whole(data)
        return (seq, stamp, gid) if n == _GID_LEN else None
    old = _labelled(data)
    return None if old is None else old


class AttachmentWriter:
    """Packs one publisher's attachments in a single call (the publish hot path)."""

    __slots__ = ("_gid", "_pack")

    def __init__(self, gid: bytes) -> None:
        if len(gid) != _GID_LEN:
            raise BusError(f"a GID is 16 bytes, got {len(gid)}")
        self._gid = gid
        self._pack = _WHOLE.pack

    def __call__(self, sequence_number: int, source_timestamp_ns: int) -> bytes:
        """The 33 bytes for one sample."""
        return self._pack(sequence_number, source_timestamp_ns, _GID_LEN, self._gid)


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
        """Read the first 33 bytes (or the labelled form); raises BusError on anything else."""
        old = _labelled(data)
        if old is not None:
            return cls(*old)
        if len(data) < ATTACHMENT_SIZE:
            raise BusError(f"attachment of {len(data)} bytes, expected at least {ATTACHMENT_SIZE}")
        seq, stamp, n = _HEAD.unpack_from(data)
        if n != _GID_LEN:
            raise BusError(f"attachment GID length {n}, expected {_GID_LEN}")
        return cls(seq, stamp, bytes(data[_HEAD.size:ATTACHMENT_SIZE]))
