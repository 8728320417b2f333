"""ROS 1's command-line forms for every node, read as rospy and roscpp read them, on the ROS 1 wire.

On ROS 1 a node takes its arguments as ``NAME:=VALUE`` words anywhere on its command line
(wiki.ros.org/Remapping Arguments): ``__name:=NAME`` renames the node, ``__ns:=NS`` moves it
(relative: under ``/``), ``_param:=value`` sets the private parameter ``~param`` (the value
read as YAML, as rospy reads it: ``10.0`` a double, ``10`` an int, ``true`` a bool), any other
``from:=to`` remaps a name, and ``__master``, ``__ip``, ``__hostname``, ``__log`` are taken and
have no effect here. :func:`robotmodel.rcl.take_node_args` picks these up when the wire is ROS 1
(:func:`robotmodel.bus.default_wire`), after ROS 2's ``--ros-args`` blocks
(:func:`robotmodel.rcl.take_ros_args`), which work on both wires; elsewhere such words stay
where they are (xacro's ``name:=value`` mappings).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple

from robotmodel.errors import RosArgsError

__all__ = ["Ros1Words", "ros1_wire", "take_ros1_args"]

# rospy's and roscpp's special keys with no meaning here (the master comes from ROS_MASTER_URI).
_IGNORED = frozenset({"__master", "__ip", "__hostname", "__log"})


def ros1_wire(environ: Mapping[str, str] | None = None) -> bool:
    """True when the environment selects the ROS 1 wire (``ROS_VERSION=1`` and ``ROS_MASTER_URI``)."""
    from robotmodel.bus._select import default_wire

    return default_wire(environ) == "ros1"


def _yaml_value(text: str) -> Any:
    import yaml

    try:
        return yaml.safe_load(text) if text else ""
    except yaml.YAMLError:
        return text  # rospy keeps what YAML cannot read as the string it was


class Ros1Words(NamedTuple):
    """What ROS 1's words set (None: not set); ``params`` as :class:`robotmodel.rcl.RosArgs` keeps them."""

    namespace: str | None
    node_name: str | None
    remaps: tuple[str, ...]
    params: tuple[tuple[str, str, Any], ...]


def take_ros1_args(words: Sequence[str]) -> tuple[Ros1Words, list[str]]:
    """Take ROS 1's ``NAME:=VALUE`` words out of ``words``: (what they set, the other words)."""
    from robotmodel.bus._names import validate_namespace
    from robotmodel.errors import BusError

    rest: list[str] = []
    namespace: str | None = None
    name: str | None = None
    remaps: list[str] = []
    params: list[tuple[str, str, Any]] = []
    for word in words:
        key, sep, value = word.partition(":=")
        if not sep or not key or word.startswith("-"):
            rest.append(word)
        elif key in _IGNORED:
            pass
        elif key == "__name":
            name = value
        elif key == "__ns":
            try:
                namespace = validate_namespace(value if value.startswith("/") else "/" + value)
            except BusError as exc:
                raise RosArgsError(f"__ns:={value}: {exc}") from None
        elif key.startswith("__"):
            raise RosArgsError(f"unknown special key '{key}' in '{word}'")
        elif key.startswith("_"):
            params.append(("/**", key[1:], _yaml_value(value)))
        else:
            remaps.append(word)
    return Ros1Words(namespace, name, tuple(remaps), tuple(params)), rest
