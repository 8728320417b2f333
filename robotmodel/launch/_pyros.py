"""launch_ros's actions and parameter values: ``Node``, ``ParameterValue``, the ROS scope actions.

A ``Node`` becomes a :class:`robotmodel.launch.NodeDecl`, as the XML launcher reads a
``<node>``, so the same mapping decides what starts. Parameter values follow launch_ros's
evaluation: a Python string stays that string, substitutions are read as YAML (a URDF
from ``Command`` whose text is not a YAML scalar fails with launch_ros's message;
``ParameterValue(..., value_type=str)`` keeps text as text), lists must be uniform (ints
and floats: floats), nested dicts name nested parameters (``a.b``).
"""

from __future__ import annotations

import json
import os
import shlex
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import yaml

from robotmodel.errors import LaunchError
from robotmodel.launch._model import Dialect, NodeDecl, Param
from robotmodel.launch._pyactions import Action
from robotmodel.launch._pyctx import LaunchContext
from robotmodel.launch._pysubst import Substitution, normalize, perform_all

__all__ = [
    "ComposableNode",
    "ComposableNodeContainer",
    "LifecycleNode",
    "LoadComposableNodes",
    "Node",
    "ParameterFile",
    "ParameterValue",
    "PushROSNamespace",
    "PushRosNamespace",
    "SetParameter",
    "SetRemap",
    "SetUseSimTime",
    "yaml_text",
]

_SCALARS = (bool, int, float, str)
_LOADER: Any = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class ParameterValue:
    """A parameter value with the type launch_ros should give it (None: read the text as YAML)."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value, self.value_type = value, value_type

    def evaluate(self, context: LaunchContext, name: str) -> tuple[Any, str | None]:
        """(value, the text it came from when it came from text)."""
        if not _is_text(self.value):
            return self.value, None
        text = perform_all(context, normalize(self.value))
        if self.value_type is str:
            return text, text
        value = _from_yaml(name, text)
        if self.value_type in (int, float, bool) and not isinstance(value, self.value_type):
            raise TypeError(f"value '{text}' of parameter {name} is not a {self.value_type.__name__}")
        return value, text


class ParameterFile:
    """A parameters file (``allow_substs`` is not applied here)."""

    def __init__(self, param_file: Any, *, allow_substs: bool = False) -> None:
        self.param_file, self.allow_substs = param_file, allow_substs


def _is_text(value: Any) -> bool:
    if isinstance(value, str | Substitution):
        return True
    return isinstance(value, list | tuple) and bool(value) and all(isinstance(v, str | Substitution) for v in value) \
        and any(isinstance(v, Substitution) for v in value)


def _uniform(items: list[Any]) -> bool:
    return bool(items) and type(items[0]) in _SCALARS and all(type(v) is type(items[0]) for v in items)


def _from_yaml(name: str, text: str) -> Any:
    try:
        value = yaml.load(text or "''", Loader=_LOADER)
    except yaml.YAMLError:
        raise TypeError(f"Unable to parse the value of parameter {name} as yaml. If the parameter is meant to be a "
                        "string, try wrapping it in launch_ros.parameter_descriptions.ParameterValue"
                        "(value, value_type=str)") from None
    if type(value) in (*_SCALARS, bytes):
        return value
    if isinstance(value, list):
        if not _uniform(value):
            raise TypeError("Expected a non-empty sequence, with items of uniform type. Allowed sequence item types "
                            f"are bool, int, float, str. Got inconsistent input for \"{name}\"")
        return tuple(value)
    raise TypeError(f"Allowed value types are bytes, bool, int, float, str, Sequence[bool], Sequence[int], "
                    f"Sequence[float], Sequence[str]. Got {type(value)} for \"{name}\". If the parameter is meant to "
                    "be a string, try wrapping it in launch_ros.parameter_descriptions.ParameterValue"
                    "(value, value_type=str)")


def evaluate_value(context: LaunchContext, name: str, value: Any) -> tuple[Any, str | None]:
    """launch_ros's value of parameter ``name``: (value, the text it came from, if any)."""
    if isinstance(value, ParameterValue):
        return value.evaluate(context, name)
    if isinstance(value, str):
        return value, value  # launch_ros dumps it as YAML and reads it back: the same text, as text
    if _is_text(value):
        text = perform_all(context, normalize(value))
        return _from_yaml(name, text), text
    if isinstance(value, list | tuple):
        if value and all(isinstance(v, list | tuple) for v in value):
            items = [_from_yaml(name, perform_all(context, normalize(v))) for v in value]
        else:
            items = list(value)
            if items and all(type(v) in (int, float) for v in items):
                items = [float(v) for v in items] if any(type(v) is float for v in items) else items
        if not _uniform(items):
            raise TypeError("Expected a non-empty sequence, with items of uniform type. Allowed sequence item types "
                            f"are bool, int, float, str. Got inconsistent input for \"{name}\"")
        return tuple(items), None
    if not isinstance(value, (*_SCALARS, bytes)):
        raise TypeError(f"Expected 'value' to be one of [float, int, str, bool, bytes], but got '{value}' of type "
                        f"'{type(value)}'")
    return value, None


