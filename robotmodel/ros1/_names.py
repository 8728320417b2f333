"""ROS 1 graph names: resolution against a namespace and a node, as rospy's ``resolve_name`` does it."""

from __future__ import annotations

from robotmodel.errors import Ros1Error

__all__ = ["resolve_name"]


def _join(namespace: str, name: str) -> str:
    return (namespace.rstrip("/") + "/" + name.strip("/")) if name.strip("/") else (namespace or "/")


def resolve_name(name: str, namespace: str, node_name: str) -> str:
    """ROS 1's resolution of a graph name: ``/x`` stays, ``~x`` is under the node, ``x`` under the namespace."""
    if not name:
        raise Ros1Error("empty graph name")
    if name.startswith("/"):
        resolved = name
    elif name.startswith("~"):
        resolved = _join(node_name, name[1:])
    else:
        resolved = _join(namespace if namespace.startswith("/") else "/" + namespace, name)
    return "/" + "/".join(part for part in resolved.split("/") if part)
