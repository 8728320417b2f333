"""The values a launch file is read into: declared nodes and parameters, and the resulting plan."""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "Dialect",
    "LaunchPlan",
    "NodeDecl",
    "Param",
    "ProcessSpec",
    "XacroSource",
]


class Dialect(enum.Enum):
    """Which launch XML a file is written in."""

    ROS1 = "ros1"
    ROS2 = "ros2"


@dataclass(frozen=True)
class XacroSource:
    """A robot description made by running xacro on ``file`` with ``name:=value`` mappings."""

    file: Path
    mappings: tuple[tuple[str, str], ...] = ()


@dataclass(frozen=True)
class Param:
    """One parameter: a literal ``value``, the contents of ``textfile``, or xacro's output.

    ``file`` and ``line`` say where it was set (for messages). ``typed`` is the value as a
    ``-p`` value's YAML text where the launch system fixes its type (ROS 1's ``type``
    attribute and its guess without one); None: ``value`` as written.
    """

    name: str
    value: str | None = None
    textfile: Path | None = None
    xacro: XacroSource | None = None
    file: Path | None = None
    line: int = 0
    typed: str | None = None


@dataclass(frozen=True)
class NodeDecl:
    """A ``<node>`` after substitution: what ROS would start, before it is mapped to a command.

    ``namespace`` is absolute (``/`` at the root); ``params`` are the node's own (private)
    parameters by relative name (``zeros.j1`` for ROS 2's nested parameters). ``named``
    says whether the file gave the node a name (else ``name`` is the executable's);
    ``remaps`` are its remap rules (``from``, ``to``) in the order rcl should try them;
    ``param_files`` are ROS 2 ``<param from="FILE"/>`` params files, each with the line of its tag;
    ``scope_params`` the ROS 2 ``<set_parameter>`` values in force; ``ros_args`` ROS 2's
    ``ros_args`` attribute (words for the node's ``--ros-args`` block). ``dialect`` is the
    file's (None: not known).
    """

    pkg: str
    executable: str
    name: str
    namespace: str
    args: str
    params: Mapping[str, Param]
    required: bool
    file: Path
    line: int
    named: bool = True
    remaps: tuple[tuple[str, str], ...] = ()
    param_files: tuple[tuple[Path, int], ...] = ()
    scope_params: tuple[tuple[str, str], ...] = ()
    ros_args: str = ""
    dialect: Dialect | None = None

    @property
    def full_name(self) -> str:
        """The node's namespaced name (``/ns/name``)."""
        return self.namespace.rstrip("/") + "/" + self.name


@dataclass(frozen=True)
class ProcessSpec:
    """A process to start: ``robotmodel`` followed by ``argv``, standing in for node ``name``."""

    name: str
    kind: str
    argv: tuple[str, ...]
    required: bool = False


@dataclass
class LaunchPlan:
    """What a launch file starts (in order), the nodes it skips, and notes on what was not applied."""

    processes: list[ProcessSpec] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
