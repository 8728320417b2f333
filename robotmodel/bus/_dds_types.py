"""ROS 2's names and types on DDS: ``rt/`` topics, ``dds_`` type names, and Cyclone topic types built from rosbags.

Payloads cross cyclonedds-python as raw CDR: the binding's C layer (``_clayer``) writes the
bytes it is given (4-byte encapsulation header included) and hands back the bytes it
received, so no sample is ever rebuilt in Python. What it needs from Python is a topic
*type*: an ``IdlStruct`` whose name is ROS's DDS type name (``std_msgs::msg::dds_::String_``)
and whose fields are the message's, because Cyclone derives from it the XTypes type
information it announces in discovery, and checks each sample written or received against
it (a payload that does not parse as the type is refused, never delivered). So each ROS
type gets one struct, built once from rosbags' field definitions of the Jazzy typestore
(nested types become nested structs with their own ``dds_`` names, ROS ``char`` is IDL
``uint8`` and ``byte`` is ``octet``, as rosidl maps them; constants are not fields).

Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import threading
from typing import Any

from cyclonedds.idl import IdlStruct, make_idl_struct
from cyclonedds.idl import types as t

from robotmodel.bus._names import dds_type_name
from robotmodel.errors import BusError

__all__ = [
    "CYCLONE_VENDOR",
    "TOPIC_PREFIX",
    "dds_topic_name",
    "idl_type",
    "reply_topic_name",
    "request_topic_name",
    "ros_topic_name",
]

#: The vendor id Cyclone DDS puts at the start of its GUIDs (RTPS 2.5, 9.3.1.5: Eclipse 01.10).
CYCLONE_VENDOR = b"\x01\x10"
#: rmw's prefix for ROS topics on DDS (``rq``/``rr`` are services' request and reply).
TOPIC_PREFIX = "rt"


def request_topic_name(service: str) -> str:
    """``/add`` -> ``rq/addRequest``, the DDS topic a service's requests go on."""
    return "rq" + service + "Request"


def reply_topic_name(service: str) -> str:
    """``/add`` -> ``rr/addReply``, the DDS topic a service's replies go on."""
    return "rr" + service + "Reply"

_BASE: dict[str, Any] = {
    "bool": bool,
    "byte": t.byte,
    "char": t.uint8,
    "int8": t.int8,
    "uint8": t.uint8,
    "int16": t.int16,
    "uint16": t.uint16,
    "int32": t.int32,
    "uint32": t.uint32,
    "int64": t.int64,
    "uint64": t.uint64,
    "float32": t.float32,
    "float64": t.float64,
}
# cyclonedds' type annotations (indexed like generics at runtime, typed as plain classes).
_bounded_str: Any = t.bounded_str
_array: Any = t.array
_sequence: Any = t.sequence
_cache: dict[str, type[IdlStruct]] = {}
_lock = threading.RLock()


def dds_topic_name(topic: str) -> str:
    """``/ns/chatter`` -> ``rt/ns/chatter``, as rmw mangles a ROS topic for DDS."""
    return TOPIC_PREFIX + topic


def ros_topic_name(dds_name: str) -> str | None:
    """``rt/ns/chatter`` -> ``/ns/chatter``; None for DDS topics that are not ROS topics."""
    prefix = TOPIC_PREFIX + "/"
    return dds_name[len(TOPIC_PREFIX):] if dds_name.startswith(prefix) else None


def _store() -> Any:
    from robotmodel.msgs import typestore

    return typestore()


def _field_type(desc: tuple[Any, Any], owner: str) -> Any:
    kind, detail = desc
    name = getattr(kind, "name", str(kind))
    if name == "BASE":
        base, bound = detail
        if base == "string":
            return _bounded_str[bound] if bound else str
        if base == "wstring":
            raise BusError(f"message type '{owner}': wstring fields are not supported on DDS yet")
        return _BASE[base]
    if name == "NAME":
        return idl_type(detail)
    if name == "ARRAY":
        inner, size = detail
        return _array[_field_type(inner, owner), size]
    if name == "SEQUENCE":
        inner, bound = detail
        return _sequence[_field_type(inner, owner), bound] if bound else _sequence[_field_type(inner, owner)]
    raise BusError(f"message type '{owner}': unknown field kind {kind!r}")


def idl_type(typename: str, request_header: bool = False) -> type[IdlStruct]:
    """The Cyclone topic type of a ROS message type (``pkg/msg/Name``), built once; raises BusError.

    ``request_header``: a service request or reply as rmw_cyclonedds_cpp writes it: the
    client's 64-bit id and the request's sequence number, then the message. The type holds
    the header alone: Cyclone reads the message after it as trailing bytes and checks it
    no further (the codecs above do), so such a reader also takes another vendor's bare
    request without failing on it, which would keep Cyclone from giving that sample to the
    bare-typed reader that wants it (:mod:`._dds_service`).
    """
    key = typename + ("+header" if request_header else "")
    with _lock:
        found = _cache.get(key)
        if found is not None:
            return found
        store = _store()
        if typename not in store.fielddefs:
            raise BusError(f"unknown message type '{typename}': its definition is not in robotmodel's typestore")
        _consts, fields = store.fielddefs[typename]
        dds_name = dds_type_name(typename)
        members = {fname: _field_type(desc, typename) for fname, desc in fields}
        if not members:
            # rosidl gives an empty message one member, so its IDL struct is not empty.
            members = {"structure_needs_at_least_one_member": t.uint8}
        if request_header:
            members = {"rmw_request_guid": t.uint64, "rmw_request_seq": t.int64}
        cls: type[IdlStruct] = make_idl_struct(dds_name.replace("::", "_") + ("_h" if request_header else ""),
                                               dds_name, members)
        _cache[key] = cls
        return cls

