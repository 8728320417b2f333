"""Message classes to wire bytes and back, with the ROS type name and RIHS01 hash the wires need.

A codec serves one encoding (MCAP's names: ``"cdr"``, ``"ros1"``); the node layer asks for
the one its wire declares (:attr:`robotmodel.bus.Backend.encoding`). The ROS 1 codecs of
the same classes live in :mod:`._ros1codec`, registered by the package with
:func:`register_encoding`; single codecs plug in with :func:`register_codec`.

:mod:`robotmodel.msgs` classes go through its ``serialize``/``deserialize`` (rosbags, and a
hand-written TFMessage path with the same bytes); ROS type names mean rosbags' own classes.
Either way the payload starts with the 4-byte encapsulation header ``00 01 00 00`` that
rmw_zenoh puts on the wire. Other message classes plug in through :func:`register_codec`.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from functools import cache
from typing import Any

from robotmodel.bus._backend import CDR, MessageType
from robotmodel.errors import BusError, MessageError

__all__ = [
    "KNOWN_TYPE_HASHES",
    "Codec",
    "MsgsCodec",
    "RosbagsCodec",
    "TFRecords",
    "codec_for",
    "register_codec",
    "register_encoding",
    "typestore",
]


def typestore() -> Any:
    """The shared rosbags ROS 2 Jazzy typestore (built once, ~90 ms; the one robotmodel.msgs uses)."""
    from robotmodel.msgs import typestore as msgs_typestore

    return msgs_typestore()


class Codec:
    """Turns messages of one ROS type into CDR payloads (with header) and back.

    Subclasses set ``typename`` (``pkg/msg/Name``) and implement :meth:`encode` and
    :meth:`decode`; ``type_hash`` defaults to rosbags' RIHS01 hash of the type. ``encoding``
    is the serialization the codec writes (``"cdr"`` here).
    """

    typename: str = ""
    encoding: str = CDR

    def message_type(self) -> MessageType:
        """The type as the wires name it (see :class:`robotmodel.bus.MessageType`)."""
        return MessageType(self.typename, self.type_hash)

    @property
    def type_hash(self) -> str:
        """The RIHS01 type hash text used in keys and tokens."""
        return _type_hash(self.typename)

    def encode(self, msg: Any) -> bytes:
        """CDR bytes, starting with the encapsulation header."""
        raise NotImplementedError

    def decode(self, data: bytes | memoryview) -> Any:
        """The message; raises :class:`MessageError` on bytes that are not a valid message."""
        raise NotImplementedError

    def warm(self) -> None:
        """Build generated (de)serializers now, so the first messages are not late."""


# RIHS01 hashes of the types the tools publish, so they start without building the
# typestore (~0.2 s); tests/bus check each against rosbags' hash_rihs01.
KNOWN_TYPE_HASHES = {
    "tf2_msgs/msg/TFMessage": "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087",
    "geometry_msgs/msg/TransformStamped": "RIHS01_0a241f87d04668d94099cbb5ba11691d5ad32c2f29682e4eb5653424bd275206",
    "std_msgs/msg/String": "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18",
    "sensor_msgs/msg/JointState": "RIHS01_a13ee3a330e346c9d87b5aa18d24e11690752bd33a0350f11c5882bc9179260e",
}


@cache
def _type_hash(typename: str) -> str:
    known = KNOWN_TYPE_HASHES.get(typename)
    if known is not None:
        return known
    try:
        return str(typestore().hash_rihs01(typename))
    except KeyError as exc:
        raise BusError(f"unknown message type '{typename}'") from exc


class RosbagsCodec(Codec):
    """CDR through rosbags; ``to_ros``/``from_ros`` adapt other classes to rosbags' ones."""

    def __init__(self, typename: str, to_ros: Callable[[Any], Any] | None = None,
                 from_ros: Callable[[Any], Any] | None = None) -> None:
        store = typestore()
        if typename not in store.fielddefs:
            raise BusError(f"unknown message type '{typename}'")
        self.typename = typename
        self._to_ros = to_ros
        self._from_ros = from_ros
        self._store = store

    def encode(self, msg: Any) -> bytes:
        """See :meth:`Codec.encode`."""
        obj = self._to_ros(msg) if self._to_ros else msg
        return bytes(self._store.serialize_cdr(obj, self.typename))

    def decode(self, data: bytes | memoryview) -> Any:
        """See :meth:`Codec.decode`."""
        from rosbags.serde import SerdeError

        try:
            obj = self._store.deserialize_cdr(data, self.typename)
        except (SerdeError, UnicodeDecodeError) as exc:
            # rosbags reports every malformed buffer as SerdeError; text fields may also fail UTF-8.
            raise MessageError(f"cannot decode {len(data)} bytes as {self.typename}: {exc}") from None
        return self._from_ros(obj) if self._from_ros else obj

    def warm(self) -> None:
        """Generate the serializers of the type and of every type it nests."""
        _warm_rosbags(self._store, self.typename)


def _warm_rosbags(store: Any, typename: str) -> None:
    seen: set[str] = set()
    todo = [typename]
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        store.get_msgdef(name)
        for _field, desc in store.fielddefs[name][1]:
            todo.extend(_nested_names(desc))


