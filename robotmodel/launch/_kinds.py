"""Which ``robotmodel`` command stands in for each kind of node, with its parameters mapped.

| node (pkg / executable)                                  | command                        |
|----------------------------------------------------------|--------------------------------|
| robot_state_publisher / robot_state_publisher, state_publisher | ``robot-state-publisher FILE`` |
| joint_state_publisher / joint_state_publisher            | ``joint-state-publisher [FILE]`` (``use_gui``: the GUI) |
| joint_state_publisher_gui / joint_state_publisher_gui    | ``joint-state-publisher-gui [FILE]`` |
| tf or tf2_ros / static_transform_publisher               | ``static-transform-publisher ARGS`` |
| rviz / rviz, rviz2 / rviz2                               | ``view --follow`` (robot from /robot_description) |

Any other node is skipped with one line. ``robot_description`` is the node's own
parameter, else (ROS 1) the nearest one up its namespace, as ``searchParam`` finds it; a
xacro command becomes ``FILE name:=value ...`` so the command expands it itself.

What ROS hands a node on its command line follows in one ``--ros-args`` block, as
launch_ros writes it: ``-r __node:=NAME`` (a name the file gave, unless it is the
command's own), ``-r __ns:=/NS`` (outside the root namespace), ``-p name:=value`` for each
parameter not mapped onto a flag above (or set after one of the node's params files:
a flag would lose to the file, whereas ROS's later value wins), ``--params-file FILE`` for ROS 2's
``<param from="FILE"/>`` (these two in the file's order), then the remap rules
``-r from:=to`` in the order the node should try them. The command's own parameter
mapping then decides, and names what it ignores.
"""

from __future__ import annotations

import shlex
from collections.abc import Mapping, Sequence
from dataclasses import replace
from pathlib import Path

import yaml

from robotmodel.errors import LaunchError
from robotmodel.launch._executables import JSP, JSP_GUI, RSP, RVIZ, STATIC
from robotmodel.launch._loader import LaunchFile, join_ns
from robotmodel.launch._model import Dialect, LaunchPlan, NodeDecl, Param, ProcessSpec
from robotmodel.launch._rosargs import ros_tail

__all__ = ["build_plan"]

_RSP, _JSP, _JSP_GUI, _STATIC, _RVIZ = RSP, JSP, JSP_GUI, STATIC, RVIZ
_JSP_PARAMS = frozenset({"use_gui", "rate", "zeros", "source_list"})


def build_plan(launch: LaunchFile, workdir: Path, *, package_paths: Sequence[Path] = (),
               browser: bool = True, ros1: bool = False) -> LaunchPlan:
    """Map the declared nodes to processes; a literal robot_description is written into ``workdir``.

    ``ros1``: the processes run on the ROS 1 wire, where roslaunch has put the parameters on
    the parameter server (:func:`robotmodel.launch._ros1params.set_on_server`): a node whose
    robot_description is found there reads it from there, as ROS 1's nodes do (no FILE words).
    """
    plan = LaunchPlan(skipped=list(launch.skipped), notes=list(launch.notes))
    mapper = _Mapper(launch.params, workdir, package_paths, browser, launch.packages)
    mapper.ros1 = ros1
    for node in launch.nodes:
        key = (node.pkg, node.executable)
        label = f"{node.full_name} ({node.pkg}/{node.executable})"
        if key in _RSP | _JSP | _JSP_GUI | _STATIC | _RVIZ:
            late = _after_params_file(node, key)
            flagged = replace(node, params={k: v for k, v in node.params.items() if k not in late})
            spec = mapper.map(flagged, key)
            if isinstance(spec, str):
                plan.skipped.append(f"{label}: {spec}")
                continue
            plan.processes.append(ros_tail(spec, node, mapper.consumed(flagged, key) - late, plan.notes))
        else:
            plan.skipped.append(f"{label}: no robotmodel equivalent, not started")
    return plan


