"""xacro expansion without ROS: wraps the ``xacro`` package, resolves ROS packages itself.

- :func:`expand` / :func:`expand_string`: xacro file or text to URDF text, bounded in
  time and memory, optionally refusing environment access and outside reads.
- :func:`dependencies`: the files a xacro document includes (xacro's ``--deps``).
- :func:`run_xacro`: the ``xacro`` command (``-o``, ``--deps``, stdin).
- :func:`take_mappings` / :func:`split_mappings`: ``name:=value`` words, as the xacro command reads them.
- :func:`find_package` / :func:`resolve_uri`: re-exported from :mod:`robotmodel.resources`.
"""

from __future__ import annotations

# Package lookup lives in robotmodel.resources; these names stay for existing callers.
from robotmodel.resources import find_package, resolve_uri
from robotmodel.xacro._command import run_xacro
from robotmodel.xacro._expand import DEFAULT_MEMORY_BYTES, DEFAULT_TIMEOUT_S, dependencies, expand, expand_string
from robotmodel.xacro._mappings import split_mappings, take_mappings

__all__ = [
    "DEFAULT_MEMORY_BYTES",
    "DEFAULT_TIMEOUT_S",
    "dependencies",
    "expand",
    "expand_string",
    "find_package",
    "resolve_uri",
    "run_xacro",
    "split_mappings",
    "take_mappings",
]
