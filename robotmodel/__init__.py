"""robotmodel: ROS's robot-model and transform toolchain without ROS.

Subpackages, one concern each:

- :mod:`robotmodel.xacro`: xacro expansion with ROS-free package resolution.
- :mod:`robotmodel.model`: the typed robot description (URDF in, URDF out).
- :mod:`robotmodel.check`: check_urdf, lint and urdf_to_graphviz.
- :mod:`robotmodel.kinematics`: forward kinematics on Pinocchio.
- :mod:`robotmodel.spatial`: rotations and rigid transforms.
- :mod:`robotmodel.tf`: a tf2-style transform buffer.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"
__all__ = ["RobotDescription", "__version__", "load"]

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription, load


def __getattr__(name: str) -> Any:
    # Lazy, so `python -m robotmodel.xacro._worker` starts without importing the model stack.
    if name in ("load", "RobotDescription"):
        from robotmodel import model

        return getattr(model, name)
    raise AttributeError(f"module 'robotmodel' has no attribute '{name}'")