class MsgsCodec(Codec):
    """CDR for a :mod:`robotmodel.msgs` class (its fast TFMessage path included)."""

    def __init__(self, cls: type[Any]) -> None:
        from robotmodel import msgs

        self.typename = str(cls.__msgtype__)
        self._cls = cls
        self._serialize = msgs.serialize
        self._deserialize = msgs.deserialize

    def encode(self, msg: Any) -> bytes:
        """See :meth:`Codec.encode`."""
        return self._serialize(msg)

    def decode(self, data: bytes | memoryview) -> Any:
        """See :meth:`Codec.decode`."""
        return self._deserialize(data, self._cls)

    def warm(self) -> None:
        """Build rosbags' (de)serializers and robotmodel's converters for the type now."""
        if self.typename != _TFMESSAGE:  # TFMessage has its own codec, no generated code
            _warm_rosbags(typestore(), self.typename)
        self.decode(self.encode(self._cls()))


class TFRecords:
    """Message type standing for a TFMessage read and written as a list of ``TFRecord``.

    ``TFRecord(parent, child, stamp_ns, pose)`` with ``pose`` as (x, y, z, qx, qy, qz, qw):
    the form ``Buffer.insert`` takes, without building message objects (the /tf hot path).
    Same key, same bytes as :class:`robotmodel.msgs.TFMessage`.
    """

    __msgtype__ = "tf2_msgs/msg/TFMessage"


class _TFRecordsCodec(Codec):
    def __init__(self) -> None:
        from robotmodel import msgs

        self.typename = TFRecords.__msgtype__
        self._encode = msgs.encode_tf_records
        self._decode = msgs.decode_tf_records

    def encode(self, msg: Any) -> bytes:
        return self._encode(msg)

    def decode(self, data: bytes | memoryview) -> Any:
        return self._decode(data)

    def warm(self) -> None:
        self.decode(self.encode([]))


def _nested_names(desc: Any) -> list[str]:
    # rosbags field descriptors: (NODETYPE, payload); NAME=2 nests a message directly,
    # ARRAY/SEQUENCE=3/4 wrap another descriptor.
    kind, payload = desc
    if kind == 2:
        return [payload]
    if kind in (3, 4):
        return _nested_names(payload[0])
    return []


_TFMESSAGE = "tf2_msgs/msg/TFMessage"
_registry: dict[tuple[Any, str], Codec] = {}
_lock = threading.Lock()


# Encoding -> the factory of its codecs (encodings other than CDR; see register_encoding).
_factories: dict[str, Callable[[Any], Codec]] = {}


def register_encoding(encoding: str, factory: Callable[[Any], Codec]) -> None:
    """Make codecs for ``encoding`` with ``factory(msg_type)`` (``robotmodel.bus`` registers ``"ros1"``)."""
    with _lock:
        _factories[encoding] = factory


def register_codec(msg_type: Any, codec: Codec) -> None:
    """Use ``codec`` for messages of ``msg_type`` (a class or a ROS type name) in ``codec.encoding``."""
    with _lock:
        _registry[(msg_type, codec.encoding)] = codec


def codec_for(msg_type: Any, encoding: str = CDR) -> Codec:
    """The codec of a message class (with ``__msgtype__``) or of a ROS type name, for ``encoding``.

    A type name (``'tf2_msgs/msg/TFMessage'``) means rosbags' own message classes.
    """
    with _lock:
        found = _registry.get((msg_type, encoding))
    if found is not None:
        return found
    if encoding != CDR:
        factory = _factories.get(encoding)
        if factory is None:
            name = msg_type if isinstance(msg_type, str) else getattr(msg_type, "__msgtype__", repr(msg_type))
            known = "', '".join([CDR, *_factories])
            raise BusError(f"no {encoding} codec for {name} (encodings: '{known}')")
        codec: Codec = factory(msg_type)
        register_codec(msg_type, codec)
        return codec
    if isinstance(msg_type, str):
        codec = RosbagsCodec(msg_type)
    else:
        typename = getattr(msg_type, "__msgtype__", None)
        if not isinstance(typename, str):
            raise BusError(f"{msg_type!r} is not a message class (no __msgtype__)")
        codec = _codec_for_class(msg_type, typename)
    register_codec(msg_type, codec)
    return codec


def _codec_for_class(cls: type, typename: str) -> Codec:
    if cls.__module__.startswith("rosbags."):
        return RosbagsCodec(typename)
    if cls is TFRecords:
        return _TFRecordsCodec()
    to_ros = getattr(cls, "to_rosbags", None)
    from_ros = getattr(cls, "from_rosbags", None)
    # A class bringing its own rosbags conversion uses it (robotmodel.msgs' classes built from the typestore).
    if cls.__module__.startswith("robotmodel.msgs") and (to_ros is None or from_ros is None):
        return MsgsCodec(cls)
    if to_ros is None or from_ros is None:
        raise BusError(f"message class {cls.__qualname__} ({typename}) has no rosbags conversion")
    return RosbagsCodec(typename, to_ros, from_ros)
