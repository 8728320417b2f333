"""Where a mesh URI (``package://``, ``file://`` or a path) points on disk."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from robotmodel.errors import RobotModelError
from robotmodel.resources import resolve_uri

__all__ = ["resolve_mesh_uri"]


def resolve_mesh_uri(uri: str, base: Path, package_paths: Sequence[str]) -> Path:
    """The file ``uri`` names; relative paths are taken from ``base`` (the URDF's folder).

    Raises :class:`RobotModelError` (naming the URI) when a package cannot be found.
    """
    if uri.startswith("package:///"):
        # A common typo (an empty authority) that rviz's resource retriever accepts.
        uri = "package://" + uri[len("package:///"):]
    try:
        return resolve_uri(uri, base_dir=base, package_paths=package_paths)
    except RobotModelError:
        raise
    except (OSError, ValueError) as exc:
        raise RobotModelError(f"cannot resolve '{uri}': {exc}") from None
