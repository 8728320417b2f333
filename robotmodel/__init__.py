"""robotmodel: ROS's robot-model and transform toolchain without ROS.

:func:`load` is the entry point from a ``.urdf``/``.xacro`` file or XML text to a
:class:`RobotDescription`: it expands xacro documents (and only those: a plain URDF is
parsed directly, see :mod:`robotmodel.model._load` for the rule) and parses the URDF.

Subpackages, one concern each:

- :mod:`robotmodel.resources`: ROS package lookup and ``package://``/``file://`` URIs.
- :mod:`robotmodel.xacro`: xacro expansion (in a bounded child process).
- :mod:`robotmodel.model`: the typed robot description (URDF in, URDF out).
- :mod:`robotmodel.check`: check_urdf, lint and urdf_to_graphviz.
- :mod:`robotmodel.kinematics`: forward kinematics on Pinocchio.
- :mod:`robotmodel.spatial`: rotations and rigid transforms.
- :mod:`robotmodel.tf`: a tf2-style transform buffer.
- :mod:`robotmodel.time`: rclpy-style time as integer nanoseconds, and clocks.
- :mod:`robotmodel.msgs`: ROS 2 message classes and their CDR encoding.
- :mod:`robotmodel.bus`: a ROS 2 bus in rmw_zenoh's wire format, with rclpy's shape.
- :mod:`robotmodel.tf_ros`: tf2_ros's broadcasters and listener on the bus.
- :mod:`robotmodel.publishers`: robot_state_publisher and joint_state_publisher.
- :mod:`robotmodel.viewer`: meshcat's browser viewer.
- :mod:`robotmodel.signals`: stopping a long-running tool cleanly on SIGINT/SIGTERM.
- :mod:`robotmodel.rcl`: rcl's ``--ros-args`` (remaps, parameters, namespace) and console lines.
- :mod:`robotmodel.process`: the one supervisor of child processes (``launch``, ``demo``).
- :mod:`robotmodel.topic`: ``ros2 topic list`` / ``echo`` on the bus.
- :mod:`robotmodel.demo`: the whole pipeline on the bundled diffbot (``robotmodel demo``).

Each ``robotmodel`` command is its parser (``cli/``, installed as ``robotmodel.cli``) and one
call into these packages (``run_*`` functions), which never import the command line.
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
