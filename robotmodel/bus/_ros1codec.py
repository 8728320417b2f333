"""ROS 1 codecs: robotmodel's (ROS 2-shaped) message classes to ROS 1 bytes and back.

The classes stay ROS 2's on every wire; only the bytes differ. A ROS 1 codec wraps the CDR
codec of the same class and converts at the byte level with rosbags (``cdr_to_ros1`` and
``ros1_to_cdr`` of the ROS 2 type store), which knows the two differences that matter
between the generations: ROS 1's ``std_msgs/Header`` has a ``seq`` (written 0, dropped when
read) and ROS 1's ``time``/``duration`` are ROS 2's ``builtin_interfaces`` Time/Duration
with the same bytes. The ROS 1 name, md5sum and full definition (the TCPROS connection
header) come from Noetic's type store (:func:`robotmodel.ros1.message_type`).

``/tf`` has a hand path (tf2_msgs/TFMessage as messages or as :class:`TFRecords`): ROS 1
lays it out without alignment: uint32 count, then per transform: Header (uint32 seq, uint32
secs, uint32 nsecs, string frame_id), string child_frame_id (uint32 length, bytes, no NUL),
seven float64.
"""

from __future__ import annotations

import struct
from collections.abc import Callable, Iterable, Sequence
from typing import Any, TypeVar

from robotmodel.bus._backend import ROS1, MessageType
from robotmodel.bus._codec import Codec, TFRecords, codec_for, typestore
from robotmodel.errors import BusError, MessageError, Ros1Error

__all__ = ["Ros1Codec", "Ros1TFCodec", "ros1_codec"]

_TFMESSAGE = "tf2_msgs/msg/TFMessage"
_NS = 1_000_000_000
_U32 = struct.Struct("<I")
_HEADER = struct.Struct("<IIII")  # seq, secs, nsecs, frame_id length
_POSE = struct.Struct("<7d")
# Smallest transform: header 16, empty child 4, pose 56.
_MIN_TRANSFORM = 16 + 4 + 56
T = TypeVar("T")
Item = tuple[int, int, str, str, Sequence[float]]


def _ros1_type(typename: str) -> MessageType:
    from robotmodel.ros1 import message_type

    try:
        r1 = message_type(typename)
    except Ros1Error as exc:
        raise BusError(f"no ROS 1 counterpart of {typename}: {exc}") from None
    return MessageType(typename, "", r1.md5sum, r1.definition)


class Ros1Codec(Codec):
    """ROS 1 bytes for a class whose CDR codec is ``cdr`` (byte-level conversion by rosbags)."""

    encoding = ROS1

    def __init__(self, cdr: Codec) -> None:
        self.typename = cdr.typename
        self._cdr = cdr
        self._store = typestore()
        if self.typename not in self._store.fielddefs:
            raise BusError(f"unknown message type '{self.typename}'")
        self._mtype = _ros1_type(self.typename)

    def message_type(self) -> MessageType:
        """The type with its ROS 1 md5sum and definition (see :class:`robotmodel.bus.MessageType`)."""
        return self._mtype

    def encode(self, msg: Any) -> bytes:
        """ROS 1 bytes of ``msg``."""
        from rosbags.serde import SerdeError

        try:
            return bytes(self._store.cdr_to_ros1(self._cdr.encode(msg), self.typename))
        except SerdeError as exc:
            raise MessageError(f"cannot encode {self.typename} for ROS 1: {exc}") from None

    def decode(self, data: bytes | memoryview) -> Any:
        """The message ROS 1 bytes ``data`` hold; :class:`MessageError` when they hold none."""
        from rosbags.serde import SerdeError

        try:
            cdr = self._store.ros1_to_cdr(data, self.typename)
        except (SerdeError, UnicodeDecodeError, IndexError, ValueError) as exc:
            raise MessageError(f"cannot decode {len(data)} bytes as ROS 1 {self.typename}: {exc}") from None
        return self._cdr.decode(cdr)

    def warm(self) -> None:
        """Build the conversions and the CDR codec now."""
        self._cdr.warm()
        self._store.get_msgdef(self.typename)


