"""Message and service classes built from the typestore, for packages robotmodel.msgs has no module of.

``message_class("rcl_interfaces/msg/ParameterDescriptor")`` is a dataclass with ROS's
defaults (0, '', False, empty sequences, zero-filled arrays, nested defaults) and its
constants as class attributes, converting to and from rosbags' class for the bus codecs
(``to_rosbags``/``from_rosbags``). ``service_class("example_interfaces/srv/AddTwoInts")``
has ``Request`` and ``Response`` such classes and names the service in ``__srvtype__``.
"""

from __future__ import annotations

import dataclasses
import functools
import threading
from typing import Any

from robotmodel.msgs._convert import typestore
from robotmodel.msgs._srvdefs import check_service_name, register_service_types

__all__ = ["message_class", "service_class"]

_lock = threading.RLock()
_classes: dict[str, type[Any]] = {}
_services: dict[str, type[Any]] = {}
_NUMERIC = {"bool": "bool", "byte": "uint8", "char": "uint8", "int8": "int8", "uint8": "uint8", "int16": "int16",
            "uint16": "uint16", "int32": "int32", "uint32": "uint32", "int64": "int64", "uint64": "uint64",
            "float32": "float32", "float64": "float64"}


def _kind(desc: Any) -> str:
    return str(getattr(desc[0], "name", desc[0]))


def _default(desc: Any) -> Any:
    kind, detail = _kind(desc), desc[1]
    if kind == "BASE":
        base = detail[0]
        return "" if base in ("string", "wstring") else False if base == "bool" else \
            0.0 if base.startswith("float") else 0
    if kind == "NAME":
        return message_class(detail)()
    if kind == "ARRAY":
        return [_default(detail[0]) for _ in range(detail[1])]
    return []


def _to_ros(desc: Any, value: Any) -> Any:
    import numpy as np

    kind, detail = _kind(desc), desc[1]
    if kind == "BASE":
        return value
    if kind == "NAME":
        return value.to_rosbags() if hasattr(value, "to_rosbags") else value
    inner = detail[0]
    if _kind(inner) == "BASE" and inner[1][0] in _NUMERIC:
        return np.array(list(value), dtype=_NUMERIC[inner[1][0]])
    return [_to_ros(inner, v) for v in value]


def _from_ros(desc: Any, value: Any) -> Any:
    kind, detail = _kind(desc), desc[1]
    if kind == "BASE":
        return value.item() if hasattr(value, "item") else value
    if kind == "NAME":
        return message_class(detail).from_rosbags(value)
    inner = detail[0]
    if _kind(inner) == "BASE":
        return [v.item() if hasattr(v, "item") else v for v in value]
    return [_from_ros(inner, v) for v in value]


def message_class(typename: str) -> type[Any]:
    """The dataclass of ``pkg/msg/Name`` (or a service's ``_Request``/``_Response``), built once."""
    with _lock:
        found = _classes.get(typename)
        if found is not None:
            return found
        store = typestore()
        consts, fields = store.fielddefs[typename]
        spec = [(name, Any, dataclasses.field(default_factory=functools.partial(_default, desc)))
                for name, desc in fields]
        rosbags_cls = store.types[typename]

        def to_rosbags(self: Any) -> Any:
            return rosbags_cls(**{name: _to_ros(desc, getattr(self, name)) for name, desc in fields})

        def from_rosbags(obj: Any) -> Any:
            return cls(**{name: _from_ros(desc, getattr(obj, name)) for name, desc in fields})

        namespace: dict[str, Any] = {"__msgtype__": typename, "to_rosbags": to_rosbags,
                                     "from_rosbags": staticmethod(from_rosbags)}
        for cname, _ctype, cvalue in consts:
            namespace[cname] = cvalue
        cls = dataclasses.make_dataclass(typename.rsplit("/", 1)[1], spec, namespace=namespace)
        cls.__module__ = __name__
        cls.__doc__ = f"{typename} (fields with ROS's defaults)."
        _classes[typename] = cls
        return cls


def service_class(typename: str) -> type[Any]:
    """The class of service ``pkg/srv/Name``: ``Request`` and ``Response`` message classes."""
    with _lock:
        found = _services.get(typename)
        if found is not None:
            return found
        check_service_name(typename)
        register_service_types(typename)
        cls = type(typename.rsplit("/", 1)[1], (), {
            "__srvtype__": typename, "__doc__": f"The service {typename}.",
            "Request": message_class(typename + "_Request"), "Response": message_class(typename + "_Response"),
        })
        cls.__module__ = __name__
        _services[typename] = cls
        return cls
