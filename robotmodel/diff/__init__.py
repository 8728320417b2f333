"""Semantic diff of two robot descriptions: what a change to a URDF/xacro changes.

- :func:`diff_descriptions`: links, joints and materials added, removed, renamed (found
  from the tree: same parent, child and type under a new name) and changed (type, ends,
  origin in mm and degrees, axis, limits, mimic, dynamics, inertial, visual and collision
  geometry, mesh paths, materials), and how every link on both sides moved at the zero
  configuration (FK before and after; largest first).
- :func:`render_text` (for a code review) and :func:`render_json` / :func:`diff_json`
  (for scripts).
- :func:`run_diff`: the ``diff`` command (exit 0 equal, 1 different, 2 error).
- :func:`load_revision`: a file as it was at a git revision (xacro includes resolved in
  that revision's files).

Numbers are equal within :data:`DEFAULT_TOLERANCE` (1e-9, relative above 1).
"""

from __future__ import annotations

from robotmodel.diff._command import run_diff
from robotmodel.diff._diff import diff_descriptions
from robotmodel.diff._git import load_revision
from robotmodel.diff._json import diff_json, render_json
from robotmodel.diff._poses import zero_poses
from robotmodel.diff._text import render_text
from robotmodel.diff._types import (
    DEFAULT_TOLERANCE,
    DescriptionDiff,
    ElementChange,
    FieldChange,
    Json,
    PoseChange,
    SectionDiff,
    Side,
)

__all__ = [
    "DEFAULT_TOLERANCE",
    "DescriptionDiff",
    "ElementChange",
    "FieldChange",
    "Json",
    "PoseChange",
    "SectionDiff",
    "Side",
    "diff_descriptions",
    "diff_json",
    "load_revision",
    "render_json",
    "render_text",
    "run_diff",
    "zero_poses",
]
