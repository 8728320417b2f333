"""The state a Python launch file runs in: launch configurations, the ROS scope, what it declared.

One :class:`LaunchContext` per run (``launch.LaunchContext`` to the user's file). Its
:class:`Frame` is what a scoped ``GroupAction`` saves and restores, as launch's
``PushLaunchConfigurations``/``PopLaunchConfigurations`` do: the configurations (copied),
the ROS namespace pushed by ``PushRosNamespace`` (launch_ros keeps it among the
configurations, so it scopes with them), and the ``SetRemap``/``SetParameter`` lists,
which launch_ros extends in place, so a group that inherits a non-empty list shares it.
"""

from __future__ import annotations

import inspect
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robotmodel.errors import LaunchError
from robotmodel.launch._model import Dialect, NodeDecl, XacroSource
from robotmodel.launch._syntax import SubstContext

__all__ = ["Frame", "LaunchContext", "current", "user_line", "user_site", "using"]

_HERE = Path(__file__).resolve().parent


@dataclass
class Frame:
    """The scoped part of the context (see the module documentation)."""

    configs: dict[str, str] = field(default_factory=dict)
    ns: str | None = None
    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, str]] = field(default_factory=list)

    def pushed(self) -> Frame:
        """The frame a scoped group starts with."""
        return Frame(dict(self.configs), self.ns, self.remaps if self.remaps else [],
                     self.params if self.params else [])


@dataclass
class Deferred:
    """Actions launch would run later (a timer, an event handler): run after the rest, in this order."""

    order: tuple[int, float, int]
    entities: list[Any]
    frame: Frame
    file: Path


class LaunchContext:
    """What ``launch.LaunchContext`` offers description files, plus what the run collects."""

    def __init__(self, top: Path, package_paths: Sequence[Path] = ()) -> None:
        self.package_paths = list(package_paths)
        self.frame = Frame()
        self.stack: list[Frame] = []
        self.file = top
        self.environment: dict[str, str | None] = {}
        self.nodes: list[NodeDecl] = []
        self.skipped: list[str] = []
        self.notes: list[str] = []
        self.found: dict[Path, None] = {}
        self.xacro_outputs: dict[str, XacroSource] = {}
        self.deferred: list[Deferred] = []
        self.depth = 0

    # -- launch.LaunchContext's surface -------------------------------------------
    @property
    def launch_configurations(self) -> dict[str, str]:
        """The launch configurations in force (``name`` -> value)."""
        return self.frame.configs

    @property
    def locals(self) -> Any:
        """``context.locals.current_launch_file_path`` / ``_directory``."""
        from types import SimpleNamespace

        return SimpleNamespace(current_launch_file_path=str(self.file),
                               current_launch_file_directory=str(self.file.parent))

    def perform_substitution(self, substitution: Any) -> str:
        """``substitution.perform(self)``."""
        return str(substitution.perform(self))

    # -- scopes ------------------------------------------------------------------------
    def push(self) -> None:
        """Save the frame (a scoped group begins)."""
        self.stack.append(self.frame)
        self.frame = self.frame.pushed()

    def pop(self) -> None:
        """Restore the saved frame (the group ends)."""
        if not self.stack:
            raise LaunchError(f"{self.file}: PopLaunchConfigurations without a matching push")
        self.frame = self.stack.pop()

    def subst(self, line: int = 0) -> SubstContext:
        """A context for the XML launcher's substitution helpers (xacro commands, package lookup)."""
        return SubstContext(self.file, line or user_line(self.file), Dialect.ROS2, dict(self.frame.configs),
                            self.package_paths, self.found)

    def where(self, line: int = 0) -> str:
        """``FILE:LINE`` of the user's code now running (or ``line``)."""
        return f"{self.file}:{line or user_line(self.file)}"


_CURRENT: ContextVar[LaunchContext | None] = ContextVar("robotmodel_launch_context", default=None)


def current() -> LaunchContext | None:
    """The context of the launch run in progress (None outside one)."""
    return _CURRENT.get()


@contextmanager
def using(context: LaunchContext) -> Iterator[LaunchContext]:
    """Make ``context`` the run in progress for the ``with`` block."""
    token = _CURRENT.set(context)
    try:
        yield context
    finally:
        _CURRENT.reset(token)


def user_line(file: Path | None = None) -> int:
    """The line of the innermost caller outside robotmodel.launch (in ``file`` if given), else 0."""
    return user_site(file)[1]


def user_site(file: Path | None = None) -> tuple[Path | None, int]:
    """(file, line) of the innermost caller outside robotmodel.launch (in ``file`` if given)."""
    frame = inspect.currentframe()
    try:
        while frame is not None:
            path = Path(frame.f_code.co_filename)
            if path.parent != _HERE and not frame.f_code.co_filename.startswith("<") and (
                    file is None or path == file):
                return path, frame.f_lineno
            frame = frame.f_back
        return None, 0
    finally:
        del frame
