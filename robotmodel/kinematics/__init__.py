"""Forward kinematics on Pinocchio, with robot_state_publisher's semantics.

- :class:`KinematicModel`: immutable; joint names ↔ Pinocchio's ``q`` (through
  ``idx_q``/``nq``), mimic chains resolved by us, limits and JSP-style defaults.
- :class:`KinematicState`: mutable; link poses T_root_link and Jacobians for one configuration.
- :func:`joint_transforms` / :func:`static_transforms`: per-joint T_parent_child as RSP publishes.
- :func:`batch_link_matrices`: N configurations at once, vectorized.
"""

from __future__ import annotations

from robotmodel.kinematics._model import JointValues, KinematicModel, MimicRule
from robotmodel.kinematics._publish import (
    JointTransforms,
    batch_link_matrices,
    batch_link_poses,
    joint_transforms,
    static_transforms,
)
from robotmodel.kinematics._state import KinematicState

__all__ = [
    "JointTransforms",
    "JointValues",
    "KinematicModel",
    "KinematicState",
    "MimicRule",
    "batch_link_matrices",
    "batch_link_poses",
    "joint_transforms",
    "static_transforms",
]
