"""The robot models bundled with robotmodel, installed as ``robotmodel.robots``.

Use :func:`robotmodel.robots.path` to get a bundled file's path.
"""

from __future__ import annotations

from importlib.resources import as_file, files
from pathlib import Path

__all__ = ["names", "path"]


def path(filename: str) -> Path:
    """Return the filesystem path of a bundled model file (e.g. ``'diffbot.urdf.xacro'``)."""
    resource = files(__name__).joinpath(filename)
    if not resource.is_file():
        from robotmodel.errors import RobotModelError

        raise RobotModelError(f"no bundled robot file '{filename}'; bundled: {', '.join(names())}")
    with as_file(resource) as p:
        return Path(p)


def names() -> list[str]:
    """List the bundled top-level robot model files."""
    return sorted(
        r.name for r in files(__name__).iterdir() if r.name.endswith((".urdf.xacro", ".urdf"))
    )
