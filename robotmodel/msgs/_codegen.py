"""Straight-line converters generated per message type, the fast path of :mod:`._convert`.

Each is one expression building the target class from the source's attributes, so a
conversion costs about one constructor call per nested message. Values that are not
already of their ROS type's plain Python type go to the checking converters of
:mod:`._convert`; a failure there is reported by re-running the checked (slow) path,
which names the field.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import fields
from typing import Any, get_args, get_origin, get_type_hints

__all__ = ["INT_RANGES", "from_converter", "to_converter"]

Converter = Callable[[Any], Any]

INT_RANGES = {
    "bool": (0, 1), "byte": (0, 255), "char": (0, 255), "uint8": (0, 255), "int8": (-(2**7), 2**7 - 1),
    "uint16": (0, 2**16 - 1), "int16": (-(2**15), 2**15 - 1), "uint32": (0, 2**32 - 1),
    "int32": (-(2**31), 2**31 - 1), "uint64": (0, 2**64 - 1), "int64": (-(2**63), 2**63 - 1),
}


def _tolist(value: Any) -> list[Any]:
    # numpy arrays (rosbags' primitive sequences) know tolist(); numpy itself stays unimported here.
    return value.tolist() if hasattr(value, "tolist") else list(value)


def _compile(name: str, expr: str, env: dict[str, Any]) -> Converter:
    # Only identifiers reach the source: field names from dataclasses and ROS definitions.
    namespace: dict[str, Any] = {}
    exec(f"def {name}(o):\n    return {expr}\n", env, namespace)
    return namespace[name]  # type: ignore[no-any-return]


def from_converter(cls: type[Any], cache: dict[type[Any], Converter]) -> Converter:
    """A function building ``cls`` from an object with the same field names (rosbags' classes)."""
    done = cache.get(cls)
    if done is not None:
        return done
    hints = get_type_hints(cls)
    env: dict[str, Any] = {"cls": cls, "tolist": _tolist}
    args = []
    for i, f in enumerate(fields(cls)):
        hint = hints[f.name]
        if hasattr(hint, "__msgtype__"):
            env[f"c{i}"] = from_converter(hint, cache)
            args.append(f"c{i}(o.{f.name})")
        elif get_origin(hint) is list and hasattr(get_args(hint)[0], "__msgtype__"):
            env[f"c{i}"] = from_converter(get_args(hint)[0], cache)
            args.append(f"[c{i}(e) for e in o.{f.name}]")
        elif get_origin(hint) is list:
            args.append(f"tolist(o.{f.name})")
        else:
            args.append(f"o.{f.name}")
    convert = _compile("from_" + cls.__name__, f"cls({', '.join(args)})", env)
    cache[cls] = convert
    return convert


def to_converter(target: type[Any], plan: list[tuple[str, Any, Converter]],
                 nested: Callable[[str], Converter]) -> Converter:
    """A function building rosbags' ``target`` from one of our messages.

    ``plan`` lists (field, ROS field description, checking converter); plain values of
    the right Python type pass straight through, anything else goes to its checker.
    """
    env: dict[str, Any] = {"T": target}
    args = []
    for i, (name, desc, check) in enumerate(plan):
        if not name.isidentifier():
            raise ValueError(f"field name {name!r} of {target.__name__} is not an identifier")
        kind, arg = int(desc[0]), desc[1]
        env[f"k{i}"] = check
        if kind == 2:
            env[f"k{i}"] = nested(arg)
            args.append(f"k{i}(o.{name})")
        elif kind == 1 and arg[0] == "float64":
            args.append(f"(x if type(x := o.{name}) is float else k{i}(x))")
        elif kind == 1 and arg[0] == "string" and not arg[1]:
            args.append(f"(x if type(x := o.{name}) is str else k{i}(x))")
        elif kind == 1 and arg[0] in INT_RANGES and arg[0] != "bool":
            lo, hi = INT_RANGES[arg[0]]
            args.append(f"(x if type(x := o.{name}) is int and {lo} <= x <= {hi} else k{i}(x))")
        elif kind == 4 and arg[1] == 0 and int(arg[0][0]) == 2:  # an unbounded sequence of messages
            env[f"n{i}"] = nested(arg[0][1])
            args.append(f"([n{i}(e) for e in x] if type(x := o.{name}) is list else k{i}(x))")
        else:
            args.append(f"k{i}(o.{name})")
    return _compile("to_" + target.__name__, f"T({', '.join(args)})", env)
