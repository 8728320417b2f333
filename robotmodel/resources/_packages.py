"""Find ROS packages without ROS.

Search order (closest first), as a ROS user expects from ``$(find pkg)``:

1. explicit package paths (``--package-path``), each a package or a folder of packages;
2. beside the input, never beyond its *bound*:

   a. the packages the input lies in (ancestors holding a ``package.xml`` of that name);
   b. the ament resource index of any ancestor (the install prefix the input lies in; a
      lookup, no crawl), as ROS resolves installed packages;
   c. each folder from the input's up to the bound, nearest first, crawled a few levels
      down for a ``package.xml`` whose ``<name>`` matches (so a repository's own copy of
      a package wins over a same-named one elsewhere).

   The bound is the input's workspace (the nearest ancestor holding ``.catkin_workspace``,
   ``.catkin_tools``, ``install/.colcon_install_layout``, ``install/setup.sh``,
   ``devel/setup.sh`` or ``build/COLCON_IGNORE``), else its repository (the nearest
   ancestor holding ``.git``), else the folder holding its package chain (the parent of
   the outermost ancestor holding a ``package.xml``). Ancestors are only looked at below
   ``/``, ``$HOME``, the system temporary folder and any ``site-packages`` or
   ``dist-packages`` folder, so none of those is ever a bound (a package directly in one
   of them bounds itself). A file with no workspace, repository or package around it
   gets no crawl at all;
3. ``ROS_PACKAGE_PATH`` (ROS 1), crawled;
4. ``AMENT_PREFIX_PATH`` (ROS 2 ament resource index);
5. colcon ``install/`` trees of the folders within the bound and of the working directory.

Each package found is logged once (logger ``robotmodel.resources``, level INFO) with the
copy used and why, and recorded for :func:`resolved_packages`.
"""

from __future__ import annotations

import logging
import os
import re
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence
from functools import lru_cache
from pathlib import Path
from typing import NamedTuple

from robotmodel.errors import PackageNotFoundError

__all__ = ["PathLike", "ResolvedPackage", "find_package", "record_package", "resolved_packages"]

PathLike = str | os.PathLike[str]

_log = logging.getLogger("robotmodel.resources")

_ANCESTOR_DEPTH = 4
_CRAWL_DIR_BUDGET = 20000
_IGNORE_MARKERS = ("CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE")
_WORKSPACE_MARKERS = (
    ".catkin_workspace", ".catkin_tools", "install/.colcon_install_layout", "install/setup.sh",
    "devel/setup.sh", "build/COLCON_IGNORE",
)
# Folders of installed Python packages: shared by unrelated projects, so never searched beside an input.
_ENVIRONMENTS = ("site-packages", "dist-packages")
_NAME_RE = re.compile(r"<name>\s*([^<\s]+)\s*</name>")


class ResolvedPackage(NamedTuple):
    """A package as found: its folder and how the search reached it."""

    folder: Path
    how: str


_resolved: dict[str, ResolvedPackage] = {}


def resolved_packages() -> dict[str, ResolvedPackage]:
    """Every package found so far in this process (by name), with the copy used and why."""
    return dict(_resolved)


def record_package(name: str, folder: Path, how: str) -> None:
    """Note that ``name`` resolved to ``folder``; logged at INFO the first time."""
    found = ResolvedPackage(folder, how)
    if _resolved.get(name) != found:
        _resolved[name] = found
        _log.info("package '%s': %s (%s)", name, folder, how)


def _package_name(package_xml: Path) -> str | None:
    try:
        text = package_xml.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return None
    match = _NAME_RE.search(text)
    if match:
        return match.group(1)
    try:
        name = ET.fromstring(text).findtext("name")
    except ET.ParseError:
        return None
    return name.strip() if name else None


@lru_cache(maxsize=256)
def _crawl(root: str, max_depth: int) -> tuple[tuple[str, str], ...]:
    """All (name, folder) packages under ``root``, breadth first, not descending into packages."""
    found: list[tuple[str, str]] = []
    queue: list[tuple[Path, int]] = [(Path(root), 0)]
    visited = 0
    while queue and visited < _CRAWL_DIR_BUDGET:
        folder, depth = queue.pop(0)
        visited += 1
        try:
            entries = sorted(os.scandir(folder), key=lambda e: e.name)
        except OSError:
            continue
        names = {e.name for e in entries}
        if any(m in names for m in _IGNORE_MARKERS):
            continue
        if "package.xml" in names:
            name = _package_name(folder / "package.xml")
            if name:
                found.append((name, str(folder)))
            continue
        if depth >= max_depth:
            continue
        queue.extend(
            (Path(e.path), depth + 1)
            for e in entries
            if _is_dir(e) and not e.name.startswith(".") and e.name != "__pycache__"
        )
    return tuple(found)


def _is_dir(entry: os.DirEntry[str]) -> bool:
    try:
        return entry.is_dir(follow_symlinks=True)
    except OSError:
        return False


def _in_crawl(name: str, root: Path, max_depth: int) -> Path | None:
    for pkg, folder in _crawl(str(root), max_depth):
        if pkg == name:
            return Path(folder)
    return None


