"""Messages as ``ros2 topic echo`` prints them: rosidl_runtime_py's ``message_to_yaml`` and ``message_to_csv``.

Fields in message order; arrays, bytes and strings cut after ``truncate_length`` items with
``'...'``; ``no_arr`` puts ``<array type: double[36]>`` / ``<sequence type: string, length:
2>`` in place of an array field and ``no_str`` ``<string length: <5>>`` in place of a string,
with rosidl's IDL type names (``double``, ``boolean``, ``octet``, ``pkg/msg/Type``). The field
types come from the message type's definition in robotmodel's typestore.
"""

from __future__ import annotations

import sys
from dataclasses import fields
from typing import Any

__all__ = ["message_to_csv", "message_to_yaml"]

# rosidl's IDL names for the .msg primitive types (``float64`` is IDL's ``double``).
_IDL = {"bool": "boolean", "byte": "octet", "char": "uint8", "float32": "float", "float64": "double"}
_BASE, _NAME, _ARRAY, _SEQUENCE = 1, 2, 3, 4


def _field_types(msg: Any) -> list[tuple[str, Any]]:
    """(name, rosbags field definition or None) for each field, in message order."""
    from robotmodel.msgs import typestore

    defs = typestore().fielddefs.get(getattr(type(msg), "__msgtype__", ""))
    if defs is not None:
        return [(name, spec) for name, spec in defs[1]]
    return [(f.name, None) for f in fields(msg) if not f.name.startswith("__")]


def _type_name(spec: Any) -> str:
    kind, detail = spec
    if kind == _BASE:
        return "string" if detail[0] == "string" else _IDL.get(detail[0], detail[0])
    return str(detail) if kind == _NAME else "unknown"


def _abbreviated(value: Any, spec: Any) -> str:
    kind, (element, size) = spec
    if kind == _ARRAY:
        return f"<array type: {_type_name(element)}[{size}]>"
    if size:
        return f"<sequence type: {_type_name(element)}[{size}], length: {len(value)}>"
    return f"<sequence type: {_type_name(element)}, length: {len(value)}>"


def _is_array(spec: Any) -> bool:
    return spec is not None and spec[0] in (_ARRAY, _SEQUENCE)


def _plain(value: Any) -> Any:
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return value.tolist()
    return list(value) if isinstance(value, bytes | bytearray | tuple) else value


def _to_tree(msg: Any, limit: int | None, no_arr: bool, no_str: bool) -> dict[str, Any]:
    return {name: _value(getattr(msg, name), spec, limit, no_arr, no_str) for name, spec in _field_types(msg)}


def _value(value: Any, spec: Any, limit: int | None, no_arr: bool, no_str: bool) -> Any:
    if hasattr(type(value), "__msgtype__"):
        return _to_tree(value, limit, no_arr, no_str)
    value = _plain(value)
    if isinstance(value, str):
        if no_str:
            return f"<string length: <{len(value)}>>"
        return value[:limit] + "..." if limit is not None and len(value) > limit else value
    if isinstance(value, list):
        if no_arr and _is_array(spec):
            return _abbreviated(value, spec)
        items = [_value(v, None, limit, no_arr, no_str) for v in (value if limit is None else value[:limit])]
        return [*items, "..."] if limit is not None and len(value) > limit else items
    return value


def message_to_yaml(msg: Any, truncate_length: int | None = None, flow_style: bool = False, *,
                    no_arr: bool = False, no_str: bool = False) -> str:
    """A message (or a field's value) as YAML, the way ros2's ``message_to_yaml`` writes it."""
    import yaml

    tree = _value(msg, None, truncate_length, no_arr, no_str)
    return str(yaml.dump(tree, allow_unicode=True, width=sys.maxsize, default_flow_style=flow_style,
                         sort_keys=False))


def message_to_csv(msg: Any, truncate_length: int | None = None, *, no_arr: bool = False,
                   no_str: bool = False) -> str:
    """A message as one line of comma-separated values, the way ros2's ``message_to_csv`` writes it."""
    if not hasattr(type(msg), "__msgtype__"):
        return _csv_item(msg, None, truncate_length, no_arr, no_str)
    return ",".join(_csv_item(getattr(msg, name), spec, truncate_length, no_arr, no_str)
                    for name, spec in _field_types(msg))


def _csv_item(value: Any, spec: Any, limit: int | None, no_arr: bool, no_str: bool) -> str:
    if hasattr(type(value), "__msgtype__"):
        return message_to_csv(value, limit, no_arr=no_arr, no_str=no_str)
    value = _plain(value)
    if isinstance(value, list):
        if no_arr and _is_array(spec):
            return _abbreviated(value, spec)
        parts = [_csv_item(v, None, limit, no_arr, no_str) for v in (value if limit is None else value[:limit])]
        return ",".join([*parts, "..."] if limit is not None and len(value) > limit else parts)
    if isinstance(value, str):
        if no_str:
            return f"<string length: <{len(value)}>>"
        return value[:limit] + "..." if limit is not None and len(value) > limit else value
    return str(value)
