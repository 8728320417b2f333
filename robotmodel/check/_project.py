"""A robot repository's check config, and which xacro files are macro-only fragments.

The config lives in ``robotmodel.toml`` or under ``[tool.robotmodel]`` in ``pyproject.toml``
(the first found walking up from the working directory; ``robotmodel.toml`` wins in one
folder)::

    package-path = ["."]                 # optional: folders searched for ROS packages

    [[entry]]                            # [[tool.robotmodel.entry]] in pyproject.toml
    file = "urdf/robot.urdf.xacro"       # relative to the config's folder
    args = { prefix = "left_", use_gripper = true }

An entry is a document that expands to a robot, with the xacro args to check it with; the
same file may appear in several entries (one check each). A macro-only xacro file (one
whose top level only defines macros, properties and args, includes files or adds
non-link elements) is not a robot on its own: it is checked through the entries that
include it.
"""

from __future__ import annotations

import os
import tomllib
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from robotmodel.errors import ConfigError

__all__ = ["CONFIG_NAMES", "Entry", "ProjectConfig", "find_config", "is_macro_only", "read_config"]

#: File names searched for, in this order, in each folder.
CONFIG_NAMES = ("robotmodel.toml", "pyproject.toml")

_DEFINITIONS = {"macro", "property", "arg", "include"}


@dataclass(frozen=True, slots=True)
class Entry:
    """One configured check: an absolute ``file`` and its xacro ``args`` (sorted name/value pairs)."""

    file: Path
    args: tuple[tuple[str, str], ...]


@dataclass(frozen=True, slots=True)
class ProjectConfig:
    """A read config: where it came from, its entries and package folders (absolute)."""

    path: Path
    entries: tuple[Entry, ...]
    package_paths: tuple[Path, ...]

    def entries_for(self, file: str | os.PathLike[str]) -> list[Entry]:
        """The entries that check ``file`` itself."""
        real = os.path.realpath(file)
        return [e for e in self.entries if os.path.realpath(e.file) == real]


def _arg_value(value: Any, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str | int | float):
        return str(value)
    raise ConfigError(f"{where}: xacro arg values must be strings, numbers or booleans, not {type(value).__name__}")


def _table(path: Path) -> dict[str, Any] | None:
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise ConfigError(f"{path}: cannot read: {exc.strerror}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise ConfigError(f"{path}: not valid TOML: {exc}") from None
    if path.name != "pyproject.toml":
        return data
    tool = data.get("tool", {})
    section = tool.get("robotmodel") if isinstance(tool, dict) else None
    if section is None:
        return None
    if not isinstance(section, dict):
        raise ConfigError(f"{path}: [tool.robotmodel] must be a table")
    return section


def read_config(path: str | os.PathLike[str]) -> ProjectConfig:
    """Read the config at ``path`` (``robotmodel.toml`` or a ``pyproject.toml``); raises ConfigError."""
    source = Path(path).resolve()
    table = _table(source) or {}
    key = "[tool.robotmodel] " if source.name == "pyproject.toml" else ""
    root = source.parent
    unknown = sorted(set(table) - {"entry", "package-path"})
    if unknown:
        raise ConfigError(f"{source}: {key}unknown key '{unknown[0]}' (expected 'entry', 'package-path')")
    raw_paths = table.get("package-path", [])
    if not isinstance(raw_paths, list) or not all(isinstance(p, str) for p in raw_paths):
        raise ConfigError(f"{source}: {key}package-path must be a list of folder names")
    raw_entries = table.get("entry", [])
    if not isinstance(raw_entries, list):
        raise ConfigError(f"{source}: {key}entry must be an array of tables ([[entry]])")
    entries: list[Entry] = []
    for i, raw in enumerate(raw_entries):
        where = f"{source}: {key}entry[{i}]"
        if not isinstance(raw, dict) or not isinstance(raw.get("file"), str):
            raise ConfigError(f"{where}: needs file = \"path/to/robot.urdf.xacro\"")
        extra = sorted(set(raw) - {"file", "args"})
        if extra:
            raise ConfigError(f"{where}: unknown key '{extra[0]}' (expected 'file', 'args')")
        args = raw.get("args", {})
        if not isinstance(args, dict):
            raise ConfigError(f"{where}: args must be a table of name = value")
        pairs = tuple(sorted((str(k), _arg_value(v, f"{where}.args.{k}")) for k, v in args.items()))
        entries.append(Entry(root / raw["file"], pairs))
    return ProjectConfig(source, tuple(entries), tuple(root / p for p in raw_paths))


def find_config(start: str | os.PathLike[str] | None = None) -> ProjectConfig | None:
    """The config governing ``start`` (default: the working directory), or None.

    Folders are searched upward, stopping after the first that holds ``.git`` (the
    repository root), so a config outside the repository never applies.
    """
    folder = Path(start or Path.cwd()).resolve()
    for candidate in (folder, *folder.parents):
        for name in CONFIG_NAMES:
            path = candidate / name
            if path.is_file() and (name != "pyproject.toml" or _table(path) is not None):
                return read_config(path)
        if (candidate / ".git").exists():
            return None
    return None


def is_macro_only(path: str | os.PathLike[str]) -> bool:
    """Whether the xacro file ``path`` is a fragment: definitions, and no top-level link or macro call.

    Top-level ``<link>`` elements, macro calls and conditionals make a document a robot;
    ``xacro:macro``, ``xacro:property``, ``xacro:arg``, ``xacro:include`` and other URDF
    elements (materials, gazebo tags) do not. ``.urdf`` files, pipes and files that do not parse
    are never fragments: they are checked (and their errors reported) as they are.
    """
    if os.fspath(path).endswith(".urdf") or not Path(path).is_file():
        return False  # a pipe (a shell's <(...)) is never a fragment, and reading it here would empty it
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError):
        return False
    if root.tag.rsplit("}", 1)[-1] != "robot":
        return False
    defines = False
    for child in root:
        if not isinstance(child.tag, str):
            continue  # comments and processing instructions
        namespace, _, local = child.tag.rpartition("}")
        if "xacro" in namespace:
            if local not in _DEFINITIONS:
                return False
            defines = True
        elif local == "link":
            return False
    # An empty <robot/> defines nothing: it is checked (and fails) as it is.
    return defines
