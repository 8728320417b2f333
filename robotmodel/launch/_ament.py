"""ament_index_python's package lookup, as a Python launch file (and xacro's ``$(find)`` inside it) calls it.

Inside a launch run it finds packages as the launcher does (``--package-path`` first, then
the launch file's own tree, ``ROS_PACKAGE_PATH``, ``AMENT_PREFIX_PATH``, colcon install trees);
outside one, without the ``--package-path`` part.
"""

from __future__ import annotations

from pathlib import Path

from robotmodel.launch._pyctx import LaunchContext, current
from robotmodel.launch._pyfind import PackageNotFoundError, find_share

__all__ = ["PackageNotFoundError", "get_package_prefix", "get_package_share_directory", "get_package_share_path"]


def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
    """The share folder of ``package_name`` (a source package's own folder); raises PackageNotFoundError."""
    del print_warning
    context = current()
    if context is None:
        context = LaunchContext(Path.cwd() / "launch")
    return find_share(context, package_name)


def get_package_share_path(package_name: str, print_warning: bool = True) -> Path:
    """:func:`get_package_share_directory` as a Path."""
    return Path(get_package_share_directory(package_name, print_warning))


def get_package_prefix(package_name: str) -> str:
    """The install prefix of ``package_name`` (a source package's own folder)."""
    share = Path(get_package_share_directory(package_name))
    return str(share.parent.parent) if share.parent.name == "share" else str(share)
