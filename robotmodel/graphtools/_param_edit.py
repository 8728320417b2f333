"""``ros2 param delete|describe|load`` (and rosparam's ``delete KEY`` / ``load FILE [NS]``) on every wire.

ROS 2 wires: ros2param waits ``timeout`` s for the node to appear in the graph ("Node not
found" otherwise), then calls its parameter services: delete is ``set_parameters`` with a
NOT_SET value (the node refuses it for a statically typed parameter, with rclpy's or rclcpp's
reason), describe is ``describe_parameters``, load sets, one by one, every parameter of the
file as rclpy's ``parameter_dict_from_yaml_file`` reads it (each node's ``ros__parameters``,
the ``/**`` ones first unless ``use_wildcard`` is off; values typed from their text as
``ros2 param set`` types them). The ROS 1 wire goes to the parameter server: ``rosparam
delete KEY`` and ``rosparam load FILE [NAMESPACE]`` (each YAML document, ``_ns`` moving it, a
mapping setting its leaves one by one, as rosparam); the ROS 2 forms there name ``/node/name``
keys, a described parameter being typed from its value.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

from robotmodel.errors import BusError
from robotmodel.graphtools._param import _call, _is_ros1, _ros1_key, _session

__all__ = ["parameter_file_values", "run_param_delete", "run_param_describe", "run_param_load"]

_NOT_SET, _WILDCARD, _NS = 0, "/**", "_ns"
# ros2param's get_parameter_type_string.
_TYPE_WORDS = ["not set", "boolean", "integer", "double", "string", "byte array", "boolean array", "integer array",
               "double array", "string array"]


def _wait_for_node(node: Any, node_name: str, timeout: float, include_hidden_nodes: bool) -> None:
    """ros2node's wait_for_node: the node in the graph within ``timeout`` s, else "Node not found"."""
    from robotmodel.topic._tools import _hidden

    full = node_name if node_name.startswith("/") else "/" + node_name
    deadline = time.monotonic() + timeout
    while True:
        names = {ns.rstrip("/") + "/" + name for name, ns in node.get_node_names_and_namespaces()}
        if full in names and (include_hidden_nodes or not _hidden(full)):
            return
        if time.monotonic() >= deadline:
            raise BusError("Node not found")
        time.sleep(0.1)


def _set(node: Any, node_name: str, params: list[Any]) -> list[Any]:
    return list(_call(node, node_name, "set_parameters", lambda c: c.Request(parameters=params)).results)


def _said(what: str, result: Any) -> bool:
    """Print ros2param's line for one result (failures to stderr); whether it succeeded."""
    ok = bool(result.successful)
    line = f"{what} {'successful' if ok else 'failed'}" + (f": {result.reason}" if result.reason else "")
    print(line, file=sys.stdout if ok else sys.stderr)
    return ok


def run_param_delete(node_name: str, parameter_name: str | None = None, *, timeout: float = 1.0,
                     include_hidden_nodes: bool = False, connect: Sequence[str] = (), spin_time: float = 0.5) -> int:
    """``ros2 param delete NODE NAME``, or ``rosparam delete KEY`` (``parameter_name`` None); the exit code."""
    from robotmodel.msgs.rcl_interfaces.msg import Parameter, ParameterValue

    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            key = node_name if parameter_name is None else _ros1_key(node_name, parameter_name)
            key = key if key.startswith("/") else "/" + key
            try:
                node.parameters.delete(key)
            except KeyError:
                raise BusError(f"parameter [{key}] is not set") from None
            if parameter_name is not None:
                print("Deleted parameter successfully")
            return 0
        if parameter_name is None:
            raise BusError("a node name and a parameter name are needed on ROS 2 (ros2 param delete NODE NAME)")
        _wait_for_node(node, node_name, timeout, include_hidden_nodes)
        results = _set(node, node_name, [Parameter(name=parameter_name, value=ParameterValue(type=_NOT_SET))])
    result = results[0] if results else None
    if result is not None and result.successful:
        print("Deleted parameter successfully" + (f": {result.reason}" if result.reason else ""))
        return 0
    reason = result.reason if result is not None else "no result"
    raise BusError("Deleting parameter failed" + (f": {reason}" if reason else ""))


