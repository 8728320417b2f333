"""Conversion between robotmodel's messages and rosbags' typestore classes.

Converters are compiled once per (typestore, message type) from the typestore's field
definitions, so the ROS type (int32, uint32, float64[36], ...) decides how each field is
checked. A value the ROS type cannot carry raises :class:`MessageError` naming the field
path, e.g. ``tf2_msgs/msg/TFMessage.transforms[0].header.stamp.sec``.
"""

from __future__ import annotations

import math
import numbers
import operator
from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

from robotmodel.errors import MessageError
from robotmodel.msgs import (
    builtin_interfaces,
    geometry_msgs,
    nav_msgs,
    rosgraph_msgs,
    sensor_msgs,
    std_msgs,
    tf2_msgs,
    turtlesim,
)
from robotmodel.msgs._codegen import INT_RANGES, from_converter, to_converter

if TYPE_CHECKING:
    from rosbags.typesys.store import Typestore

__all__ = ["Message", "from_rosbags", "message_class", "to_rosbags", "typestore"]


class Message(Protocol):
    """Any ROS message class here: it names its ROS type in ``__msgtype__``."""

    __msgtype__: ClassVar[str]


_CLASSES: dict[str, type[Any]] = {
    cls.__msgtype__: cls
    for module in (builtin_interfaces, std_msgs, geometry_msgs, sensor_msgs, nav_msgs, tf2_msgs, rosgraph_msgs,
                   turtlesim)
    for cls in (getattr(module, name) for name in module.__all__)
}
_FLOAT32_MAX = 3.4028234663852886e38
# numpy dtype names of ROS primitive types; numpy is imported when a converter is first built.
_DTYPES = {"float32": "float32", "float64": "float64", "bool": "bool", "byte": "uint8", "char": "uint8",
           "uint8": "uint8", "int8": "int8", "uint16": "uint16", "int16": "int16", "uint32": "uint32",
           "int32": "int32", "uint64": "uint64", "int64": "int64"}

Converter = Callable[[Any], Any]
_FLOAT_ONLY = frozenset({float})
_FROM: dict[type[Any], Converter] = {}


class _Bad(Exception):
    """A field value the ROS type cannot carry; the path is filled in on the way out."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason
        self.path: list[str] = []


@lru_cache(maxsize=1)
def typestore() -> Typestore:
    """The ROS 2 Jazzy typestore of rosbags, with turtlesim's Pose registered (built once, on first use)."""
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS2_JAZZY)
    store.register(get_types_from_msg(turtlesim.POSE_DEFINITION, turtlesim.Pose.__msgtype__))
    return store


def message_class(msgtype: str) -> type[Any]:
    """The robotmodel class of a ROS message type name such as ``"tf2_msgs/msg/TFMessage"``."""
    try:
        return _CLASSES[msgtype]
    except KeyError:
        raise MessageError(f"no robotmodel message class for '{msgtype}'") from None


def _int_converter(typename: str) -> Converter:
    lo, hi = INT_RANGES[typename]

    def convert(value: Any) -> int:
        if type(value) is not int:
            try:
                value = operator.index(value)
            except TypeError:
                raise _Bad(f"{value!r} is not an integer ({typename})") from None
        if not lo <= value <= hi:
            raise _Bad(f"{value} is out of range for {typename} [{lo}, {hi}]")
        return int(value)

    return convert


def _float_converter(typename: str) -> Converter:
    def convert(value: Any) -> float:
        if type(value) is not float:
            if not isinstance(value, numbers.Real):
                raise _Bad(f"{value!r} is not a number ({typename})")
            value = float(value)
        if typename == "float32" and math.isfinite(value) and abs(value) > _FLOAT32_MAX:
            raise _Bad(f"{value} is out of range for float32")
        return float(value)

    return convert


def _bool_converter(value: Any) -> bool:
    if not (isinstance(value, bool) or type(value).__name__ in ("bool", "bool_")):  # or numpy's bool
        raise _Bad(f"{value!r} is not a bool")
    return bool(value)


def _string_converter(bound: int) -> Converter:
    def convert(value: Any) -> str:
        if not isinstance(value, str):
            raise _Bad(f"{value!r} is not a str")
        text = str.__str__(value)  # a subclass's characters (numpy.str_, a str Enum), not its str()
        if bound and len(text.encode()) > bound:
            raise _Bad(f"string of {len(text.encode())} bytes exceeds its bound of {bound}")
        return text

    return convert


def _base_converter(typename: str, bound: int) -> Converter:
    if typename == "string":
        return _string_converter(bound)
    if typename == "bool":
        return _bool_converter
    if typename in ("float32", "float64"):
        return _float_converter(typename)
    return _int_converter(typename)


def _sequence(value: Any, what: str) -> Any:
    # Sequences only, as rclpy: a generator would be used up by a first, failed attempt.
    if type(value) is list or type(value) is tuple:
        return value
    if isinstance(value, str | bytes) or not (isinstance(value, Sequence) or hasattr(value, "__array__")):
        raise _Bad(f"{value!r} is not a sequence of {what}")
    return value


