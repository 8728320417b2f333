"""rospy's parameter calls on the node's store: ROS 1's parameter server, node-local on other wires.

Names resolve as rospy resolves them (``~x`` private, ``x`` in the node's namespace, ``/x``
global). :func:`search_param` goes up the namespace as the parameter server does.
"""

from __future__ import annotations

from typing import Any

from robotmodel.errors import ROSInitException
from robotmodel.rospy import _core

__all__ = ["delete_param", "get_param", "get_param_names", "has_param", "search_param", "set_param"]

_UNSET = object()


def _store() -> Any:
    node = _core.get_node()
    if node is None:
        raise ROSInitException("client code must call rospy.init_node() first")
    return node.parameters


def get_param(param_name: str, default: Any = _UNSET) -> Any:
    """The value; ``default`` when unset and given, else KeyError as rospy."""
    key = _core.resolve_name(param_name)
    try:
        return _store().get(key)
    except KeyError:
        if default is _UNSET:
            raise KeyError(param_name) from None
        return default


def set_param(param_name: str, param_value: Any) -> None:
    """Set a value (every node sees it on ROS 1)."""
    _store().set(_core.resolve_name(param_name), param_value)


def has_param(param_name: str) -> bool:
    """Whether the parameter is set."""
    return bool(_store().has(_core.resolve_name(param_name)))


def delete_param(param_name: str) -> None:
    """Remove the parameter; KeyError when unset, as rospy."""
    _store().delete(_core.resolve_name(param_name))


def get_param_names() -> list[str]:
    """Every parameter name."""
    return list(_store().names())


def search_param(param_name: str) -> str | None:
    """The full name ``param_name`` is found under, searching up from the node's namespace; None if nowhere."""
    if param_name.startswith(("/", "~")):
        key = _core.resolve_name(param_name)
        return key if has_param(key) else None
    from robotmodel.bus import LocalParameters

    store = _store()
    if not isinstance(store, LocalParameters):
        found = store.search(param_name)
        if found is None:
            return None
        return str(found) if str(found).startswith("/") else _core.get_namespace() + str(found)
    parts = [p for p in _core.get_namespace().split("/") if p]
    first, _, rest = param_name.partition("/")
    while True:
        candidate = "/" + "/".join([*parts, first])
        if store.has(candidate):
            return candidate + ("/" + rest if rest else "")
        if not parts:
            return None
        parts.pop()
