"""``ros2 param list|get|set|dump`` (and rosparam's one-name forms) on every wire.

ROS 2 wires go through the node's six parameter services (rcl_interfaces), as ros2param
does; the ROS 1 wire goes to the master's parameter server, where a node's parameters are
the names under ``/node/``. A call with no node name (``rosparam get /a/b``) names a
parameter server key and prints as rosparam does.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from robotmodel.errors import BusError

__all__ = ["run_param_dump", "run_param_get", "run_param_list", "run_param_set"]

_TIMEOUT = 5.0
# ros2param's words for each rcl_interfaces ParameterType (bool, int, double, string, byte[], ... arrays).
_WORDS = {1: "Boolean value is", 2: "Integer value is", 3: "Double value is", 4: "String value is",
          5: "Byte values are", 6: "Boolean values are", 7: "Integer values are", 8: "Double values are",
          9: "String values are"}


@contextmanager
def _session(connect: Sequence[str], spin_time: float) -> Iterator[Any]:
    from robotmodel.bus import Node
    from robotmodel.topic._tools import _discover

    with Node("_robotmodel_param", connect=list(connect)) as node:
        if node.context.encoding != "ros1":
            _discover(node, spin_time)
        yield node


def _is_ros1(node: Any) -> bool:
    return bool(node.context.encoding == "ros1")


def _call(node: Any, node_name: str, suffix: str, request: Any, wait: float = _TIMEOUT) -> Any:
    from robotmodel.msgs._dynamic import service_class
    from robotmodel.rclpy._param_services import SERVICES

    srv_type = SERVICES[suffix]
    cls = service_class(srv_type)
    client = node.create_client(srv_type, f"{node_name.rstrip('/')}/{suffix}", request_type=cls.Request,
                                response_type=cls.Response)
    try:
        if not client.wait_for_service(wait):
            raise BusError("Node not found")
        return client.call(request(cls), _TIMEOUT)
    finally:
        client.close()


def _ros2_names(node: Any, node_name: str, wait: float = _TIMEOUT) -> list[str]:
    result = _call(node, node_name, "list_parameters", lambda c: c.Request(prefixes=[], depth=0), wait).result
    return sorted(result.names)


def _ros2_values(node: Any, node_name: str, names: list[str]) -> list[Any]:
    from robotmodel.rclpy.parameter import parameter_value_to_python

    values = _call(node, node_name, "get_parameters", lambda c: c.Request(names=names)).values
    return [(int(v.type), parameter_value_to_python(v)) for v in values]


def _plain(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, bytes | bytearray | tuple):
        return list(value)
    return value


def _ros1_key(node_name: str, name: str) -> str:
    return name if name.startswith("/") else node_name.rstrip("/") + "/" + name


def _ros1_all(node: Any) -> list[str]:
    """Every key on the server, absolute (the store names them relative to this node's namespace, '/')."""
    return sorted(n if n.startswith("/") else "/" + n for n in node.parameters.names())


def _ros1_names(node: Any, node_name: str) -> list[str]:
    prefix = node_name.rstrip("/") + "/"
    return [n[len(prefix):] for n in _ros1_all(node) if n.startswith(prefix)]


def run_param_list(node_name: str | None = None, *, connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 param list [NODE]`` (``rosparam list``: every key on ROS 1 without a node)."""
    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            if node_name is None:
                for name in _ros1_all(node):
                    print(name)
                return 0
            listing = {node_name: _ros1_names(node, node_name)}
        else:
            listing = {}
            if node_name:
                listing[node_name] = _ros2_names(node, node_name)
            else:  # every node that answers (ros2param asks the nodes with a list_parameters service)
                from robotmodel.topic._tools import _hidden

                for name, ns in sorted(node.get_node_names_and_namespaces()):
                    fqn = ns.rstrip("/") + "/" + name
                    if _hidden(fqn):
                        continue
                    try:
                        listing[fqn] = _ros2_names(node, fqn, wait=1.0)
                    except BusError:
                        continue
    for name, params in listing.items():
        print(f"{name}:")
        for param in params:
            print(f"  {param}")
    return 0


def _ros1_text(value: Any) -> str:
    import yaml

    if isinstance(value, dict | list):
        return str(yaml.safe_dump(value, default_flow_style=False)).rstrip("\n")
    return str(value)


def run_param_get(node_name: str, parameter_name: str | None = None, *, hide_type: bool = False,
                  connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 param get NODE NAME``, or rosparam's ``get KEY`` (``parameter_name`` None)."""
    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            key = node_name if parameter_name is None else _ros1_key(node_name, parameter_name)
            try:
                value = node.parameters.get(key)
            except KeyError:
                raise BusError(f"Parameter [{key}] is not set" if parameter_name is None
                               else "Parameter not set") from None
            if parameter_name is None:
                print(_ros1_text(value))
                return 0
            got = [(0, value)]
        else:
            if parameter_name is None:
                raise BusError("a node name and a parameter name are needed on ROS 2 (ros2 param get NODE NAME)")
            got = _ros2_values(node, node_name, [parameter_name])
    if not got:
        raise BusError("Parameter not set")
    ptype, value = got[0]
    if ptype == 0 and value is not None:  # ROS 1: the type follows the value
        value = _plain(value)
        word = {bool: 1, int: 2, float: 3, str: 4}.get(type(value), 0)
        print(value if hide_type else f"{_WORDS[word]}: {value}" if word else _ros1_text(value))
    elif ptype == 0:  # declared, no value: ros2param's label, and exit 0
        print(None if hide_type else "Parameter not set.")
    else:
        shown = _ros2_text(ptype, value)
        print(shown if hide_type else f"{_WORDS.get(ptype, 'Value is')}: {shown}")
    return 0


def _ros2_text(ptype: int, value: Any) -> str:
    """A ROS 2 value as ros2param prints the message field: integer and double arrays are ``array.array``s."""
    if ptype in (7, 8):
        return repr(array("q" if ptype == 7 else "d", list(value)))
    return str(_plain(value))


def run_param_set(node_name: str, parameter_name: str, value: str | None = None, *, connect: Sequence[str] = (),
                  spin_time: float = 0.5) -> int:
    """``ros2 param set NODE NAME VALUE`` (VALUE in YAML), or rosparam's ``set KEY VALUE`` (``value`` None)."""
    import yaml

    if value is None:  # rosparam set KEY VALUE
        key, text, ros1_form = node_name, parameter_name, True
    else:
        key, text, ros1_form = parameter_name, value, False
    try:
        parsed = yaml.safe_load(text)
    except yaml.YAMLError:
        parsed = text
    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            node.parameters.set(key if ros1_form else _ros1_key(node_name, key), parsed)
            if not ros1_form:
                print("Set parameter successful")
            return 0
        if ros1_form:
            raise BusError("a node name, a parameter name and a value are needed on ROS 2 "
                           "(ros2 param set NODE NAME VALUE)")
        from robotmodel.rclpy.parameter import Parameter

        param = Parameter(key, value=parsed).to_parameter_msg()
        results = _call(node, node_name, "set_parameters", lambda c: c.Request(parameters=[param])).results
    if results and results[0].successful:
        print("Set parameter successful")
        return 0
    reason = results[0].reason if results else "no result"
    raise BusError(f"Set parameter failed: {reason}" if reason else "Set parameter failed")


def run_param_dump(node_name: str, *, connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 param dump NODE``: the node's parameters as a ROS 2 parameter file, to stdout."""
    import yaml

    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            params = {name: node.parameters.get(_ros1_key(node_name, name)) for name in _ros1_names(node, node_name)}
        else:
            names = _ros2_names(node, node_name)
            params = {name: _plain(v) for name, (_t, v) in zip(names, _ros2_values(node, node_name, names),
                                                               strict=False)}
    print(yaml.safe_dump({node_name: {"ros__parameters": params}}, default_flow_style=False), end="")
    return 0
