"""The launch XML reader's state, its attribute helpers, and parameters (``<param>``, ``<rosparam>``).

:class:`_Reader` is the part of the reader that :mod:`robotmodel.launch._loader` walks the
elements with: what a load collects (nodes, ROS 1 global parameters, skips, notes, the
packages ``$(find)`` resolved), attributes read through the substitutions in scope, and the
parameter forms of both dialects: a value (typed as roslaunch types it, for ROS 1), a
``textfile``, a xacro ``command`` (expanded once per distinct command, so a failing xacro
is an error before anything starts), ROS 2 nested ``<param>``s and params files, and
``<rosparam>`` YAML.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robotmodel.errors import LaunchError
from robotmodel.launch._model import Dialect, NodeDecl, Param, XacroSource
from robotmodel.launch._ptype import ros1_param_text
from robotmodel.launch._remaps import Remap
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
from robotmodel.launch._xml import Element, where

__all__ = ["PythonInclude", "join_ns"]

#: (reader, file, includer's scope, the include's arguments, namespace) -> None
PythonInclude = Callable[[Any, Path, Any, Mapping[str, str], str], None]


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


class _Reader:
    def __init__(self, package_paths: Sequence[Path], python_include: PythonInclude | None = None) -> None:
        self.package_paths = list(package_paths)
        # How a ROS 2 <include> of a Python launch file runs (robotmodel.launch._pysources.include_python),
        # handed in so that this reader does not import the Python launch machinery, which imports it.
        self.python_include = python_include
        self.nodes: list[NodeDecl] = []
        self.params: dict[str, Param] = {}
        self.skipped: list[str] = []
        self.notes: list[str] = []
        self.expanded: set[XacroSource] = set()
        self.found: dict[Path, None] = {}

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
