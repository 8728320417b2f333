"""Checking robot descriptions: urdfdom's check_urdf and urdf_to_graphviz output, plus lint.

- :func:`tree_report`: the exact stdout of ``check_urdf`` for a valid robot.
- :func:`to_graphviz`: the exact ``.gv`` text of ``urdf_to_graphviz``.
- :func:`lint`: physical and referential findings (inertia, limits, meshes, materials),
  each a :class:`Finding` with a stable ``code``.
"""

from __future__ import annotations

from robotmodel.check._lint import Finding, Severity, lint
from robotmodel.check._report import to_graphviz, tree_report, urdfdom_rpy

__all__ = ["Finding", "Severity", "lint", "to_graphviz", "tree_report", "urdfdom_rpy"]