def _after_params_file(node: NodeDecl, key: tuple[str, str]) -> frozenset[str]:
    """The flag-mapped parameters set after one of the node's params files.

    A flag is only the command's default, which any params file overrides; such a parameter
    travels as ``-p`` after the file instead, so the later one wins as in ROS.
    """
    if not node.param_files:
        return frozenset()
    first = min(line for _, line in node.param_files)
    if key in _RSP:
        names = {"publish_frequency", "frame_prefix", "ignore_timestamp"}
    elif key in _JSP and not _flag(node, "use_gui"):
        names = {"rate", "source_list", "zeros"} | {n for n in node.params if n.startswith("zeros.")}
    else:
        return frozenset()
    return frozenset(n for n in names if n in node.params and node.params[n].line > first)


class _Mapper:
    def __init__(self, params: Mapping[str, Param], workdir: Path, package_paths: Sequence[Path],
                 browser: bool, found: Sequence[Path] = ()) -> None:
        self.params = params
        self.found = list(found)
        self.workdir = workdir
        self.package_paths = list(package_paths)
        self.browser = browser
        self.written = 0
        self.ros1 = False

    def map(self, node: NodeDecl, key: tuple[str, str]) -> ProcessSpec | str:
        if key in _STATIC:
            return ProcessSpec(node.full_name, "static_transform_publisher",
                               ("static-transform-publisher", *_split(node)), node.required)
        if key in _RVIZ:
            # The viewer sees only the description's text: the packages the launch file found are
            # where its package:// URIs point (the other nodes find them beside their xacro file).
            found = tuple(w for p in self.found if not any(p == q or q in p.parents for q in self.package_paths)
                          for w in ("--package-path", str(p)))
            return ProcessSpec(node.full_name, "rviz", ("view", "--follow", *self._paths(), *found, *self._page()),
                               node.required)
        description = self._description(node)
        if self.ros1 and self._param(node) is not None:
            description = ()  # on the server: the node searches it up its namespace itself
        elif key in _RSP and not description:
            return "no robot_description parameter for it"
        if key in _RSP:
            return ProcessSpec(node.full_name, "robot_state_publisher",
                               ("robot-state-publisher", *description, *self._paths(), *_rsp_options(node)),
                               node.required)
        if key in _JSP | _JSP_GUI:
            node = self._jsp_params(node)
        if key in _JSP and not _flag(node, "use_gui"):
            return ProcessSpec(node.full_name, "joint_state_publisher",
                               ("joint-state-publisher", *description, *self._paths(), *_jsp_options(node)),
                               node.required)
        joints = [f"--joint={name}={value}" for name, value in _zeros(node)]
        return ProcessSpec(node.full_name, "joint_state_publisher_gui",
                           ("joint-state-publisher-gui", *description, *self._paths(), *joints, *self._page()),
                           node.required)

    def consumed(self, node: NodeDecl, key: tuple[str, str]) -> frozenset[str]:
        """The node's parameters this mapping turned into the command's words (the rest go as ``-p``)."""
        if key in _RSP:
            return frozenset({"robot_description", "publish_frequency", "frame_prefix", "ignore_timestamp"})
        if key in _JSP | _JSP_GUI:
            node = self._jsp_params(node)
            names = {"robot_description", "use_gui", "zeros"} | {n for n in node.params if n.startswith("zeros.")}
            if key in _JSP and not _flag(node, "use_gui"):
                names |= {"rate", "source_list"}
            return frozenset(names)
        return frozenset()

    def _jsp_params(self, node: NodeDecl) -> NodeDecl:
        # ROS 1's joint_state_publisher reads each parameter as ~name, else as name in its
        # namespace: display.launch files of that era set use_gui at the top level.
        merged = dict(node.params)
        prefix = node.namespace.rstrip("/") + "/"
        for full, param in self.params.items():
            if not full.startswith(prefix) or "/" in full[len(prefix):]:
                continue
            name = full[len(prefix):]
            if name.split(".")[0] in _JSP_PARAMS and name not in merged:
                merged[name] = param
        return replace(node, params=merged)

    def _page(self) -> tuple[str, ...]:
        # No --port: each page binds the first free port from 7000 up, so pages never race for one.
        return ("--open",) if self.browser else ()

    def _paths(self) -> tuple[str, ...]:
        return tuple(w for p in self.package_paths for w in ("--package-path", str(p)))

    def _description(self, node: NodeDecl) -> tuple[str, ...]:
        param = self._param(node)
        if param is None:
            # ROS 2's joint_state_publisher takes the URDF as its first argument.
            words = _split(node)
            if node.pkg == "joint_state_publisher" and words and not words[0].startswith("-"):
                return (str(Path(words[0]).resolve()),)
            return ()
        if param.xacro is not None:
            return (str(param.xacro.file), *(f"{k}:={v}" for k, v in param.xacro.mappings))
        if param.textfile is not None:
            return (str(param.textfile),)
        self.written += 1
        path = self.workdir / f"robot_description_{self.written}.urdf"
        # Leading blanks go: urdfdom's XML parser skips them, an XML declaration may not follow them here.
        path.write_text((param.value or "").lstrip(), encoding="utf-8")
        return (str(path),)

    def _param(self, node: NodeDecl) -> Param | None:
        param = node.params.get("robot_description")
        if param is None:
            # ROS 1 searchParam: the node's namespace, then each parent up to the root; a remap
            # of the name as written applies first (roscpp matches it unresolved), so
            # <remap from="robot_description" to="arm_description"/> reads arm_description.
            key = "robot_description"
            if node.dialect is Dialect.ROS1:
                key = next((to for source, to in node.remaps if source == key), key)
            ns = node.namespace
            while param is None:
                param = self.params.get(join_ns(ns, key))
                if ns == "/" or key.startswith("/"):
                    break
                ns = ns.rsplit("/", 1)[0] or "/"
        return param


