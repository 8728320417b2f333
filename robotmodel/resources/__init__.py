"""ROS packages and the files robots name, found without ROS.

- :func:`find_package`: the folder of a ROS package (``$(find pkg)``), searched as the
  module :mod:`robotmodel.resources._packages` documents.
- :func:`resolve_uri`: ``package://pkg/rel``, ``file:///abs`` or a plain path to a path.
- :func:`resolved_packages` / :func:`record_package`: which copy of each package was
  used (logged at INFO by the ``robotmodel.resources`` logger).

Used by xacro expansion, lint's mesh checks and the viewer. Failures raise
:class:`robotmodel.errors.ResourceError` (:class:`~robotmodel.errors.PackageNotFoundError`
for an unknown package).
"""

from __future__ import annotations

from robotmodel.resources._packages import (
    PathLike,
    ResolvedPackage,
    find_package,
    record_package,
    resolved_packages,
)
from robotmodel.resources._uri import resolve_uri

__all__ = ["PathLike", "ResolvedPackage", "find_package", "record_package", "resolve_uri", "resolved_packages"]