def _numeric_array_converter(typename: str, length: int, bounded: bool) -> Converter:
    import numpy as np

    dtype = np.dtype(_DTYPES[typename])
    is_f64 = dtype == np.float64
    element = _base_converter(typename, 0)

    def convert(value: Any) -> Any:
        if isinstance(value, np.ndarray) and value.ndim == 1 and value.dtype.kind in "fiub":
            items: Any = value
            checked = value.dtype.kind == "f" and is_f64
        else:
            items = list(_sequence(value, typename))
            checked = is_f64 and {*map(type, items)} <= _FLOAT_ONLY
        if (bounded and len(items) > length) or (not bounded and length and len(items) != length):
            raise _Bad(f"{len(items)} elements where {typename}[{'<=' if bounded else ''}{length}] is expected")
        if not checked:
            for i, item in enumerate(items):
                try:
                    element(item)
                except _Bad as exc:
                    exc.path.append(f"[{i}]")
                    raise
        return np.asarray(items, dtype=dtype)

    return convert


def _list_converter(element: Converter, length: int, bounded: bool, what: str, plain: type | None) -> Converter:
    """A list converter; elements of type ``plain`` need no check (unbounded strings)."""

    def convert(value: Any) -> list[Any]:
        if plain is not None and not length and type(value) is list and {*map(type, value)} <= {plain}:
            return list(value)
        out = []
        for i, item in enumerate(_sequence(value, what)):
            try:
                out.append(element(item))
            except _Bad as exc:
                exc.path.append(f"[{i}]")
                raise
        if (bounded and len(out) > length) or (not bounded and length and len(out) != length):
            raise _Bad(f"{len(out)} elements where {what}[{'<=' if bounded else ''}{length}] is expected")
        return out

    return convert


def _field_converter(store: Typestore, desc: Any) -> Converter:
    kind, arg = desc
    kind = int(kind)
    if kind == 1:  # BASE: (typename, string bound)
        return _base_converter(arg[0], arg[1])
    if kind == 2:  # NAME: a nested message
        return _struct_converter(store, arg)
    (sub_kind, sub_arg), length = arg
    if kind == 4 and length == 0:  # an unbounded SEQUENCE
        length, bounded = 0, False
    else:
        bounded = kind == 4  # a bounded SEQUENCE: length is an upper bound; an ARRAY (3): exact
    if int(sub_kind) == 1 and sub_arg[0] != "string":
        return _numeric_array_converter(sub_arg[0], length, bounded)
    element = _field_converter(store, (sub_kind, sub_arg))
    plain = str if int(sub_kind) == 1 and sub_arg == ("string", 0) else None
    return _list_converter(element, length, bounded, sub_arg if int(sub_kind) == 2 else sub_arg[0], plain)


_STRUCTS: dict[tuple[int, str], tuple[Typestore, Converter]] = {}


def _struct_converter(store: Typestore, msgtype: str) -> Converter:
    key = (id(store), msgtype)
    cached = _STRUCTS.get(key)
    if cached is not None and cached[0] is store:
        return cached[1]
    # ROS types cannot nest themselves, so the plan is complete before anyone can see it.
    plan = [(name, _field_converter(store, desc)) for name, desc in store.fielddefs[msgtype][1]]
    target = store.types[msgtype]

    def convert(value: Any) -> Any:
        args = []
        for name, conv in plan:
            try:
                args.append(conv(getattr(value, name)))
            except _Bad as exc:
                exc.path.append(f".{name}")
                raise
            except AttributeError:
                raise _Bad(f"a {type(value).__name__} is not a {msgtype} (no field '{name}')") from None
        return target(*args)

    _STRUCTS[key] = (store, convert)
    return convert


_FAST: dict[tuple[int, str], tuple[Typestore, Converter]] = {}


def _fast_converter(store: Typestore, msgtype: str) -> Converter:
    key = (id(store), msgtype)
    cached = _FAST.get(key)
    if cached is not None and cached[0] is store:
        return cached[1]
    plan = [(name, desc, _field_converter(store, desc)) for name, desc in store.fielddefs[msgtype][1]]
    convert = to_converter(store.types[msgtype], plan, lambda nested: _fast_converter(store, nested))
    _FAST[key] = (store, convert)
    return convert


def to_rosbags(msg: Message, store: Typestore | None = None) -> Any:
    """``msg`` as an instance of the typestore's class for its type (default: ROS 2 Jazzy).

    Raises :class:`MessageError` naming the field when a value does not fit its ROS type.
    """
    store = store if store is not None else typestore()
    msgtype = type(msg).__msgtype__
    if msgtype not in store.types:
        raise MessageError(f"'{msgtype}' is not a type of the typestore")
    try:
        return _fast_converter(store, msgtype)(msg)
    except (_Bad, AttributeError, TypeError, ValueError):
        pass  # the checked path below converts what the fast one could not, or names the field
    try:
        return _struct_converter(store, msgtype)(msg)
    except _Bad as exc:
        raise MessageError(f"{msgtype}{''.join(reversed(exc.path))}: {exc.reason}") from None


def from_rosbags(obj: Any) -> Any:
    """The robotmodel message equal to a rosbags message object (fields it lacks, like ROS 1's seq, drop)."""
    msgtype = getattr(obj, "__msgtype__", None)
    cls = _CLASSES.get(msgtype) if isinstance(msgtype, str) else None
    if cls is None:
        raise MessageError(f"no robotmodel message class for '{msgtype or type(obj).__name__}'")
    try:
        return from_converter(cls, _FROM)(obj)
    except (AttributeError, TypeError) as exc:
        raise MessageError(f"cannot read a {msgtype} from {type(obj).__name__}: {exc}") from None
