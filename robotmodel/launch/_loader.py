"""Reading launch files (ROS 1 roslaunch XML and ROS 2 launch XML) into nodes and parameters.

Scoping follows each system:

- ROS 1: args belong to one file (a ``<group>`` does not scope them); an ``<include>``
  sees only the args passed to it (all of them with ``pass_all_args``), an arg declared
  with ``value`` cannot be set from outside, and an arg passed to an include that does
  not declare it is an error. Parameters outside nodes are global, under the group's
  ``ns``; a node finds ``robot_description`` by searching up from its namespace. A
  ``<remap>`` outside a node applies to the nodes after it in its group or file and in the
  files that file includes afterwards (:mod:`robotmodel.launch._remaps`).
- ROS 2: ``<arg>`` and ``<let>`` set launch configurations; a ``<group>`` scopes them
  (unless ``scoped="false"``), an ``<include>`` does not, so its arguments stay set after
  it, as upstream does. Namespaces come from ``<push-ros-namespace>`` and the node's
  ``namespace``; ``<set_remap>`` and ``<set_parameter>`` live in the configurations (an
  include shares its includer's; a group's end with it, unless the scope already had some,
  which launch_ros then extends in place). Parameters belong to nodes, inline or
  from a params file (``<param from="FILE"/>``). A ROS 2 file's ``<include>`` of a Python
  launch file runs it in that scope (:func:`robotmodel.launch._pyload.include_python`), of a
  YAML one reads it as XML; roslaunch includes only XML, so a ROS 1 file's are skipped.

The reader's state, attribute helpers and parameter forms are :mod:`robotmodel.launch._readbase`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from robotmodel.errors import LaunchError
from robotmodel.launch._dialect import detect_dialect
from robotmodel.launch._model import Dialect, NodeDecl, Param
from robotmodel.launch._readbase import PythonInclude, _Reader, _Scope, join_ns
from robotmodel.launch._remaps import Remap, ros1_add, ros1_for_node, ros1_problem
from robotmodel.launch._subst import (
    truth,
)
from robotmodel.launch._xml import Element, parse_file, where

__all__ = ["LaunchFile", "join_ns", "read_launch_xml"]

_MAX_DEPTH = 32
_IGNORED = frozenset({
    "env", "machine", "set_env", "unset_env", "set-env", "unset-env", "log", "timer", "set_parameters_from_file",
})
_SET_PARAMETER = frozenset({"set_parameter", "set-parameter"})
_SET_REMAP = frozenset({"set_remap", "set-remap"})


@dataclass
class LaunchFile:
    """Everything a launch file declares: its nodes in order, ROS 1 global parameters, skips and notes."""

    nodes: list[NodeDecl]
    params: dict[str, Param]
    skipped: list[str]
    notes: list[str]
    packages: tuple[Path, ...] = ()  # the packages its $(find)s resolved, in first-use order


def read_launch_xml(path: Path, args: Mapping[str, str], package_paths: Sequence[Path] = (),
                    python_include: PythonInclude | None = None) -> LaunchFile:
    """Read ``path`` with command-line ``args``; raises LaunchError (``FILE:LINE: ...``) on bad input.

    ``python_include`` runs a ROS 2 ``<include>`` of a Python launch file (None: listed as skipped).
    """
    loader = _Loader(package_paths, python_include)
    try:
        loader.load_top(path.resolve(), dict(args))
    except RecursionError:
        raise LaunchError(f"{path}: elements nested too deep") from None
    return LaunchFile(loader.nodes, loader.params, loader.skipped, loader.notes, tuple(loader.found))


class _Loader(_Reader):
    def load_top(self, path: Path, args: dict[str, str]) -> None:
        root = parse_file(path)
        dialect = detect_dialect(path, root)
        configs: dict[str, str | None] = dict(args) if dialect is Dialect.ROS2 else {}
        self._walk(root.children, _Scope(path, dialect, configs, dict(args), set(), "/", 0))

    def _walk(self, elems: list[Element], scope: _Scope) -> None:
        for elem in elems:
            if not self._enabled(scope, elem):
                continue
            tag = elem.tag
            if tag == "arg":
                self._arg(scope, elem)
            elif tag == "let":
                scope.args[self._req(scope, elem, "name")] = self._req(scope, elem, "value")
            elif tag == "include":
                self._include(scope, elem)
            elif tag == "group":
                self._group(scope, elem)
            elif tag in ("push-ros-namespace", "push_ros_namespace"):
                scope.ns = join_ns(scope.ns, self._req(scope, elem, "namespace"))
            elif tag == "node":
                self._node(scope, elem)
            elif tag == "remap" or (tag in _SET_REMAP and scope.dialect is Dialect.ROS2):
                self._scope_remap(scope, elem)
            elif tag in _SET_PARAMETER and scope.dialect is Dialect.ROS2:
                scope.params.append((self._req(scope, elem, "name"), self._req(scope, elem, "value")))
            elif tag == "param":
                self._global_param(scope, elem, scope.ns)
            elif tag == "rosparam":
                for p in self._rosparam(scope, elem):
                    self.params[join_ns(scope.ns, p.name)] = p
            elif tag in ("executable", "test"):
                shown = self._attr(scope, elem, "cmd") or self._attr(scope, elem, "type") or ""
                self.skipped.append(f"<{tag}> {shown} ({where(scope.path, elem.line)}): not run")
            elif tag in _IGNORED:
                self.notes.append(f"{where(scope.path, elem.line)}: <{tag}> ignored")
            else:
                self.notes.append(f"{where(scope.path, elem.line)}: unknown tag <{tag}> ignored")

    def _arg(self, scope: _Scope, elem: Element) -> None:
        name = self._req(scope, elem, "name")
        ctx = self._ctx(scope, elem)
        value, default = self._attr(scope, elem, "value"), self._attr(scope, elem, "default")
        if scope.dialect is Dialect.ROS2:
            if value is not None:
                scope.args[name] = value
            elif name not in scope.args or scope.args[name] is None:
                if default is None:
                    # ros2 launch includes the top file too, so the text is the include's either way.
                    given = ", ".join(scope.passed)
                    desc = elem.attrib.get("description", "no description given")
                    raise ctx.error(f"Included launch description missing required argument '{name}' "
                                    f"(description: '{desc}'), given: [{given}]")
                scope.args[name] = default
            return
        if name in scope.declared:
            raise ctx.error(f"arg '{name}' has already been declared")
        scope.declared.add(name)
        if value is not None:
            if name in scope.passed:
                raise ctx.error(f"cannot override arg '{name}', which has already been set")
            scope.args[name] = value
        elif default is not None:
            scope.args[name] = scope.passed.get(name, default)
        else:
            scope.args[name] = scope.passed.get(name)

    def _include(self, scope: _Scope, elem: Element) -> None:
        ctx = self._ctx(scope, elem)
        if scope.depth >= _MAX_DEPTH:
            raise ctx.error(f"includes nested deeper than {_MAX_DEPTH} (an include cycle?)")
        text = self._req(scope, elem, "file")
        path = Path(text)
        if not path.is_absolute():
            beside = scope.path.parent / path
            path = beside if beside.exists() else Path.cwd() / path
        if not path.is_file():
            raise ctx.error(f"<include>: launch file not found: {path}")
        if path.suffix in (".py", ".yaml", ".yml") and scope.dialect is Dialect.ROS1:
            self.skipped.append(f"<include> {path} ({where(scope.path, elem.line)}): roslaunch reads only XML "
                                "launch files")
            return
        given: dict[str, str] = {}
        for child in elem.children:
            if child.tag == "arg" and self._enabled(scope, child):
                value = self._attr(scope, child, "value")
                if value is None:
                    value = self._attr(scope, child, "default", required=True)
                assert value is not None
                given[self._req(scope, child, "name")] = value
            elif child.tag in ("remap", *_SET_REMAP):
                # Neither roslaunch nor launch_ros applies it there: it has to precede the include.
                self.notes.append(f"{where(scope.path, child.line)}: <{child.tag}> inside <include> ignored")
        ns = join_ns(scope.ns, self._attr(scope, elem, "ns") or "")
        if path.suffix == ".py":
            if self.python_include is None:
                self.skipped.append(f"<include> {path} ({where(scope.path, elem.line)}): no Python launch support here")
                return
            self.python_include(self, path, scope, given, ns)
            return
        if path.suffix in (".yaml", ".yml"):
            from robotmodel.launch._yamlfront import parse_yaml_file

            root, dialect = parse_yaml_file(path), Dialect.ROS2
        else:
            root = parse_file(path)
            dialect = detect_dialect(path, root, scope.dialect)
        if dialect is Dialect.ROS2:
            configs = scope.args if scope.dialect is Dialect.ROS2 else {}
            configs.update(given)
            # Not scoped: its <set_remap> rules stay in force after it, as its configurations do.
            shared = scope.dialect is Dialect.ROS2
            remaps = scope.remaps if shared else list(scope.remaps)
            params = scope.params if shared else []
            self._walk(root.children, _Scope(path, dialect, configs, given, set(), ns, scope.depth + 1, remaps,
                                             params))
            return
        passed = {}
        pass_all = self._attr(scope, elem, "pass_all_args")
        if pass_all is not None and truth(pass_all, ctx, "pass_all_args"):
            passed = {k: v for k, v in scope.args.items() if v is not None}
        passed.update(given)
        inner = _Scope(path, dialect, {}, passed, set(), ns, scope.depth + 1, list(scope.remaps))
        self._walk(root.children, inner)
        unused = sorted(set(given) - inner.declared)
        if unused:
            raise ctx.error(f"unused args [{', '.join(unused)}] for include of [{path}]")

    def _group(self, scope: _Scope, elem: Element) -> None:
        ns = join_ns(scope.ns, self._attr(scope, elem, "ns") or "")
        inner = replace(scope, ns=ns, remaps=list(scope.remaps), params=list(scope.params))
        if scope.dialect is Dialect.ROS2:
            scoped = self._attr(scope, elem, "scoped")
            if scoped is None or truth(scoped, self._ctx(scope, elem), "scoped"):
                inner.args = dict(scope.args)
                # launch_ros appends <set_remap>/<set_parameter> to the list already in the
                # configurations, which a group copies shallowly: once the scope has one, the
                # group's additions stay in force after it too. Only a fresh list stays inside.
                inner.remaps = scope.remaps if scope.remaps else []
                inner.params = scope.params if scope.params else []
            else:
                inner.remaps, inner.params = scope.remaps, scope.params
        self._walk(elem.children, inner)

    # -- remaps --------------------------------------------------------------------
    def _remap(self, scope: _Scope, elem: Element, rules: list[Remap]) -> None:
        source, target = self._req(scope, elem, "from"), self._req(scope, elem, "to")
        if scope.dialect is Dialect.ROS2:
            rules.append((source, target))  # checked by rcl when the node starts, as in ROS
            return
        problem = ros1_problem(source, target)
        if problem:
            raise self._ctx(scope, elem).error(problem)
        ros1_add(rules, source, target)

    def _scope_remap(self, scope: _Scope, elem: Element) -> None:
        if scope.dialect is Dialect.ROS2 and elem.tag == "remap":
            self.notes.append(f"{where(scope.path, elem.line)}: <remap> outside a <node> ignored "
                              "(ROS 2 launch: <set_remap>)")
            return
        self._remap(scope, elem, scope.remaps)

    def _node(self, scope: _Scope, elem: Element) -> None:
        pkg = self._req(scope, elem, "pkg")
        exe_attr = "exec" if scope.dialect is Dialect.ROS2 else "type"
        executable = self._attr(scope, elem, exe_attr) or self._attr(scope, elem, "type" if exe_attr == "exec"
                                                                     else "exec")
        if executable is None:
            raise LaunchError(f"{where(scope.path, elem.line)}: <node> needs a '{exe_attr}' attribute")
        name = self._attr(scope, elem, "name") or executable.rsplit("/", 1)[-1].removesuffix(".py")
        ns_attr = self._attr(scope, elem, "namespace") or self._attr(scope, elem, "ns") or ""
        params: dict[str, Param] = {}
        files: list[tuple[Path, int]] = []
        remaps = list(scope.remaps)
        for child in elem.children:
            if not self._enabled(scope, child):
                continue
            if child.tag == "param" and "from" in child.attrib and scope.dialect is Dialect.ROS2:
                self._params_file(scope, child, files)
            elif child.tag == "param":
                for p in self._param(scope, child):
                    params[p.name.replace("/", ".")] = p
            elif child.tag == "rosparam":
                for p in self._rosparam(scope, child):
                    params[p.name] = p
            elif child.tag == "remap":
                self._remap(scope, child, remaps)
        namespace = join_ns(scope.ns, ns_attr)
        required = self._attr(scope, elem, "required") or "false"
        self.nodes.append(NodeDecl(
            pkg=pkg, executable=executable, name=name, namespace=namespace,
            args=self._attr(scope, elem, "args") or "", params=params,
            required=truth(required, self._ctx(scope, elem), "required"), file=scope.path, line=elem.line,
            named="name" in elem.attrib, scope_params=tuple(scope.params),
            ros_args=self._attr(scope, elem, "ros_args") or "", dialect=scope.dialect,
            remaps=tuple(remaps) if scope.dialect is Dialect.ROS2 else ros1_for_node(remaps, namespace, name),
            param_files=tuple(files),
        ))
