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
  from a params file (``<param from="FILE"/>``).
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from robotmodel.errors import LaunchError
from robotmodel.launch._dialect import detect_dialect
from robotmodel.launch._model import Dialect, NodeDecl, Param, XacroSource
from robotmodel.launch._ptype import ros1_param_text
from robotmodel.launch._remaps import Remap, ros1_add, ros1_for_node, ros1_problem
from robotmodel.launch._rosparam import read_rosparam_file, rosparam_params
from robotmodel.launch._subst import (
    Sub,
    SubstContext,
    expand_xacro,
    parse,
    parse_xacro_command,
    resolve,
    resolve_parts,
    truth,
)
from robotmodel.launch._xml import Element, parse_file, where

__all__ = ["LaunchFile", "join_ns", "load_launch_file"]

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


@dataclass
class _Scope:
    path: Path
    dialect: Dialect
    args: dict[str, str | None]
    passed: dict[str, str]
    declared: set[str]
    ns: str
    depth: int
    #: Remap rules in force for the nodes that follow (ROS 1 <remap>, ROS 2 <set_remap>).
    remaps: list[Remap] = field(default_factory=list)
    #: ROS 2 <set_parameter> values (name, value) for the nodes that follow, scoped as the remaps.
    params: list[tuple[str, str]] = field(default_factory=list)


def join_ns(base: str, name: str) -> str:
    """``name`` under namespace ``base`` (absolute names kept); always absolute, no trailing '/'."""
    full = name if name.startswith("/") else base.rstrip("/") + "/" + name
    parts = [p for p in full.split("/") if p]
    return "/" + "/".join(parts)


def load_launch_file(path: Path, args: Mapping[str, str], package_paths: Sequence[Path] = ()) -> LaunchFile:
    """Read ``path`` with command-line ``args``; raises LaunchError (``FILE:LINE: ...``) on bad input."""
    loader = _Loader(package_paths)
    try:
        loader.load_top(path.resolve(), dict(args))
    except RecursionError:
        raise LaunchError(f"{path}: elements nested too deep") from None
    return LaunchFile(loader.nodes, loader.params, loader.skipped, loader.notes, tuple(loader.found))


