"""Checking robot descriptions: urdfdom's check_urdf and urdf_to_graphviz output, plus lint.

- :func:`tree_report`: the exact stdout of ``check_urdf`` for a valid robot.
- :func:`graphviz`: the exact ``.gv`` text of ``urdf_to_graphviz``.
- :func:`lint`: physical and referential findings (inertia, limits, meshes, materials).
"""

from __future__ import annotations

from robotmodel.check._lint import Finding, Severity, lint
from robotmodel.check._report import graphviz, tree_report, urdfdom_rpy

__all__ = ["Finding", "Severity", "graphviz", "lint", "tree_report", "urdfdom_rpy"]