def yaml_text(value: Any) -> str:
    """``value`` as the YAML text a ``-p NAME:=TEXT`` gives back (strings quoted when YAML would retype them)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value)
    if isinstance(value, tuple | list):
        return "[" + ", ".join(yaml_text(v) for v in value) + "]"
    text = value.decode() if isinstance(value, bytes) else str(value)
    try:
        plain = "\n" not in text and yaml.safe_load(text) == text
    except yaml.YAMLError:
        plain = False
    return text if plain else json.dumps(text)


def _flatten(prefix: str, params: Mapping[Any, Any], out: dict[str, Any], context: LaunchContext) -> None:
    for key, value in params.items():
        name = prefix + (perform_all(context, normalize(key)) if not isinstance(key, str) else key)
        if isinstance(value, Mapping):
            _flatten(name + ".", value, out, context)
        else:
            out[name] = value


class Node(Action):
    """launch_ros's ``Node``: started when robotmodel has that node, listed as skipped otherwise."""

    def __init__(self, *, executable: Any = None, package: Any = None, name: Any = None, namespace: Any = None,
                 exec_name: Any = None, parameters: Iterable[Any] | None = None,
                 remappings: Iterable[tuple[Any, Any]] | None = None, ros_arguments: Iterable[Any] | None = None,
                 arguments: Iterable[Any] | None = None, **kwargs: Any) -> None:
        # Foxy's and older spellings still found in description packages.
        executable = executable if executable is not None else kwargs.pop("node_executable", None)
        name = name if name is not None else kwargs.pop("node_name", None)
        namespace = namespace if namespace is not None else kwargs.pop("node_namespace", None)
        super().__init__(**kwargs)
        if executable is None:
            raise TypeError("Node() missing required keyword argument: 'executable'")
        self.executable, self.package, self.name, self.namespace = executable, package, name, namespace
        self.exec_name = exec_name
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.ros_arguments = list(ros_arguments or [])
        self.arguments = list(arguments or [])

    def execute(self, context: LaunchContext) -> None:
        """Declare the node."""
        try:
            context.nodes.append(self._decl(context))
        except TypeError as exc:
            raise LaunchError(f"{self.where()}: {exc}") from None

    def _decl(self, context: LaunchContext) -> NodeDecl:
        def text(value: Any) -> str:
            return perform_all(context, normalize(value))

        executable = text(self.executable)
        package = text(self.package) if self.package is not None else ""
        name = text(self.name).lstrip("/") if self.name is not None else None
        own_ns = text(self.namespace) if self.namespace is not None else ""
        base = context.frame.ns or "/"
        ns = own_ns if own_ns.startswith("/") else base.rstrip("/") + "/" + own_ns
        ns = "/" + "/".join(p for p in ns.split("/") if p)
        path, line = self.site
        file = path or context.file
        params: dict[str, Param] = {}
        files: list[tuple[Path, int]] = []
        for entry in self.parameters:
            if isinstance(entry, Mapping):
                flat: dict[str, Any] = {}
                _flatten("", entry, flat, context)
                for key, raw in flat.items():
                    params[key] = _param(context, key, raw, file, line)
            elif isinstance(entry, ParameterFile):
                files.append((Path(os.path.abspath(text(entry.param_file))), line))  # noqa: PTH100
            else:
                files.append((Path(os.path.abspath(text(entry))), line))  # noqa: PTH100
        for param_file, _ in files:
            if not param_file.is_file():
                raise LaunchError(f"{file}:{line}: parameters file not found: {param_file}")
        remaps = [*context.frame.remaps, *((text(a), text(b)) for a, b in self.remappings)]
        return NodeDecl(
            pkg=package, executable=executable, name=name or executable.rsplit("/", 1)[-1].removesuffix(".py"),
            namespace=ns, args=shlex.join(text(a) for a in self.arguments), params=params, required=False,
            file=file, line=line, named=name is not None, remaps=tuple(remaps), param_files=tuple(files),
            scope_params=tuple(context.frame.params), ros_args=shlex.join(text(a) for a in self.ros_arguments),
            dialect=Dialect.ROS2,
        )