class _Loader:
    def __init__(self, package_paths: Sequence[Path]) -> None:
        self.package_paths = list(package_paths)
        self.nodes: list[NodeDecl] = []
        self.params: dict[str, Param] = {}
        self.skipped: list[str] = []
        self.notes: list[str] = []
        self.expanded: set[XacroSource] = set()
        self.found: dict[Path, None] = {}

    def load_top(self, path: Path, args: dict[str, str]) -> None:
        root = parse_file(path)
        dialect = detect_dialect(path, root)
        configs: dict[str, str | None] = dict(args) if dialect is Dialect.ROS2 else {}
        self._walk(root.children, _Scope(path, dialect, configs, dict(args), set(), "/", 0))

    # -- helpers -----------------------------------------------------------------
    def _ctx(self, scope: _Scope, elem: Element) -> SubstContext:
        return SubstContext(scope.path, elem.line, scope.dialect, scope.args, self.package_paths, self.found)

    def _attr(self, scope: _Scope, elem: Element, name: str, *, required: bool = False) -> str | None:
        raw = elem.attrib.get(name)
        if raw is None:
            if required:
                raise LaunchError(f"{where(scope.path, elem.line)}: <{elem.tag}> needs a '{name}' attribute")
            return None
        return resolve(raw, self._ctx(scope, elem))

    def _req(self, scope: _Scope, elem: Element, name: str) -> str:
        value = self._attr(scope, elem, name, required=True)
        assert value is not None
        return value

    def _enabled(self, scope: _Scope, elem: Element) -> bool:
        ctx = self._ctx(scope, elem)
        cond_if, cond_unless = self._attr(scope, elem, "if"), self._attr(scope, elem, "unless")
        if cond_if is not None and cond_unless is not None and scope.dialect is Dialect.ROS1:
            raise ctx.error(f"<{elem.tag}>: cannot set both 'if' and 'unless' on the same tag")
        if cond_if is not None and not truth(cond_if, ctx, "if"):
            return False
        return not (cond_unless is not None and truth(cond_unless, ctx, "unless"))

    # -- walking -----------------------------------------------------------------
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
        if path.suffix in (".py", ".yaml", ".yml"):
            self.skipped.append(f"<include> {path} ({where(scope.path, elem.line)}): only XML launch files are read")
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
        root = parse_file(path)
        dialect = detect_dialect(path, root, scope.dialect)
        ns = join_ns(scope.ns, self._attr(scope, elem, "ns") or "")
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

    # -- parameters ----------------------------------------------------------------
    def _param(self, scope: _Scope, elem: Element, prefix: str = "") -> list[Param]:
        name = prefix + self._req(scope, elem, "name")
        ctx = self._ctx(scope, elem)
        if elem.children and scope.dialect is Dialect.ROS2:
            out: list[Param] = []
            for child in elem.children:
                if child.tag == "param" and self._enabled(scope, child):
                    out.extend(self._param(scope, child, name + "."))
            return out
        raw_value = elem.attrib.get("value")
        if raw_value is not None:
            parts = parse(raw_value, ctx)
            if len(parts) == 1 and isinstance(parts[0], Sub) and parts[0].name == "command" and parts[0].args:
                return [self._xacro_param(name, resolve_parts(parts[0].args[0], ctx), ctx)]
            value = resolve_parts(parts, ctx)
            typed = None
            if scope.dialect is Dialect.ROS1:
                try:
                    typed = ros1_param_text(value, self._attr(scope, elem, "type"))
                except ValueError as exc:
                    raise ctx.error(f"<param name=\"{name}\">: {exc}") from None
            return [Param(name, value=value, file=scope.path, line=elem.line, typed=typed)]
        textfile = self._attr(scope, elem, "textfile")
        if textfile is not None:
            path = Path(textfile)
            if not path.is_file():
                raise ctx.error(f"<param name=\"{name}\">: textfile not found: {path}")
            return [Param(name, textfile=path.resolve(), file=scope.path, line=elem.line)]
        command_text = self._attr(scope, elem, "command")
        if command_text is not None:
            return [self._xacro_param(name, command_text, ctx)]
        if "binfile" in elem.attrib or "from" in elem.attrib:
            self.notes.append(f"{where(scope.path, elem.line)}: <param name=\"{name}\"> from a file ignored")
            return []
        raise ctx.error(f"<param name=\"{name}\"> needs value, textfile or command")

    def _xacro_param(self, name: str, command: str, ctx: SubstContext) -> Param:
        source = parse_xacro_command(command, ctx)
        # roslaunch runs a <param command> while it reads the file, ros2 launch a $(command) as
        # the node starts: either way a xacro that fails ends the launch before anything runs.
        # The nodes expand it again themselves; it is checked here once per distinct command.
        if source not in self.expanded:
            expand_xacro(command, source, ctx, name)
            self.expanded.add(source)
        return Param(name, xacro=source, file=ctx.path, line=ctx.line)

    def _params_file(self, scope: _Scope, elem: Element, files: list[tuple[Path, int]]) -> None:
        # launch_ros makes it absolute without resolving links (the node sees the path as written).
        path = Path(os.path.abspath(self._req(scope, elem, "from")))  # noqa: PTH100
        if path.is_file():
            files.append((path, elem.line))
        else:
            # launch_ros warns and starts the node without it.
            self.notes.append(f"{where(scope.path, elem.line)}: Parameter file path is not a file: {path}")

    def _global_param(self, scope: _Scope, elem: Element, ns: str) -> None:
        if scope.dialect is Dialect.ROS2:
            self.notes.append(f"{where(scope.path, elem.line)}: <param> outside a node ignored (ROS 2)")
            return
        for p in self._param(scope, elem):
            self.params[join_ns(ns, p.name)] = p

    def _rosparam(self, scope: _Scope, elem: Element) -> list[Param]:
        ctx = self._ctx(scope, elem)
        command = self._attr(scope, elem, "command") or "load"
        if command != "load":
            self.notes.append(f"{where(scope.path, elem.line)}: <rosparam command=\"{command}\"> ignored")
            return []
        file = self._attr(scope, elem, "file")
        if file is None:
            text = resolve(elem.text, ctx)
        else:
            text = read_rosparam_file(Path(file), ctx)
            subst = self._attr(scope, elem, "subst_value")
            if subst is not None and truth(subst, ctx, "subst_value"):
                text = resolve(text, ctx)
        base = join_ns(self._attr(scope, elem, "ns") or "", self._attr(scope, elem, "param") or "").lstrip("/")
        return rosparam_params(text, base, ctx)

    # -- nodes ---------------------------------------------------------------------
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
