"""CDR through rosbags' generated (de)serializers: every message type, either byte order.

The layer under :mod:`._cdr` (which sends TFMessage through the hand-written codec first)
and under :mod:`._tfcodec`'s rare big-endian path; it knows nothing of either.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robotmodel.errors import MessageError
from robotmodel.msgs._convert import Message, from_rosbags, message_class, to_rosbags, typestore

if TYPE_CHECKING:
    from rosbags.typesys.store import Typestore

__all__ = ["deserialize_generic", "msgtype_name", "serialize_generic"]


def msgtype_name(msgtype: str | type[Any]) -> str:
    """The ROS type name of ``msgtype`` (a name already, or a class with ``__msgtype__``)."""
    return msgtype if isinstance(msgtype, str) else str(msgtype.__msgtype__)


def serialize_generic(msg: Message, store: Typestore | None = None) -> bytes:
    """CDR bytes of ``msg`` (little-endian, with its encapsulation header) through rosbags.

    Raises :class:`MessageError` naming the field when a value does not fit its ROS type.
    """
    store = store if store is not None else typestore()
    msgtype = type(msg).__msgtype__
    obj = to_rosbags(msg, store)
    try:
        return bytes(store.serialize_cdr(obj, msgtype))
    except UnicodeEncodeError as exc:
        raise MessageError(f"{msgtype}: a string is not valid UTF-8 ({exc.reason})") from None


def deserialize_generic(data: bytes | bytearray | memoryview, msgtype: str | type[Any],
                        store: Typestore | None = None) -> Any:
    """The message of type ``msgtype`` in CDR ``data`` (either byte order), through rosbags.

    Raises :class:`MessageError` when the type is unknown or the bytes do not decode as it.
    """
    name = msgtype_name(msgtype)
    message_class(name)  # an unknown type fails here, before decoding
    store = store if store is not None else typestore()
    from rosbags.serde import SerdeError

    try:
        obj = store.deserialize_cdr(data if isinstance(data, bytes | memoryview) else bytes(data), name)
    except (SerdeError, UnicodeDecodeError) as exc:
        raise MessageError(f"cannot decode {len(data)} bytes as {name}: {exc}") from None
    return from_rosbags(obj)
