"""Forward kinematics with robot_state_publisher's semantics; Jacobians on Pinocchio.

- :class:`KinematicModel`: immutable, built from the typed description; joint names ↔
  Pinocchio's ``q`` (through ``idx_q``/``nq``), mimic chains resolved by us, limits and
  JSP-style defaults.
- :class:`KinematicState`: mutable; link poses T_root_link (our own O(joints) FK, any
  size) and Jacobians (Pinocchio, while its Data stays under :data:`PINOCCHIO_DATA_LIMIT`).
- :func:`joint_transforms` / :func:`static_transforms`: per-joint T_parent_child as RSP publishes
  (:func:`variable_transforms`: the same from a vector of every variable, RSP's hot path).
- :func:`batch_link_matrices`: N configurations at once, vectorized.
- :func:`to_yourdfpy` / :func:`trimesh_scene`: the robot posed at a configuration as a
  ``yourdfpy.URDF`` or a ``trimesh.Scene``, for code written for those libraries.
- :func:`run_fk`: the ``fk`` command's report (every link's pose, text or JSON).
- :func:`parse_joint_words`: ``NAME=VALUE`` words (``--joint``) to a dict, with one-line errors.
"""

from __future__ import annotations

from robotmodel.kinematics._model import JointValues, KinematicModel, MimicRule
from robotmodel.kinematics._pin import PINOCCHIO_DATA_LIMIT
from robotmodel.kinematics._publish import (
    JointTransforms,
    batch_link_matrices,
    batch_link_poses,
    joint_transforms,
    static_transforms,
    variable_transforms,
)
from robotmodel.kinematics._report import run_fk
from robotmodel.kinematics._state import KinematicState
from robotmodel.kinematics._words import parse_joint_words
from robotmodel.kinematics._yourdfpy import to_yourdfpy, trimesh_scene

__all__ = [
    "PINOCCHIO_DATA_LIMIT",
    "JointTransforms",
    "JointValues",
    "KinematicModel",
    "KinematicState",
    "MimicRule",
    "batch_link_matrices",
    "batch_link_poses",
    "joint_transforms",
    "parse_joint_words",
    "run_fk",
    "static_transforms",
    "to_yourdfpy",
    "trimesh_scene",
    "variable_transforms",
]
