"""ROS names: validation and expansion as rcl does, and ROS 2's type-name mangling.

Shared by every wire; the zenoh forms of these names (key expressions, liveliness tokens)
are in :mod:`._zenoh_names`.
"""

from __future__ import annotations

import re

from robotmodel.errors import BusError

__all__ = [
    "dds_type_name",
    "resolve_topic",
    "ros_type_name",
    "validate_namespace",
    "validate_node_name",
]

_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_DDS_MARK = "dds_::"


def validate_node_name(name: str) -> str:
    """Return ``name`` if it is a valid ROS node name (letters, digits, '_', no leading digit)."""
    if not _TOKEN.fullmatch(name):
        raise BusError(f"invalid node name '{name}': must be letters, digits and '_', not starting with a digit")
    return name


def _check_fq(name: str, what: str) -> str:
    if not name.startswith("/"):
        raise BusError(f"invalid {what} '{name}': must be absolute")
    if name == "/":
        return name
    if name.endswith("/"):
        raise BusError(f"invalid {what} '{name}': must not end with '/'")
    for token in name[1:].split("/"):
        if not _TOKEN.fullmatch(token):
            raise BusError(
                f"invalid {what} '{name}': '{token}' must be letters, digits and '_', not starting with a digit"
            )
    return name


def validate_namespace(namespace: str) -> str:
    """Return the namespace made absolute ('' and 'ns' become '/' and '/ns'); raises BusError."""
    ns = namespace if namespace.startswith("/") else "/" + namespace
    return _check_fq(ns, "namespace")


def resolve_topic(name: str, namespace: str = "/", node_name: str = "") -> str:
    """Expand a topic name as rcl does: absolute kept, relative under the namespace, '~' the node."""
    if not name:
        raise BusError("invalid topic name '': must not be empty")
    ns = validate_namespace(namespace)
    if name == "~" or name.startswith("~/"):
        if not node_name:
            raise BusError(f"invalid topic name '{name}': '~' needs a node name")
        base = ns.rstrip("/") + "/" + node_name
        full = base + name[1:]
    elif name.startswith("/"):
        full = name
    else:
        full = ns.rstrip("/") + "/" + name
    if full == "/":
        raise BusError(f"invalid topic name '{name}'")
    return _check_fq(full, "topic name")


def dds_type_name(typename: str) -> str:
    """``pkg/msg/Name`` -> ``pkg::msg::dds_::Name_`` (the type chunk of keys and tokens)."""
    parts = typename.split("/")
    if len(parts) != 3 or not all(parts):
        raise BusError(f"invalid message type '{typename}': expected pkg/msg/Name")
    pkg, kind, name = parts
    return f"{pkg}::{kind}::dds_::{name}_"


def ros_type_name(dds_name: str) -> str:
    """``pkg::msg::dds_::Name_`` -> ``pkg/msg/Name``, as rmw_zenoh's graph cache demangles it.

    Text ending in '_' and holding ``dds_::``: the part before it with every '::' made '/',
    then the name without its final '_'. Other text is returned unchanged.
    """
    at = dds_name.find(_DDS_MARK)
    if not dds_name.endswith("_") or at < 0:
        return dds_name
    return dds_name[:at].replace("::", "/") + dds_name[at + len(_DDS_MARK):-1]
