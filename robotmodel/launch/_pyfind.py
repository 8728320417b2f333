"""launch_ros's package finders and ament_index_python's lookup error.

Packages are found as the XML launcher finds them (``--package-path`` first, then the
launch file's own tree, ``ROS_PACKAGE_PATH``, ``AMENT_PREFIX_PATH``, colcon install trees),
so a source tree and an install prefix both resolve.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from robotmodel.errors import RobotModelError
from robotmodel.launch._pyctx import LaunchContext
from robotmodel.launch._pysubst import Substitution, _describe, normalize, perform_all

__all__ = ["FindPackage", "FindPackagePrefix", "FindPackageShare", "PackageNotFoundError", "find_share"]


class FindPackageShare(Substitution):
    """launch_ros's: the share folder of a package (source or install layout; ``--package-path`` first)."""

    def __init__(self, package: Any) -> None:
        self.package = normalize(package)

    def perform(self, context: LaunchContext) -> str:
        """The package's folder."""
        return find_share(context, perform_all(context, self.package))

    def describe(self) -> str:
        """``FindPackageShare(pkg='name')``."""
        return f"{type(self).__name__}(pkg={_describe(self.package)})"


class FindPackagePrefix(FindPackageShare):
    """launch_ros's: the install prefix of a package (its folder in a source tree)."""

    def perform(self, context: LaunchContext) -> str:
        """The package's prefix."""
        share = Path(find_share(context, perform_all(context, self.package)))
        return str(share.parent.parent) if share.parent.name == "share" else str(share)


def find_share(context: LaunchContext, package: str) -> str:
    """The folder of ``package`` as the XML launcher finds it; not found raises launch_ros's error."""
    from robotmodel.resources import find_package

    try:
        root = find_package(package, start=context.file, package_paths=context.package_paths)
    except RobotModelError as exc:
        raise PackageNotFoundError(f"\"package '{package}' not found, searching: {_searched(exc)}\"") from None
    context.found[root] = None
    return str(root)


def _searched(exc: RobotModelError) -> str:
    text = " ".join(str(exc).splitlines())
    return text.split("searched ", 1)[-1] if "searched " in text else text


class PackageNotFoundError(KeyError):
    """ament_index_python's: no package of that name (a KeyError, as there)."""

    def __str__(self) -> str:
        return str(self.args[0]).strip('"') if self.args else ""


class FindPackage(FindPackagePrefix):
    """launch_ros's older name: the package's prefix."""
