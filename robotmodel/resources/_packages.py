"""Find ROS packages and resolve ``package://`` URIs without ROS.

Search order (closest first), as a ROS user expects from ``$(find pkg)``:

1. explicit package paths (``--package-path``), each a package or a folder of packages;
2. the input file's own tree: each ancestor folder, nearest first, crawled a few levels
   down for a ``package.xml`` whose ``<name>`` matches (so a repository's own copy of a
   package wins over a same-named one elsewhere), or holding an ament resource index
   that names it (an install prefix);
3. ``ROS_PACKAGE_PATH`` (ROS 1), crawled;
4. ``AMENT_PREFIX_PATH`` (ROS 2 ament resource index);
5. colcon ``install/`` trees beside the input's ancestors and the working directory.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence
from functools import lru_cache
from pathlib import Path

from robotmodel.errors import PackageNotFoundError

__all__ = ["PathLike", "find_package"]

PathLike = str | os.PathLike[str]

# Crawling ancestors is bounded: an input near "/" must not walk the whole disk.
_ANCESTOR_LEVELS = 6
_ANCESTOR_DEPTH = 3
_CRAWL_DIR_BUDGET = 20000
_IGNORE_MARKERS = ("CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE")
_NAME_RE = re.compile(r"<name>\s*([^<\s]+)\s*</name>")


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
            if e.is_dir(follow_symlinks=True) and not e.name.startswith(".") and e.name != "__pycache__"
        )
    return tuple(found)


def _in_crawl(name: str, root: Path, max_depth: int) -> Path | None:
    for pkg, folder in _crawl(str(root), max_depth):
        if pkg == name:
            return Path(folder)
    return None


def _ancestors(start: Path) -> Iterator[Path]:
    folder = start if start.is_dir() else start.parent
    home = Path.home()
    for level, anc in enumerate([folder, *folder.parents]):
        if level >= _ANCESTOR_LEVELS or anc == Path(anc.anchor) or anc == home:
            return
        yield anc


def _from_ament(name: str, prefixes: Sequence[str]) -> Path | None:
    for prefix in prefixes:
        if (Path(prefix) / "share" / "ament_index" / "resource_index" / "packages" / name).is_file():
            return Path(prefix) / "share" / name
    return None


def _from_colcon(name: str, bases: Sequence[Path]) -> Path | None:
    for base in bases:
        install = base / "install"
        if not install.is_dir():
            continue
        for candidate in (install / name / "share" / name, install / "share" / name):
            if (candidate / "package.xml").is_file():
                return candidate
    return None


def find_package(
    name: str, *, start: PathLike | None = None, package_paths: Sequence[PathLike] = ()
) -> Path:
    """Return the folder of ROS package ``name`` (its share directory), searching like ROS.

    ``start`` is the file (or folder) whose tree is searched after the explicit
    ``package_paths``. Raises :class:`PackageNotFoundError` naming where it looked.
    """
    searched: list[str] = []
    for raw in package_paths:
        root = Path(raw).resolve()
        found = _in_crawl(name, root, 8)
        if found:
            return found
        searched.append(f"--package-path {root}")
    start_path = Path(start).resolve() if start is not None else None
    if start_path is not None:
        for anc in _ancestors(start_path):
            # An installed package lives in <prefix>/share/<pkg>, indexed by its prefix.
            found = _in_crawl(name, anc, _ANCESTOR_DEPTH) or _from_ament(name, [str(anc)])
            if found:
                return found
        searched.append(f"the tree of {start_path}")
    ros_path = [p for p in os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep) if p]
    for root_str in ros_path:
        found = _in_crawl(name, Path(root_str), 8)
        if found:
            return found
    searched.append(f"ROS_PACKAGE_PATH ({':'.join(ros_path) or 'unset'})")
    ament = [p for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    found = _from_ament(name, ament)
    if found:
        return found
    searched.append(f"AMENT_PREFIX_PATH ({':'.join(ament) or 'unset'})")
    bases = [Path.cwd()]
    if start_path is not None:
        bases.extend(_ancestors(start_path))
    found = _from_colcon(name, bases)
    if found:
        return found
    searched.append("colcon install/ trees")
    raise PackageNotFoundError(name, searched)
