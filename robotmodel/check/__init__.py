"""Checking robot descriptions: urdfdom's check_urdf and urdf_to_graphviz output, plus lint.

- :func:`tree_report`: the exact stdout of ``check_urdf`` for a valid robot.
- :func:`to_graphviz`: the exact ``.gv`` text of ``urdf_to_graphviz`` (:func:`run_urdf_to_graphviz`
  writes it and the PDF, as the program does).
- :func:`lint`: physical and referential findings (inertia, limits, meshes, materials),
  each a :class:`Finding` with a stable ``code``; :data:`RULES` says what each code means.
- :func:`check_file`: one file end to end (load, lint, each finding placed at a
  :class:`Location` in the URDF or xacro sources) into a picklable :class:`FileReport`.
- :func:`workflow_command` / :func:`to_sarif`: findings as GitHub Actions annotations or
  a SARIF 2.1.0 log for code scanning.
- :func:`run_check`: the ``check-urdf`` program over a :class:`CheckOptions` (files and
  globs, config entries, fragments checked through their entries, parallel, four formats).
- :func:`find_config` / :func:`read_config`: a robot repository's entry points and their
  xacro args (``[tool.robotmodel]`` or ``robotmodel.toml``); :func:`is_macro_only` tells the
  xacro fragments that are checked through the entries including them.
"""

from __future__ import annotations

from robotmodel.check._command import FORMATS, CheckOptions, run_check
from robotmodel.check._github import escape_data, escape_property, workflow_command
from robotmodel.check._graphviz import run_urdf_to_graphviz
from robotmodel.check._lint import Finding, Severity, lint
from robotmodel.check._locations import Location, SourceIndex, display_path
from robotmodel.check._project import CONFIG_NAMES, Entry, ProjectConfig, find_config, is_macro_only, read_config
from robotmodel.check._report import to_graphviz, tree_report, urdfdom_rpy
from robotmodel.check._rules import RULES, Rule, error_code
from robotmodel.check._run import CheckJob, FileReport, LocatedFinding, TreeRow, check_file, job_args
from robotmodel.check._sarif import SARIF_SCHEMA, to_sarif

__all__ = [
    "CONFIG_NAMES",
    "FORMATS",
    "RULES",
    "SARIF_SCHEMA",
    "CheckJob",
    "CheckOptions",
    "Entry",
    "FileReport",
    "Finding",
    "LocatedFinding",
    "Location",
    "ProjectConfig",
    "Rule",
    "Severity",
    "SourceIndex",
    "TreeRow",
    "check_file",
    "display_path",
    "error_code",
    "escape_data",
    "escape_property",
    "find_config",
    "is_macro_only",
    "job_args",
    "lint",
    "read_config",
    "run_check",
    "run_urdf_to_graphviz",
    "to_graphviz",
    "to_sarif",
    "tree_report",
    "urdfdom_rpy",
    "workflow_command",
]
