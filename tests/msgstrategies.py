"""Hypothesis strategies for every robotmodel message, derived from rosbags' Jazzy field definitions."""

from __future__ import annotations

from typing import Any

from hypothesis import strategies as st
from rosbags.typesys import Stores, get_typestore

from robotmodel.msgs import (
    builtin_interfaces,
    geometry_msgs,
    message_class,
    nav_msgs,
    rosgraph_msgs,
    sensor_msgs,
    std_msgs,
    tf2_msgs,
)

STORE = get_typestore(Stores.ROS2_JAZZY)
MODULES = (builtin_interfaces, std_msgs, geometry_msgs, sensor_msgs, nav_msgs, tf2_msgs, rosgraph_msgs)
CLASSES = [getattr(m, n) for m in MODULES for n in m.__all__]

INT_RANGES = {"int32": (-(2**31), 2**31 - 1), "uint32": (0, 2**32 - 1), "int8": (-128, 127), "uint8": (0, 255),
              "int16": (-(2**15), 2**15 - 1), "uint16": (0, 2**16 - 1), "int64": (-(2**63), 2**63 - 1),
              "uint64": (0, 2**64 - 1)}
FLOATS = st.floats(allow_nan=False, width=64)
TEXT = st.text(max_size=12)


def field_strategy(desc: Any) -> st.SearchStrategy[Any]:
    kind, arg = desc
    kind = int(kind)
    if kind == 1:
        name = arg[0]
        if name == "string":
            return TEXT
        if name == "float64":
            return FLOATS
        if name == "bool":
            return st.booleans()
        lo, hi = INT_RANGES[name]
        return st.one_of(st.sampled_from([lo, hi]), st.integers(lo, hi))  # limits every time they come up
    if kind == 2:
        return message_strategy(arg)
    sub, length = arg
    element = field_strategy(sub)
    if kind == 3:
        return st.lists(element, min_size=length, max_size=length)
    return st.lists(element, max_size=length or 4)


def message_strategy(msgtype: str) -> st.SearchStrategy[Any]:
    cls = message_class(msgtype)
    return st.builds(cls, *[field_strategy(desc) for _, desc in STORE.fielddefs[msgtype][1]])