def _encode(items: Iterable[Item]) -> bytes:
    out = [b""]
    append = out.append
    count = 0
    try:
        for sec, nanosec, frame_id, child_id, pose in items:
            frame = frame_id.encode()
            child = child_id.encode()
            append(_HEADER.pack(0, sec, nanosec, len(frame)))
            append(frame)
            append(_U32.pack(len(child)))
            append(child)
            append(_POSE.pack(*pose))
            count += 1
    except (struct.error, AttributeError, TypeError, ValueError) as exc:
        raise MessageError(f"cannot encode {_TFMESSAGE} for ROS 1: {exc}") from None
    out[0] = _U32.pack(count)
    return b"".join(out)


def _decode(data: Any, make: Callable[[int, int, str, str, Any], T]) -> list[T]:
    if type(data) is not bytes:
        data = bytes(data)
    end = len(data)
    unpack_header, unpack_u32, unpack_pose = _HEADER.unpack_from, _U32.unpack_from, _POSE.unpack_from
    try:
        (count,) = unpack_u32(data, 0)
        if count > (end - 4) // _MIN_TRANSFORM:
            raise MessageError(f"ROS 1 {_TFMESSAGE}: invalid array length {count} for {end} bytes")
        out = []
        off = 4
        for _ in range(count):
            _seq, sec, nanosec, n1 = unpack_header(data, off)
            off += 16
            stop = off + n1
            if stop > end:
                raise MessageError(f"ROS 1 {_TFMESSAGE}: string beyond the end at offset {off}")
            frame = data[off:stop].decode()
            (n2,) = unpack_u32(data, stop)
            off = stop + 4
            stop = off + n2
            if stop > end:
                raise MessageError(f"ROS 1 {_TFMESSAGE}: string beyond the end at offset {off}")
            child = data[off:stop].decode()
            out.append(make(sec, nanosec, frame, child, unpack_pose(data, stop)))
            off = stop + 56
    except (struct.error, UnicodeDecodeError) as exc:
        raise MessageError(f"cannot decode ROS 1 {_TFMESSAGE}: {exc}") from None
    if off != end:
        raise MessageError(f"ROS 1 {_TFMESSAGE}: {end - off} bytes after the message's end")
    return out


class Ros1TFCodec(Codec):
    """The /tf hot path on ROS 1: TFMessage (``records=False``) or :class:`TFRecords` by hand."""

    encoding = ROS1

    def __init__(self, records: bool) -> None:
        from robotmodel.msgs import TFMessage, TFRecord
        from robotmodel.msgs._tfcodec import _make_message, _message_items

        self.typename = _TFMESSAGE
        self._records = records
        self._mtype = _ros1_type(_TFMESSAGE)
        self._message_items = _message_items
        self._make_message = _make_message
        self._tfmessage = TFMessage
        self._tfrecord = TFRecord

    def message_type(self) -> MessageType:
        """See :meth:`Ros1Codec.message_type`."""
        return self._mtype

    def encode(self, msg: Any) -> bytes:
        """ROS 1 bytes of a TFMessage (or of a list of TFRecord)."""
        if self._records:
            items: Iterable[Item] = ((*divmod(int(r[2]), _NS), r[0], r[1], r[3]) for r in msg)
        else:
            transforms = msg.transforms
            if type(transforms) is not list:  # the checked path names the bad field
                return Ros1Codec(codec_for(type(msg))).encode(msg)
            items = self._message_items(transforms)
        return _encode(items)

    def decode(self, data: bytes | memoryview) -> Any:
        """A TFMessage (or a list of TFRecord) from ROS 1 bytes."""
        if self._records:
            record = self._tfrecord
            return _decode(data, lambda sec, nsec, frame, child, pose: record(frame, child, sec * _NS + nsec, pose))
        return self._tfmessage(_decode(data, self._make_message))

    def warm(self) -> None:
        """Nothing is generated: the path is written by hand."""


def ros1_codec(msg_type: Any) -> Codec:
    """The ROS 1 codec of a message class or ROS type name (as :func:`codec_for` takes them)."""
    if msg_type is TFRecords:
        return Ros1TFCodec(records=True)
    if getattr(msg_type, "__msgtype__", None) == _TFMESSAGE and \
            getattr(msg_type, "__module__", "").startswith("robotmodel.msgs"):
        return Ros1TFCodec(records=False)
    return Ros1Codec(codec_for(msg_type))
