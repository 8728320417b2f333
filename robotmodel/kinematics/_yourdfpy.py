"""Handing a robot to yourdfpy and trimesh: a ``yourdfpy.URDF`` posed at a configuration, and its scene."""

from __future__ import annotations

import io
import math
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotmodel.errors import ResourceError
from robotmodel.kinematics._model import JointValues, KinematicModel
from robotmodel.model import JointType, Mimic, RobotDescription, to_urdf

if TYPE_CHECKING:
    import os
    from collections.abc import Sequence

__all__ = ["to_yourdfpy", "trimesh_scene"]

_MOVING = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


def _handed(model: KinematicModel) -> RobotDescription:
    """The description as yourdfpy must read it to move as our FK does.

    Each moving joint's axis is of unit length (URDF's axis is a direction). Each mimic
    names its resolved independent master, with the composed multiplier and offset
    (yourdfpy follows one level only), and a mimic whose master does not exist is dropped:
    the joint moves freely, as :class:`KinematicModel` (and robot_state_publisher) has it.
    """
    joints = []
    for joint in model.description.joints:
        x, y, z = joint.axis
        norm = math.sqrt(x * x + y * y + z * z)
        axis = (x / norm, y / norm, z / norm) if joint.type in _MOVING and norm > 0.0 else joint.axis
        rule = model.mimics.get(joint.name)
        mimic = Mimic(rule.master, rule.multiplier, rule.offset) if rule is not None else None
        joints.append(replace(joint, axis=axis, mimic=mimic))
    return replace(model.description, joints=tuple(joints))


def to_yourdfpy(
    robot: RobotDescription | KinematicModel,
    positions: JointValues | None = None,
    *,
    load_meshes: bool = False,
    collision: bool = False,
    package_paths: Sequence[str | os.PathLike[str]] = (),
) -> Any:
    """A ``yourdfpy.URDF`` of ``robot`` posed at ``positions``, for code written for yourdfpy or trimesh.

    ``positions`` maps joint names to values (radians, metres) as
    :meth:`KinematicModel.vector` reads them: unknown names raise
    :class:`~robotmodel.errors.UnknownJointError`, NaN/inf :class:`JointValueError`,
    values are not clamped, and joints not named take their default (0, or the middle of
    their limits when 0 is outside). Mimic joints follow their master (yourdfpy computes
    them, from the resolved rules: a mimic of a mimic names the first master, a mimic of a
    joint the robot lacks moves freely); floating and planar joints stay at their origin. ``urdf.get_transform(link,
    root)`` then equals this library's ``KinematicState.link_matrix(link)``, which a
    test checks joint by joint over the bundled robots.

    The URDF is written from the typed description (:func:`robotmodel.model.to_urdf`), never
    from the text it was read from, with each moving joint's axis made unit length: URDF's
    axis is a direction (KDL, Pinocchio and robot_state_publisher normalize it), while
    yourdfpy moves a prismatic joint by ``value * axis`` as written.

    ``load_meshes`` loads the visual meshes into ``urdf.scene`` (a ``trimesh.Scene``),
    and ``collision`` the collision geometry into ``urdf.collision_scene``; their
    ``package://`` and relative file names resolve as everywhere in robotmodel
    (``package_paths`` first, then around the description's source file, ROS_PACKAGE_PATH,
    ...). Without them the scene graph holds the link frames only.
    """
    import yourdfpy

    model = robot if isinstance(robot, KinematicModel) else KinematicModel(robot)
    description = model.description
    q = model.vector(positions)  # validates names and values, fills the defaults
    base = Path(description.source).parent if description.source else Path.cwd()

    def resolve(fname: str) -> str:  # yourdfpy calls it by this keyword
        from robotmodel.resources import resolve_uri

        try:
            return str(resolve_uri(fname, base_dir=base, package_paths=package_paths))
        except ResourceError:
            return fname  # yourdfpy reports the file it could not load, and goes on

    text = to_urdf(_handed(model))
    urdf = yourdfpy.URDF.load(io.StringIO(text), build_scene_graph=True, load_meshes=load_meshes,
                              build_collision_scene_graph=collision, load_collision_meshes=collision,
                              filename_handler=resolve)
    urdf.update_cfg({name: float(value) for name, value in zip(model.variables, q.tolist(), strict=True)})
    return urdf


def trimesh_scene(
    robot: RobotDescription | KinematicModel,
    positions: JointValues | None = None,
    *,
    collision: bool = False,
    package_paths: Sequence[str | os.PathLike[str]] = (),
) -> Any:
    """The robot at ``positions`` as a ``trimesh.Scene``: its visual meshes (or ``collision`` geometry).

    Frames are named after the links, so ``scene.graph.get(link, root)`` is
    T_root_link; ``scene.show()`` or ``scene.export("robot.glb")`` hand it on. Built by
    :func:`to_yourdfpy` (same ``positions`` rules and file resolution).
    """
    urdf = to_yourdfpy(robot, positions, load_meshes=not collision, collision=collision,
                       package_paths=package_paths)
    return urdf.collision_scene if collision else urdf.scene
