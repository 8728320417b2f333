"""A hand-written little-endian CDR codec for tf2_msgs/TFMessage, the bus's hot path.

Its bytes equal rosbags' for every message (tests/msgs prove it on random messages, and
that its decoder accepts and refuses the same damaged bytes). A value it cannot pack is
handed back to the caller (:class:`CannotPack`), which reports it through the generic
path so the error names the field. Layout (alignment relative to the body, after the
4-byte encapsulation header): uint32 count, then per transform: int32 sec, uint32
nanosec, string frame_id, string child_frame_id (uint32 length counting a NUL
terminator, bytes, NUL; padded to 4), padding to 8, seven float64 (translation x y z,
rotation x y z w).

Besides messages, it reads and writes :class:`TFRecord` tuples (parent, child, stamp in
ns, pose), which feed a buffer's message-free ``insert`` without building six message
objects per transform.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Any, NamedTuple, TypeVar

from robotmodel.errors import MessageError
from robotmodel.msgs._generic_cdr import deserialize_generic
from robotmodel.msgs.builtin_interfaces import Time
from robotmodel.msgs.geometry_msgs import Quaternion, Transform, TransformStamped, Vector3
from robotmodel.msgs.std_msgs import Header
from robotmodel.msgs.tf2_msgs import TFMessage

__all__ = ["CannotPack", "TFRecord", "decode_tf_records", "decode_tfmessage", "encode_tf_records",
           "encode_tfmessage", "is_little_endian_cdr"]

_NS = 1_000_000_000
_HEADER_LE = b"\x00\x01\x00\x00"
_U32 = struct.Struct("<I")
_STAMP_LEN = struct.Struct("<iII")
_POSE = struct.Struct("<7d")
_ZEROS = [b"\x00" * n for n in range(9)]
# Smallest encoded transform: stamp 8, two empty strings (4 + 1, padded), 7 doubles.
_MIN_TRANSFORM = 8 + 8 + 5 + 56

Pose7 = tuple[float, float, float, float, float, float, float]
T = TypeVar("T")


class TFRecord(NamedTuple):
    """One transform of a TFMessage without message objects: ``child``'s pose in ``parent``."""

    parent: str
    child: str
    stamp_ns: int
    pose: Pose7  # x, y, z, qx, qy, qz, qw


class CannotPack(Exception):
    """The fast path could not pack a value; the caller reports it with the field path."""


def _encode(items: Iterable[tuple[int, int, str, str, Sequence[float]]], count: int) -> bytes:
    out = [_HEADER_LE, _U32.pack(count)]
    append = out.append
    pos = 4  # body offset; each transform starts 4-aligned (after doubles, 8-aligned)
    try:
        for sec, nanosec, frame_id, child_id, pose in items:
            count -= 1
            frame = frame_id.encode()
            child = child_id.encode()
            n1 = len(frame) + 1
            pos += 12 + n1
            pad1 = -pos % 4
            pos += pad1 + 4 + len(child) + 1
            pad2 = -pos % 8
            pos += pad2 + 56
            append(_STAMP_LEN.pack(sec, nanosec, n1))
            append(frame)
            append(_ZEROS[1 + pad1])
            append(_U32.pack(len(child) + 1))
            append(child)
            append(_ZEROS[1 + pad2])
            append(_POSE.pack(*pose))
    except (struct.error, AttributeError, TypeError, ValueError) as exc:
        raise CannotPack(str(exc)) from exc
    if count:
        raise CannotPack("the transform count changed while encoding")
    return b"".join(out)


def _message_items(transforms: list[TransformStamped]) -> Iterator[tuple[int, int, str, str, Pose7]]:
    for t in transforms:
        header = t.header
        stamp = header.stamp
        tr = t.transform.translation
        rot = t.transform.rotation
        yield stamp.sec, stamp.nanosec, header.frame_id, t.child_frame_id, (tr.x, tr.y, tr.z, rot.x, rot.y, rot.z,
                                                                            rot.w)


def encode_tfmessage(msg: TFMessage) -> bytes:
    """CDR bytes (with the little-endian encapsulation header) of a TFMessage."""
    transforms = msg.transforms
    if type(transforms) is not list:
        raise CannotPack("transforms is not a list")  # the checked path takes other sequences
    return _encode(_message_items(transforms), len(transforms))


