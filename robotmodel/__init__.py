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

import sys
from importlib.abc import MetaPathFinder
from importlib.machinery import ModuleSpec
from importlib.util import spec_from_file_location
from pathlib import Path
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


class _CheckoutFinder(MetaPathFinder):
    """Finds ``robotmodel.cli``, ``.robots`` and ``.examples`` beside this folder in a source checkout.

    pyproject.toml maps ``cli/``, ``urdf/`` and ``examples/`` into the package when it is
    installed. Python started in a checkout's root imports this folder instead of the installed
    copy (the current directory comes first on ``sys.path``), where those three are not inside
    it; this finder maps them the same way, so ``import robotmodel.robots`` works there too.
    It comes after Python's own finders, so an installed or editable copy always wins.
    """

    def __init__(self, mapped: dict[str, Path]) -> None:
        self.mapped = mapped

    def find_spec(self, fullname: str, path: Any = None, target: Any = None) -> ModuleSpec | None:
        """The spec of a mapped subpackage; None for any other name."""
        folder = self.mapped.get(fullname)
        if folder is None:
            return None
        return spec_from_file_location(fullname, folder / "__init__.py", submodule_search_locations=[str(folder)])


def _map_checkout() -> None:
    root = Path(__file__).resolve().parent.parent
    if not ((root / "pyproject.toml").is_file() and (root / "urdf" / "__init__.py").is_file()):
        return  # installed: the subpackages are inside this folder
    layout = (("cli", "cli"), ("robots", "urdf"), ("examples", "examples"))
    mapped = {f"robotmodel.{name}": root / folder for name, folder in layout
              if (root / folder / "__init__.py").is_file()}
    sys.meta_path.append(_CheckoutFinder(mapped))


_map_checkout()
