"""Launch description sources and ``IncludeLaunchDescription``: Python, XML and YAML launch files.

A Python file is the user's own code, run as ``ros2 launch`` runs it: imported, then its
``generate_launch_description()`` called. An XML or YAML file included from one is read by
the XML launcher with the includer's launch configurations, namespace, ``SetRemap`` and
``SetParameter`` in force (an include is not scoped, so what it sets stays set).
"""

from __future__ import annotations

import importlib.util
import itertools
import traceback
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from robotmodel.errors import LaunchError
from robotmodel.launch._pyactions import Action, LaunchDescription, SetLaunchConfiguration
from robotmodel.launch._pyctx import LaunchContext
from robotmodel.launch._pysubst import TextSubstitution, normalize, perform_all

__all__ = [
    "AnyLaunchDescriptionSource",
    "FrontendLaunchDescriptionSource",
    "IncludeLaunchDescription",
    "LaunchDescriptionSource",
    "PythonLaunchDescriptionSource",
    "XMLLaunchDescriptionSource",
    "YAMLLaunchDescriptionSource",
    "error_site",
    "error_text",
    "include_python",
    "load_python_file",
    "load_yaml_launch",
    "run_python",
]

_MAX_DEPTH = 32
_COUNTER = itertools.count()


class LaunchDescriptionSource:
    """A launch description, given or found at a location (a path, possibly substitutions)."""

    kind = "any"

    def __init__(self, launch_description: Any = None, location: Any = "<script>", method: str = "") -> None:
        del method
        if isinstance(launch_description, LaunchDescription):
            self.given: LaunchDescription | None = launch_description
            self.location = normalize(location)
        else:
            self.given = None
            self.location = normalize(launch_description if launch_description is not None else location)

    def path(self, context: LaunchContext) -> Path:
        """The file, resolved in ``context``."""
        return Path(perform_all(context, self.location))

    def static_path(self) -> Path | None:
        """The file when its location needs no context (for ``--show-args``)."""
        if self.given is None and all(isinstance(s, TextSubstitution) for s in self.location):
            return Path("".join(s.text for s in self.location if isinstance(s, TextSubstitution)))
        return None


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """A Python launch file."""

    kind = "python"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path)


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    """An XML or YAML launch file."""

    kind = "frontend"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path)


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """launch_xml's: an XML launch file."""


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """launch_yaml's: a YAML launch file."""


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """A launch file of any kind, told by its name (``.py``: Python, else XML or YAML)."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path)


def load_python_file(path: Path) -> LaunchDescription:
    """Import ``path`` and call its ``generate_launch_description()``."""
    if not path.is_file():
        raise LaunchError(f"{path}: no such launch file")
    spec = importlib.util.spec_from_file_location(f"robotmodel_launch_file_{next(_COUNTER)}", path)
    if spec is None or spec.loader is None:
        raise LaunchError(f"{path}: cannot be loaded as a Python launch file")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    make = getattr(module, "generate_launch_description", None)
    if not callable(make):
        raise LaunchError(f"launch file at '{path}' does not contain the required function "
                          "'generate_launch_description()'")
    result = make()
    if not isinstance(result, LaunchDescription):
        raise LaunchError(f"{path}: generate_launch_description() returned {type(result).__name__}, "
                          "not a LaunchDescription")
    return result


def _is_python(source: LaunchDescriptionSource, path: Path) -> bool:
    if source.kind == "any":
        return path.suffix == ".py"
    return source.kind == "python"


class IncludeLaunchDescription(Action):
    """Include a launch description with ``launch_arguments`` set as launch configurations (not scoped)."""

    def __init__(self, launch_description_source: Any, *, launch_arguments: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(launch_description_source, LaunchDescriptionSource):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.source = launch_description_source
        self.launch_arguments = [(k, v) for k, v in (launch_arguments or [])]

    @property
    def launch_description_source(self) -> LaunchDescriptionSource:
        """Where the description comes from."""
        source: LaunchDescriptionSource = self.source
        return source

    def get_sub_entities(self) -> list[Any]:
        """The included description when it can be loaded without running (launch's rule, for ``--show-args``)."""
        if self.source.given is not None:
            return [self.source.given]
        path = self.source.static_path()
        if path is None or not path.is_file() or not _is_python(self.source, path):
            return []
        try:
            return [load_python_file(path)]
        except Exception:
            return []

    def static_argument_names(self) -> list[str]:
        """The names of its launch arguments that need no context (text only)."""
        names = []
        for key, _ in self.launch_arguments:
            subs = normalize(key)
            if all(isinstance(s, TextSubstitution) for s in subs):
                names.append("".join(s.text for s in subs if isinstance(s, TextSubstitution)))
        return names

    def execute(self, context: LaunchContext) -> list[Any]:
        """Load it, check its required arguments, set the given ones, then visit it."""
        if context.depth >= _MAX_DEPTH:
            raise LaunchError(f"{self.where()}: includes nested deeper than {_MAX_DEPTH} (an include cycle?)")
        names = [perform_all(context, normalize(k)) for k, _ in self.launch_arguments]
        values = [perform_all(context, normalize(v)) for _, v in self.launch_arguments]
        if self.source.given is not None:
            return [*(SetLaunchConfiguration(k, v) for k, v in zip(names, values, strict=True)), self.source.given]
        path = self.source.path(context)
        if not path.is_absolute():
            path = (context.file.parent / path) if (context.file.parent / path).exists() else Path.cwd() / path
        if not path.is_file():
            raise LaunchError(f"{self.where()}: launch file not found: {path}")
        if not _is_python(self.source, path):
            for name, value in zip(names, values, strict=True):
                context.launch_configurations[name] = value
            _Frontend(path).run(context)
            return []
        description = load_python_file(path)
        known = list(names)
        for argument, includes in description.get_launch_arguments_with_include_launch_description_actions():
            if argument.conditionally_included or argument.default_value is not None:
                continue
            # launch's best effort: the names nested includes pass (where known without running) count too.
            for include in includes or []:
                known.extend(include.static_argument_names())
            if argument.name not in known:
                raise LaunchError(f"{path}: Included launch description missing required argument "
                                  f"'{argument.name}' (description: '{argument.description}'), given: "
                                  f"[{', '.join(known)}]")
        return [_Enter(path), *(SetLaunchConfiguration(k, v) for k, v in zip(names, values, strict=True)),
                description, _Leave(context.file)]


class _Enter(Action):
    def __init__(self, path: Path) -> None:
        super().__init__()
        self.path = path

    def execute(self, context: LaunchContext) -> None:
        context.file = self.path
        context.depth += 1


class _Leave(Action):
    def __init__(self, path: Path) -> None:
        super().__init__()
        self.path = path

    def execute(self, context: LaunchContext) -> None:
        context.file = self.path
        context.depth -= 1


class _Frontend:
    """An XML or YAML file read by the XML launcher inside the Python run's scope."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def run(self, context: LaunchContext) -> None:
        from robotmodel.launch._loader import _Loader
        from robotmodel.launch._model import Dialect
        from robotmodel.launch._readbase import _Scope
        from robotmodel.launch._xml import parse_file
        from robotmodel.launch._yamlfront import parse_yaml_file

        loader = _Loader(context.package_paths, include_python)
        loader.found = context.found
        yaml_file = self.path.name.endswith((".yaml", ".yml"))
        root = parse_yaml_file(self.path) if yaml_file else parse_file(self.path)
        configs: dict[str, str | None] = context.launch_configurations  # type: ignore[assignment]
        scope = _Scope(self.path, Dialect.ROS2, configs, dict(context.launch_configurations), set(),
                       context.frame.ns or "/", context.depth + 1, context.frame.remaps, context.frame.params)
        loader._walk(root.children, scope)
        context.nodes.extend(loader.nodes)
        context.skipped.extend(loader.skipped)
        context.notes.extend(loader.notes)


def load_yaml_launch(path: Path, args: dict[str, str], package_paths: list[Path]) -> Any:
    """A ROS 2 YAML launch file on its own: its nodes, skips and notes (a :class:`LaunchFile`)."""
    from robotmodel.launch._loader import LaunchFile

    context = LaunchContext(path.resolve(), package_paths)
    context.launch_configurations.update(args)
    _Frontend(context.file).run(context)
    return LaunchFile(context.nodes, {}, context.skipped, context.notes, tuple(context.found))


def include_python(loader: Any, path: Path, scope: Any, given: Mapping[str, str], ns: str) -> None:
    """A ROS 2 XML file's ``<include>`` of Python launch file ``path``, run in the includer's scope.

    The included file shares the includer's launch configurations, ``<set_remap>`` and
    ``<set_parameter>`` lists (an include is not scoped); what it declares joins ``loader``'s.
    """
    from robotmodel.launch._pyctx import Frame

    context = LaunchContext(scope.path, loader.package_paths)
    context.found = loader.found
    context.frame = Frame(scope.args, ns if ns != "/" else None, scope.remaps, scope.params)
    context.depth = scope.depth + 1
    run_python(context, path.resolve(), given)
    loader.nodes.extend(context.nodes)
    loader.skipped.extend(context.skipped)
    loader.notes.extend(context.notes)


def run_python(context: Any, path: Path, args: Mapping[str, str]) -> None:
    """Include Python launch file ``path`` with ``args`` into ``context`` and run what it defers."""
    from robotmodel.launch._pyactions import visit
    from robotmodel.launch._pyctx import using
    from robotmodel.launch._pyevents import run_deferred
    from robotmodel.launch._pyimport import standins

    with standins(), using(context):
        try:
            visit(IncludeLaunchDescription(PythonLaunchDescriptionSource(str(path)),
                                           launch_arguments=list(args.items())), context)
            run_deferred(context)
        except LaunchError:
            raise
        except RecursionError:
            raise LaunchError(f"{path}: launch entities nested too deep") from None
        except (Exception, SystemExit) as exc:
            raise LaunchError(f"{error_site(exc, context.file)}: Caught exception in launch (see debug for traceback): "
                              f"{error_text(exc)}") from None


def error_text(exc: BaseException) -> str:
    """An exception as one line (its type when it has no text)."""
    text = " ".join(str(exc).split())
    return text or type(exc).__name__


def error_site(exc: BaseException, fallback: Path) -> str:
    """``FILE:LINE`` of the innermost traceback frame outside robotmodel and the standard library."""
    import sys

    here = Path(__file__).resolve().parent
    system = [Path(p) for p in {sys.prefix, sys.base_prefix, sys.exec_prefix}]
    found = f"{fallback}"
    for frame in traceback.extract_tb(exc.__traceback__):
        path = Path(frame.filename)
        if frame.filename.startswith("<") or path.parent == here or "site-packages" in path.parts:
            continue
        if not any(path.is_relative_to(p) for p in system):
            found = f"{path}:{frame.lineno}"
    return found