def _record_items(records: Iterable[TFRecord]) -> Iterator[tuple[int, int, str, str, Sequence[float]]]:
    for parent, child, stamp_ns, pose in records:
        sec, nanosec = divmod(int(stamp_ns), _NS)
        yield sec, nanosec, parent, child, pose


def encode_tf_records(records: Iterable[TFRecord]) -> bytes:
    """CDR bytes of the TFMessage holding ``records``, as :func:`serialize` gives for the message.

    Raises :class:`MessageError` naming the record for a value a TFMessage cannot carry
    (a stamp beyond int32 seconds, a pose that is not 7 numbers, a frame that is not a str).
    """
    if not isinstance(records, list | tuple):
        records = list(records)
    try:
        return _encode(_record_items(records), len(records))
    except CannotPack:
        pass
    for i, record in enumerate(records):
        try:
            _encode(_record_items([record]), 1)
        except CannotPack as exc:
            raise MessageError(f"tf2_msgs/msg/TFMessage: record {i} {record!r}: {exc}") from None
    raise MessageError("tf2_msgs/msg/TFMessage: the records cannot be encoded")


def _decode(data: Any, make: Callable[[int, int, str, str, Pose7], T]) -> list[T]:
    if type(data) is not bytes:
        data = bytes(data)
    end = len(data)
    unpack_stamp, unpack_u32, unpack_pose = _STAMP_LEN.unpack_from, _U32.unpack_from, _POSE.unpack_from
    try:
        (count,) = unpack_u32(data, 4)
        if count > (end - 8) // _MIN_TRANSFORM:
            raise MessageError(f"tf2_msgs/msg/TFMessage: invalid sequence length {count} for {end} bytes")
        out = []
        off = 8  # absolute; the body starts at 4, so 4-alignment is the same and 8-alignment is shifted
        for _ in range(count):
            off += -off % 4
            sec, nanosec, n1 = unpack_stamp(data, off)
            off += 12
            stop = off + n1
            if n1 == 0 or stop > end or data[stop - 1] != 0:
                raise MessageError(f"tf2_msgs/msg/TFMessage: invalid string at offset {off - 8}")
            frame = data[off:stop - 1].decode()
            off = stop + (-stop % 4)
            (n2,) = unpack_u32(data, off)
            off += 4
            stop = off + n2
            if n2 == 0 or stop > end or data[stop - 1] != 0:
                raise MessageError(f"tf2_msgs/msg/TFMessage: invalid string at offset {off - 8}")
            child = data[off:stop - 1].decode()
            off = stop + (-(stop - 4) % 8)
            out.append(make(sec, nanosec, frame, child, unpack_pose(data, off)))
            off += 56
    except (struct.error, UnicodeDecodeError) as exc:
        raise MessageError(f"cannot decode tf2_msgs/msg/TFMessage: {exc}") from None
    if off + 3 < end:
        # More than alignment padding left over: the count or a length is damaged. rosbags
        # refuses such bytes for every other type, so the fast path must too.
        raise MessageError(f"tf2_msgs/msg/TFMessage: {end - off} bytes after the message's end")
    return out


def _make_message(sec: int, nanosec: int, frame: str, child: str, p: Pose7) -> TransformStamped:
    return TransformStamped(Header(Time(sec, nanosec), frame), child,
                            Transform(Vector3(p[0], p[1], p[2]), Quaternion(p[3], p[4], p[5], p[6])))


def _make_record(sec: int, nanosec: int, frame: str, child: str, pose: Pose7) -> TFRecord:
    return TFRecord(frame, child, sec * _NS + nanosec, pose)


def decode_tfmessage(data: Any) -> TFMessage:
    """The TFMessage in little-endian CDR ``data`` (with its encapsulation header).

    Raises :class:`MessageError` when the bytes do not hold a TFMessage.
    """
    return TFMessage(_decode(data, _make_message))


def decode_tf_records(data: Any) -> list[TFRecord]:
    """The transforms of a CDR TFMessage as :class:`TFRecord` tuples (either byte order).

    Raises :class:`MessageError` when the bytes do not hold a TFMessage.
    """
    if is_little_endian_cdr(data):
        return _decode(data, _make_record)
    msg: TFMessage = deserialize_generic(data, TFMessage)  # big endian is rare: rosbags reads it
    return [_make_record(*item) for item in _message_items(msg.transforms)]


def is_little_endian_cdr(data: Any) -> bool:
    """Whether ``data`` starts with the CDR_LE encapsulation header this codec reads."""
    return len(data) >= 8 and data[0] == 0 and data[1] == 1
