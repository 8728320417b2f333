"""A hand-written little-endian CDR codec for tf2_msgs/TFMessage, the bus's hot path.

Its bytes equal rosbags' for every message (tests/msgs prove it on random messages); any
value it cannot pack is handed back to the caller, which reports it through the generic
path so the error names the field. Layout (offsets relative to the body, after the 4-byte
encapsulation header): uint32 count, then per transform: int32 sec, uint32 nanosec,
string frame_id, string child_frame_id (uint32 length counting a NUL terminator, bytes,
NUL), padding to 8, seven float64 (translation x y z, rotation x y z w).
"""

from __future__ import annotations

import struct
from typing import Any

from robotmodel.errors import MessageError
from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.msgs.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
from robotmodel.msgs.std_msgs import Header
from robotmodel.msgs.tf2_msgs import TFMessage

__all__ = ["CannotPack", "decode_tfmessage", "encode_tfmessage"]

_HEADER_LE = b"\x00\x01\x00\x00"
_U32 = struct.Struct("<I")
_STAMP_LEN = struct.Struct("<iII")
_POSE = struct.Struct("<7d")
_ZEROS = [b"\x00" * n for n in range(9)]
# Smallest encoded transform: stamp 8, two empty strings (4 + 1, padded), 7 doubles.
_MIN_TRANSFORM = 8 + 8 + 5 + 56


class CannotPack(Exception):
    """The fast path could not pack a value; the caller reports it with the field path."""


def encode_tfmessage(msg: TFMessage) -> bytes:
    """CDR bytes (with the little-endian encapsulation header) of a TFMessage."""
    transforms = msg.transforms
    out = [_HEADER_LE, _U32.pack(len(transforms))]
    append = out.append
    pos = 4  # body offset; each transform starts 4-aligned (after doubles, 8-aligned)
    try:
        for t in transforms:
            header = t.header
            stamp = header.stamp
            frame = header.frame_id.encode()
            child = t.child_frame_id.encode()
            n1 = len(frame) + 1
            pos += 12 + n1
            pad1 = -pos % 4
            pos += pad1 + 4 + len(child) + 1
            pad2 = -pos % 8
            pos += pad2 + 56
            tr = t.transform.translation
            rot = t.transform.rotation
            append(_STAMP_LEN.pack(stamp.sec, stamp.nanosec, n1))
            append(frame)
            append(_ZEROS[1 + pad1])
            append(_U32.pack(len(child) + 1))
            append(child)
            append(_ZEROS[1 + pad2])
            append(_POSE.pack(tr.x, tr.y, tr.z, rot.x, rot.y, rot.z, rot.w))
    except (struct.error, AttributeError, TypeError, UnicodeEncodeError) as exc:
        raise CannotPack(str(exc)) from exc
    return b"".join(out)


def _string(data: bytes | memoryview, off: int, end: int) -> tuple[str, int]:
    (n,) = _U32.unpack_from(data, off)
    off += 4
    if n == 0 or off + n > end:
        raise MessageError(f"invalid string length {n} at offset {off - 8}")
    if data[off + n - 1] != 0:
        raise MessageError(f"missing string terminator at offset {off + n - 5}")
    return bytes(data[off:off + n - 1]).decode(), off + n


def decode_tfmessage(data: Any) -> TFMessage:
    """The TFMessage in little-endian CDR ``data`` (with its encapsulation header).

    Raises :class:`MessageError` when the bytes do not hold a TFMessage.
    """
    end = len(data)
    try:
        (count,) = _U32.unpack_from(data, 4)
        if count > (end - 8) // _MIN_TRANSFORM:
            raise MessageError(f"invalid sequence length {count} for {end} bytes")
        transforms = []
        off = 8  # absolute; body alignment is relative to offset 4
        for _ in range(count):
            off += -(off - 4) % 4
            sec, nanosec = struct.unpack_from("<iI", data, off)
            frame, off = _string(data, off + 8, end)
            off += -(off - 4) % 4
            child, off = _string(data, off, end)
            off += -(off - 4) % 8
            x, y, z, qx, qy, qz, qw = _POSE.unpack_from(data, off)
            off += 56
            transforms.append(TransformStamped(Header(Time(sec, nanosec), frame), child,
                                               Transform(Vector3(x, y, z), Quaternion(qx, qy, qz, qw))))
    except (struct.error, UnicodeDecodeError) as exc:
        raise MessageError(f"cannot decode tf2_msgs/msg/TFMessage: {exc}") from None
    return TFMessage(transforms)


def is_little_endian_cdr(data: Any) -> bool:
    """Whether ``data`` starts with the CDR_LE encapsulation header this codec reads."""
    return len(data) >= 8 and bytes(data[:2]) == b"\x00\x01"
