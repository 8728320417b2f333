"""xacro expansion without ROS: wraps the ``xacro`` package, resolves ROS packages itself.

- :func:`expand` / :func:`expand_string`: xacro file or text to URDF text, bounded in
  time and memory, optionally refusing environment access and outside reads.
- :func:`dependencies`: the files a xacro document includes (xacro's ``--deps``).
- :func:`find_package` / :func:`resolve_uri`: ``$(find pkg)`` and ``package://`` lookups.
"""

from __future__ import annotations

from robotmodel.xacro._expand import DEFAULT_MEMORY_BYTES, DEFAULT_TIMEOUT_S, dependencies, expand, expand_string
from robotmodel.xacro._packages import find_package, resolve_uri

__all__ = [
    "DEFAULT_MEMORY_BYTES",
    "DEFAULT_TIMEOUT_S",
    "dependencies",
    "expand",
    "expand_string",
    "find_package",
    "resolve_uri",
]