def _never_a_bound() -> set[Path]:
    """Folders shared by unrelated projects: crawling them would find strangers' packages."""
    shared = {Path("/"), Path(tempfile.gettempdir()).resolve()}
    home = os.environ.get("HOME")
    if home:
        shared.add(Path(home).resolve())
    return shared


class _Bound(NamedTuple):
    folder: Path
    kind: str  # "workspace", "repository" or "package folder"


def _upward(folder: Path) -> Iterator[Path]:
    """``folder`` and its ancestors, stopping before ``/``, ``$HOME``, the temp folder and site-packages."""
    shared = _never_a_bound()
    for anc in [folder, *folder.parents]:
        if anc in shared or anc == Path(anc.anchor) or anc.name in _ENVIRONMENTS:
            return
        yield anc


def _bound(folder: Path) -> _Bound | None:
    """The outermost folder the search beside an input in ``folder`` may reach (see the module doc)."""
    return _cached_bound(folder, frozenset(_never_a_bound()))


@lru_cache(maxsize=256)
def _cached_bound(folder: Path, shared: frozenset[Path]) -> _Bound | None:
    del shared  # part of the cache key only: $HOME may change between calls
    chain = list(_upward(folder))
    for anc in chain:
        if any((anc / marker).exists() for marker in _WORKSPACE_MARKERS):
            return _Bound(anc, "workspace")
    for anc in chain:
        if (anc / ".git").exists():
            return _Bound(anc, "repository")
    packages = [anc for anc in chain if (anc / "package.xml").is_file()]
    if not packages:
        return None
    outermost = packages[-1]
    holder = outermost.parent
    return _Bound(holder if holder in chain else outermost, "package folder")


def _within(folder: Path, bound: Path) -> Iterator[Path]:
    for anc in [folder, *folder.parents]:
        yield anc
        if anc == bound:
            return


def _from_ament(name: str, prefixes: Sequence[str]) -> Path | None:
    for prefix in prefixes:
        if (Path(prefix) / "share" / "ament_index" / "resource_index" / "packages" / name).is_file():
            return Path(prefix) / "share" / name
    return None


def _from_colcon(name: str, bases: Sequence[Path]) -> tuple[Path, Path] | None:
    for base in bases:
        install = base / "install"
        if not install.is_dir():
            continue
        for candidate in (install / name / "share" / name, install / "share" / name):
            if (candidate / "package.xml").is_file():
                return candidate, install
    return None


def _found(name: str, folder: Path, how: str) -> Path:
    record_package(name, folder, how)
    return folder


def _beside(name: str, folder: Path) -> tuple[tuple[Path, str] | None, list[Path], str]:
    """Search the input's own tree (step 2): (hit and why, the folders within the bound, where looked)."""
    bound = _bound(folder)
    own = list(_within(folder, bound.folder)) if bound is not None else []
    where = (f"the input's {bound.kind} {bound.folder}" if bound is not None
             else f"nothing beside the input (no workspace, repository or package around {folder})")
    # The packages the input is in first: no crawl needed for the commonest case.
    for anc in own:
        if (anc / "package.xml").is_file() and _package_name(anc / "package.xml") == name:
            return (anc, where), own, where
    # The install prefix the input lies in, as ROS resolves it: an index lookup, even above the bound.
    for anc in _upward(folder):
        found = _from_ament(name, [str(anc)])
        if found:
            return (found, f"the ament index of the input's install prefix {anc}"), own, where
    for anc in own:
        found = _in_crawl(name, anc, _ANCESTOR_DEPTH)
        if found:
            return (found, where), own, where
    return None, own, where


def find_package(
    name: str, *, start: PathLike | None = None, package_paths: Sequence[PathLike] = ()
) -> Path:
    """Return the folder of ROS package ``name`` (its share directory), searching like ROS.

    ``start`` is the input file (or its folder) whose own tree is searched, within its
    bound, after the explicit ``package_paths`` (see the module documentation for the
    order). Raises :class:`PackageNotFoundError` naming where it looked.
    """
    searched: list[str] = []
    for raw in package_paths:
        root = Path(raw).resolve()
        found = _in_crawl(name, root, 8)
        if found:
            return _found(name, found, f"--package-path {root}")
        searched.append(f"--package-path {root}")
    own: list[Path] = []
    if start is not None:
        start_path = Path(start).resolve()
        folder = start_path if start_path.is_dir() else start_path.parent
        hit, own, where = _beside(name, folder)
        if hit is not None:
            return _found(name, *hit)
        searched.append(where)
    ros_path = [p for p in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    for root_str in ros_path:
        found = _in_crawl(name, Path(root_str), 8)
        if found:
            return _found(name, found, f"ROS_PACKAGE_PATH entry {root_str}")
    searched.append(f"ROS_PACKAGE_PATH ({':'.join(ros_path) or 'unset'})")
    ament = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    found = _from_ament(name, ament)
    if found:
        return _found(name, found, f"AMENT_PREFIX_PATH prefix {found.parent.parent}")
    searched.append(f"AMENT_PREFIX_PATH ({':'.join(ament) or 'unset'})")
    colcon = _from_colcon(name, [*own, Path.cwd()])
    if colcon:
        return _found(name, colcon[0], f"colcon install tree {colcon[1]}")
    searched.append("colcon install/ trees")
    raise PackageNotFoundError(name, searched)