def _split(node: NodeDecl) -> list[str]:
    try:
        return shlex.split(node.args)
    except ValueError as exc:
        raise LaunchError(f"{node.file}:{node.line}: args=\"{node.args}\": {exc}") from None


def _value(node: NodeDecl, name: str) -> object:
    param = node.params.get(name)
    if param is None or param.value is None:
        return None
    try:
        return yaml.safe_load(param.typed if param.typed is not None else param.value)
    except yaml.YAMLError:
        return param.value


def _flag(node: NodeDecl, name: str) -> bool:
    value = _value(node, name)
    return value is True or (isinstance(value, str) and value.lower() == "true") or value == 1


def _number(node: NodeDecl, name: str) -> str | None:
    value = _value(node, name)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float):
        param = node.params[name]
        raise LaunchError(f"{param.file}:{param.line}: parameter '{name}' of {node.full_name} must be a number, "
                          f"got '{param.value}'")
    return str(value)


def _rsp_options(node: NodeDecl) -> list[str]:
    out: list[str] = []
    freq = _number(node, "publish_frequency")
    if freq is not None:
        out += ["--publish-frequency", freq]
    prefix = _value(node, "frame_prefix")
    if prefix:
        out += ["--frame-prefix", str(prefix)]
    if _flag(node, "ignore_timestamp"):
        out.append("--ignore-timestamp")
    return out


def _zeros(node: NodeDecl) -> list[tuple[str, str]]:
    found: dict[str, str] = {}
    whole = _value(node, "zeros")
    if isinstance(whole, dict):
        found.update({str(k): str(v) for k, v in whole.items()})
    for name in node.params:
        if name.startswith("zeros."):
            found[name.removeprefix("zeros.")] = str(_number(node, name))
    return sorted(found.items())


def _jsp_options(node: NodeDecl) -> list[str]:
    out: list[str] = []
    rate = _number(node, "rate")
    if rate is not None:
        out += ["--rate", rate]
    zeros = _zeros(node)
    if zeros:
        out += ["--zeros", *(f"{k}={v}" for k, v in zeros)]
    sources = _value(node, "source_list")
    if isinstance(sources, str):
        sources = [sources]
    if isinstance(sources, list) and sources:
        out += ["--source-list", *(str(s) for s in sources)]
    return out