def _param(context: LaunchContext, name: str, raw: Any, file: Path, line: int) -> Param:
    value, source = evaluate_value(context, name, raw)
    if source is not None and source in context.xacro_outputs and isinstance(value, str):
        return Param(name, xacro=context.xacro_outputs[source], file=file, line=line)
    if isinstance(value, str):
        return Param(name, value=value, file=file, line=line, typed=None if yaml_text(value) == value else
                     yaml_text(value))
    return Param(name, value=yaml_text(value), file=file, line=line)


class LifecycleNode(Node):
    """A lifecycle node: as a node (robotmodel's nodes have no lifecycle)."""


class ComposableNode:
    """A component's description (only its container is listed)."""

    def __init__(self, **kwargs: Any) -> None:
        self.description = kwargs


class PushRosNamespace(Action):
    """Push a namespace for the nodes after it in its scope."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = normalize(namespace)

    def execute(self, context: LaunchContext) -> None:
        """Push it."""
        pushed = perform_all(context, self.namespace)
        base = context.frame.ns or ""
        full = pushed if pushed.startswith("/") else base.rstrip("/") + "/" + pushed
        context.frame.ns = "/" + "/".join(p for p in full.split("/") if p)


PushROSNamespace = PushRosNamespace


class SetParameter(Action):
    """A parameter every node after it in its scope gets."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = name, value

    def execute(self, context: LaunchContext) -> None:
        """Add it."""
        name = perform_all(context, normalize(self.name))
        try:
            value, _ = evaluate_value(context, name, self.value)
        except TypeError as exc:
            raise LaunchError(f"{self.where()}: {exc}") from None
        context.frame.params.append((name, yaml_text(value)))


class SetUseSimTime(SetParameter):
    """``use_sim_time`` for every node after it in its scope."""

    def __init__(self, value: Any, **kwargs: Any) -> None:
        super().__init__("use_sim_time", value, **kwargs)


class SetRemap(Action):
    """A remap rule every node after it in its scope gets (before its own)."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src, self.dst = normalize(src), normalize(dst)

    def execute(self, context: LaunchContext) -> None:
        """Add it."""
        context.frame.remaps.append((perform_all(context, self.src), perform_all(context, self.dst)))


class ComposableNodeContainer(Action):
    """A component container: listed as skipped."""

    def __init__(self, *, name: Any = "", package: Any = "", executable: Any = "", **kwargs: Any) -> None:
        for key in ("namespace", "composable_node_descriptions", "parameters", "remappings", "arguments"):
            kwargs.pop(key, None)
        super().__init__(**kwargs)
        self.name, self.package, self.executable = name, package, executable

    def execute(self, context: LaunchContext) -> None:
        """List it."""
        shown = "/".join(perform_all(context, normalize(v)) for v in (self.package, self.executable))
        context.skipped.append(f"{perform_all(context, normalize(self.name))} ({shown}): component container, "
                               "not started")


class LoadComposableNodes(Action):
    """Components loaded into a container: listed as skipped."""

    def execute(self, context: LaunchContext) -> None:
        """List them."""
        context.skipped.append(f"LoadComposableNodes ({self.where()}): components not loaded")
