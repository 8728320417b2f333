"""The ``--ros-args`` block a launched node's command gets: name, namespace, parameters, remaps.

launch_ros's order: the node's ``ros_args`` words, ``-r __node:=NAME``, ``-r __ns:=/NS``, the
scope's ``<set_parameter>`` values, the node's parameters (inline ones and params files in the
file's order), then the remap rules. The commands read it with :mod:`robotmodel.rcl`
(rcl's rules), whose parameter-name rule decides here too, so one mapping decides what each
parameter means.
"""

from __future__ import annotations

import shlex
from dataclasses import replace

from robotmodel.errors import LaunchError
from robotmodel.launch._model import NodeDecl, ProcessSpec
from robotmodel.rcl import is_param_name

__all__ = ["ros_tail"]

# The node name each command uses when given none (None: a fresh anonymous one, as tf2_ros's).
_COMMAND_NAME = {
    "robot_state_publisher": "robot_state_publisher",
    "joint_state_publisher": "joint_state_publisher",
    "joint_state_publisher_gui": "joint_state_publisher_gui",
    "rviz": "robotmodel_view",
    "static_transform_publisher": None,
}


def ros_tail(spec: ProcessSpec, node: NodeDecl, consumed: frozenset[str], notes: list[str]) -> ProcessSpec:
    """``spec`` with the node's ROS arguments appended (unchanged when there are none).

    ``consumed`` names the parameters already turned into the command's own words; a
    parameter that cannot travel as ``-p`` (from a file or a command, or a name rcl
    refuses) is named in ``notes``.
    """
    words = _split_ros_args(node)
    name = node.name if node.named else None
    if name is not None and name != _COMMAND_NAME.get(spec.kind):
        words += ["-r", f"__node:={name}"]
    if node.namespace != "/":
        words += ["-r", f"__ns:={_checked_namespace(node)}"]
    for key, value in node.scope_params:
        words += ["-p", f"{key}:={value or _EMPTY}"]
    ordered: list[tuple[int, list[str]]] = []
    for key, param in node.params.items():
        if key in consumed:
            continue
        if param.value is None or not is_param_name(key):
            notes.append(f"{param.file}:{param.line}: parameter '{key}' of {node.full_name} not passed on "
                         "(only plain values with ROS 2 parameter names are)")
            continue
        value = param.typed if param.typed is not None else param.value
        ordered.append((param.line, ["-p", f"{key}:={value or _EMPTY}"]))
    ordered += [(line, ["--params-file", str(path)]) for path, line in node.param_files]
    for _, pair in sorted(ordered, key=lambda item: item[0]):
        words += pair
    for source, target in node.remaps:
        words += ["-r", f"{source}:={target}"]
    if not words:
        return spec
    return replace(spec, argv=(*spec.argv, "--ros-args", *words))


# rcl reads an empty value as no value at all; a quoted empty string is the empty string.
_EMPTY = "''"


def _split_ros_args(node: NodeDecl) -> list[str]:
    try:
        return shlex.split(node.ros_args)
    except ValueError as exc:
        raise LaunchError(f"{node.file}:{node.line}: ros_args=\"{node.ros_args}\": {exc}") from None


def _checked_namespace(node: NodeDecl) -> str:
    from robotmodel.bus._names import validate_namespace
    from robotmodel.errors import BusError

    try:
        return validate_namespace(node.namespace)
    except BusError as exc:
        raise LaunchError(f"{node.file}:{node.line}: node {node.name}: {exc}") from None
