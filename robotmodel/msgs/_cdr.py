"""CDR encoding of messages (the payload of ROS 2 topics and bags), through rosbags.

TFMessage takes a hand-written path with the same bytes; every other type goes through
rosbags' generated (de)serializers (:mod:`._generic_cdr`).
"""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING, Any

from robotmodel.msgs._convert import Message, message_class, typestore
from robotmodel.msgs._generic_cdr import deserialize_generic, msgtype_name, serialize_generic
from robotmodel.msgs._tfcodec import CannotPack, decode_tfmessage, encode_tfmessage, is_little_endian_cdr
from robotmodel.msgs.tf2_msgs import TFMessage

if TYPE_CHECKING:
    from rosbags.typesys.store import Typestore

__all__ = ["deserialize", "serialize", "type_hash"]

_TF = TFMessage.__msgtype__


def serialize(msg: Message, store: Typestore | None = None) -> bytes:
    """CDR bytes of ``msg``, with the 4-byte little-endian encapsulation header, as ROS 2 sends them.

    Raises :class:`MessageError` naming the field when a value does not fit its ROS type.
    """
    if store is None and type(msg) is TFMessage:
        try:
            return encode_tfmessage(msg)
        except CannotPack:
            pass  # the generic path below reports the field at fault
    return serialize_generic(msg, store)


def deserialize(data: bytes | bytearray | memoryview, msgtype: str | type[Any], store: Typestore | None = None) -> Any:
    """The message of type ``msgtype`` (a name or a class here) in CDR ``data``.

    Raises :class:`MessageError` when the bytes do not decode as that type.
    """
    if store is None and (msgtype is TFMessage or msgtype == _TF) and is_little_endian_cdr(data):
        return decode_tfmessage(data)
    return deserialize_generic(data, msgtype, store)


@cache
def _hash(name: str) -> str:
    return str(typestore().hash_rihs01(name))


def type_hash(msgtype: str | type[Any]) -> str:
    """REP-2011 type hash of a message type (``RIHS01_<sha256 hex>``), from the Jazzy typestore."""
    name = msgtype_name(msgtype)
    message_class(name)
    return _hash(name)
