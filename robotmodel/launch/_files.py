"""Reading an XML launch file with its includes of every kind: the public :func:`load_launch_file`."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from robotmodel.launch._loader import LaunchFile, read_launch_xml

__all__ = ["load_launch_file"]


def load_launch_file(path: Path, args: Mapping[str, str], package_paths: Sequence[Path] = ()) -> LaunchFile:
    """Read XML launch file ``path`` with command-line ``args`` (a ROS 2 file's Python includes run).

    Raises :class:`robotmodel.errors.LaunchError` (``FILE:LINE: ...``) on bad input.
    """
    from robotmodel.launch._pysources import include_python

    return read_launch_xml(path, args, package_paths, python_include=include_python)