def _ros1_descriptor(name: str, value: Any) -> Any:
    """A parameter server value described as a ROS 2 node would describe it: its name and type."""
    from robotmodel.msgs.rcl_interfaces.msg import ParameterDescriptor

    return ParameterDescriptor(name=name, type=int(_typed(value, str(value)).type))


def _describe_lines(d: Any) -> Iterator[str]:
    """ros2param describe's lines for one ParameterDescriptor."""
    yield f"Parameter name: {d.name}"
    yield f"  Type: {_TYPE_WORDS[int(d.type)]}"
    if d.description:
        yield f"  Description: {d.description}"
    yield "  Constraints:"
    if d.read_only:
        yield "    Read only: true"
    ranges = list(d.floating_point_range) + list(d.integer_range)
    if ranges:
        yield f"    Min value: {ranges[0].from_value}"
        yield f"    Max value: {ranges[0].to_value}"
        if ranges[0].step:
            yield f"    Step: {ranges[0].step}"
    if d.additional_constraints:
        yield f"    Additional constraints: {d.additional_constraints}"


def run_param_describe(node_name: str, parameter_names: Sequence[str], *, timeout: float = 1.0,
                       include_hidden_nodes: bool = False, connect: Sequence[str] = (),
                       spin_time: float = 0.5) -> int:
    """``ros2 param describe NODE NAME...``: each declared parameter's type and constraints; the exit code."""
    with _session(connect, spin_time) as node:
        if _is_ros1(node):
            descriptors = []
            for name in parameter_names:
                try:
                    descriptors.append(_ros1_descriptor(name, node.parameters.get(_ros1_key(node_name, name))))
                except KeyError:
                    descriptors = []  # as a ROS 2 node answers a list naming an undeclared parameter
                    break
        else:
            _wait_for_node(node, node_name, timeout, include_hidden_nodes)
            descriptors = list(_call(node, node_name, "describe_parameters",
                                     lambda c: c.Request(names=list(parameter_names))).descriptors)
    for descriptor in descriptors:
        for line in _describe_lines(descriptor):
            print(line)
    return 0


def _text_value(text: str) -> Any:
    """The ParameterValue rclpy's ``get_parameter_value`` makes of ``text`` (YAML typed, else a string)."""
    import yaml

    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:  # rclpy catches the parser's errors only; a scanner's would end ros2param
        value = text
    return _typed(value, text)


def _typed(value: Any, text: str) -> Any:
    """The ParameterValue of a YAML value (``text`` its spelling), typed as rclpy types it: arrays by their items."""
    from robotmodel.msgs.rcl_interfaces.msg import ParameterValue

    if isinstance(value, bool):
        return ParameterValue(type=1, bool_value=value)
    if isinstance(value, int):
        return ParameterValue(type=2, integer_value=value)
    if isinstance(value, float):
        return ParameterValue(type=3, double_value=value)
    if isinstance(value, list):
        for kind, field, test in ((6, "bool_array_value", bool), (7, "integer_array_value", int),
                                  (8, "double_array_value", float), (9, "string_array_value", str)):
            if all(isinstance(v, test) for v in value):
                return ParameterValue(**{"type": kind, field: value})
        return ParameterValue(type=4, string_value=text)
    return ParameterValue(type=4, string_value=value if value is not None else text)


def _flatten(prefix: str, values: dict[Any, Any], out: dict[str, Any]) -> None:
    for name, value in values.items():
        if isinstance(value, dict):
            _flatten(f"{prefix}{name}.", value, out)
        else:
            out[f"{prefix}{name}"] = value


