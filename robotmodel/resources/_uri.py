"""Turn the URIs URDF and xacro files use (``package://``, ``file://``, plain paths) into paths."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from robotmodel.errors import ResourceError
from robotmodel.resources._packages import PathLike, find_package

__all__ = ["resolve_uri"]


def resolve_uri(
    uri: str, *, base_dir: PathLike | None = None, package_paths: Sequence[PathLike] = ()
) -> Path:
    """Turn ``package://pkg/rel``, ``file:///abs`` or a plain path into a filesystem path.

    Plain relative paths are taken relative to ``base_dir`` (default: the working
    directory). The result may not exist; an unknown package raises
    :class:`PackageNotFoundError`.
    """
    base = Path(base_dir) if base_dir is not None else Path.cwd()
    if uri.startswith("package://"):
        rest = uri[len("package://") :]
        pkg, _, rel = rest.partition("/")
        if not pkg:
            raise ResourceError(f"malformed package URI '{uri}': no package name")
        return find_package(pkg, start=base, package_paths=package_paths) / rel
    if uri.startswith("file://"):
        return Path(uri[len("file://") :])
    if "://" in uri:
        raise ResourceError(f"unsupported URI scheme in '{uri}' (expected package://, file:// or a path)")
    path = Path(uri)
    return path if path.is_absolute() else base / path
