"""``PKG FILE``: a launch file inside a ROS package, found as roslaunch and ros2 launch find it."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from robotmodel.errors import LaunchError

__all__ = ["find_launch_file"]

_MAX_DEPTH = 6


def find_launch_file(package: str, name: str, package_paths: Sequence[Path] = ()) -> Path:
    """The file ``name`` anywhere in package ``package`` (a path relative to it also works).

    Several matches are an error naming them all, as in roslaunch.
    """
    from robotmodel.resources import find_package

    root = find_package(package, package_paths=package_paths)
    direct = root / name
    if direct.is_file():
        return direct
    found: list[Path] = []
    stack: list[tuple[Path, int]] = [(root, 0)]
    while stack:
        folder, depth = stack.pop()
        try:
            entries = sorted(folder.iterdir())
        except OSError:
            continue
        for entry in entries:
            if entry.is_dir() and not entry.name.startswith(".") and depth < _MAX_DEPTH:
                stack.append((entry, depth + 1))
            elif entry.name == name and entry.is_file():
                found.append(entry)
    if not found:
        raise LaunchError(f"[{name}] is neither a launch file in package [{package}] nor is [{package}] "
                          "a launch file name")
    if len(found) > 1:
        raise LaunchError(f"multiple files named [{name}] in package [{package}]: "
                          + ", ".join(str(p) for p in sorted(found)))
    return found[0]