def parameter_file_values(path: str, use_wildcard: bool = True) -> dict[str, Any]:
    """The parameters of a ROS 2 parameter file, name to ParameterValue, as ``ros2 param load`` reads them.

    As rclpy's ``parameter_dict_from_yaml_file`` with no target node: every node's section
    (``/**`` first when ``use_wildcard``, else left out), nested names joined with dots.
    """
    import yaml

    try:
        document = yaml.safe_load(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise BusError(f"{path}: {exc.strerror or exc}") from None
    except yaml.YAMLError as exc:
        raise BusError(f"{path}: not YAML: {getattr(exc, 'problem', None) or exc}") from None
    if not isinstance(document, dict):
        raise BusError(f"{path}: YAML file is not a valid ROS parameter file")
    keys = [_WILDCARD] if use_wildcard and _WILDCARD in document else []
    keys += [k for k in document if k != _WILDCARD]
    if not keys:
        raise BusError(f"{path}: Param file does not contain selected parameters")
    flat: dict[str, Any] = {}
    for key in keys:
        section = document[key]
        if not isinstance(section, dict) or "ros__parameters" not in section:
            raise BusError(f"{path}: YAML file is not a valid ROS parameter file for node {key}")
        _flatten("", section["ros__parameters"], flat)
    return {name: _text_value(str(value)) for name, value in flat.items()}


def _ros1_upload(store: Any, key: str, value: Any) -> None:
    """Set ``key`` as rosparam's set_param_raw does: a mapping sets each leaf (an update, not a replacement)."""
    if isinstance(value, dict):
        for name, item in value.items():
            if not isinstance(name, str):
                raise BusError(f"YAML dictionaries must have string keys. Invalid dictionary is:\n{value}")
            _ros1_upload(store, key.rstrip("/") + "/" + name, item)
        return
    store.set(key, value)


def _ros1_load(node: Any, path: str, namespace: str | None) -> None:
    """``rosparam load FILE [NAMESPACE]``: every document of the file into the namespace (``_ns`` moving it)."""
    import yaml

    if not Path(path).is_file():
        raise BusError(f"file [{path}] does not exist")
    base = "/" + (namespace or "").strip("/")
    try:
        documents = list(yaml.safe_load_all(Path(path).read_text(encoding="utf-8")))
    except yaml.YAMLError as exc:
        raise BusError(f"{path}: not YAML: {getattr(exc, 'problem', None) or exc}") from None
    for doc in documents:
        where = base
        if isinstance(doc, dict) and _NS in doc:
            ns = str(doc.pop(_NS))
            where = ns if ns.startswith("/") else base.rstrip("/") + "/" + ns
        if where == "/" and not isinstance(doc, dict):
            raise BusError("global / can only be set to a dictionary")
        _ros1_upload(node.parameters, where, doc)


def run_param_load(node_name: str, parameter_file: str | None = None, *, use_wildcard: bool = True,
                   timeout: float = 1.0, include_hidden_nodes: bool = False, connect: Sequence[str] = (),
                   spin_time: float = 0.5) -> int:
    """``ros2 param load NODE FILE``, or ``rosparam load FILE [NAMESPACE]``; the exit code (1 if any set failed).

    The rosparam form is taken when ``node_name`` names an existing file and
    ``parameter_file`` does not (it is then the namespace), or when only one is given.
    """
    ros1_form = parameter_file is None or (Path(node_name).is_file() and not Path(parameter_file).is_file())
    with _session(connect, spin_time) as node:
        if ros1_form:
            if not _is_ros1(node):
                raise BusError("a node name and a parameter file are needed on ROS 2 (ros2 param load NODE FILE)")
            _ros1_load(node, node_name, parameter_file)
            return 0
        assert parameter_file is not None
        values = parameter_file_values(parameter_file, use_wildcard)
        if _is_ros1(node):
            from robotmodel.rclpy.parameter import parameter_value_to_python

            for name, value in values.items():
                node.parameters.set(_ros1_key(node_name, name.replace(".", "/")), parameter_value_to_python(value))
                print(f"Set parameter {name} successful")
            return 0
        from robotmodel.msgs.rcl_interfaces.msg import Parameter

        _wait_for_node(node, node_name, timeout, include_hidden_nodes)
        results = _set(node, node_name, [Parameter(name=n, value=v) for n, v in values.items()])
    if len(results) != len(values):
        raise BusError("Not all parameters set")
    oks = [_said(f"Set parameter {name}", result) for name, result in zip(values, results, strict=True)]
    return 0 if all(oks) else 1
