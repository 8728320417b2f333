"""Validation of a description however it was made, with the messages parse_urdf gives.

:func:`robotmodel.model.parse_urdf` checks the text element by element as it reads; a
:class:`RobotDescription` built or changed in Python never went through that, so its
construction runs these checks. The order and texts follow the parser, so the same robot
fails with the same sentence either way (the parser adds the file and line in front).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from robotmodel.errors import URDFError, URDFParseError
from robotmodel.model._tree import validate_tree
from robotmodel.model._types import (
    Box,
    Cylinder,
    Geometry,
    Joint,
    JointType,
    Link,
    Material,
    Mesh,
    Pose,
    Sphere,
)

__all__ = ["validate_description"]


def _finite(values: Iterable[float], what: str) -> None:
    for value in values:
        if not math.isfinite(value):
            raise URDFParseError(f"{what}: value [{float(value)!r}] is not a finite number")


def _pose(pose: Pose, what: str) -> None:
    _finite(pose.xyz, f"malformed origin xyz of {what}")
    _finite(pose.rpy, f"malformed origin rpy of {what}")


def _geometry(geometry: Geometry, what: str) -> None:
    if isinstance(geometry, Box):
        _finite(geometry.size, f"{what}: box size")
    elif isinstance(geometry, Cylinder):
        _finite((geometry.radius,), f"{what}: cylinder radius")
        _finite((geometry.length,), f"{what}: cylinder length")
    elif isinstance(geometry, Sphere):
        _finite((geometry.radius,), f"{what}: sphere radius")
    elif isinstance(geometry, Mesh):
        if not geometry.filename:
            raise URDFParseError(f"{what}: Mesh must contain a filename attribute")
        _finite(geometry.scale, f"{what}: mesh scale")


def _material(material: Material, what: str) -> None:
    if material.color is not None:
        _finite(material.color, f"{what}: material color rgba")


def _link(link: Link) -> None:
    if not link.name:
        raise URDFParseError("No name given for the link.")
    for k, visual in enumerate(link.visuals):
        what = f"visual {k} of link [{link.name}]"
        _geometry(visual.geometry, what)
        _pose(visual.origin, what)
        if visual.material is not None:
            _material(visual.material, what)
    for k, collision in enumerate(link.collisions):
        what = f"collision {k} of link [{link.name}]"
        _geometry(collision.geometry, what)
        _pose(collision.origin, what)
    inertial = link.inertial
    if inertial is not None:
        what = f"inertial of link [{link.name}]"
        _finite((inertial.mass,), f"{what}: mass")
        ine = inertial.inertia
        for key, value in (("ixx", ine.ixx), ("ixy", ine.ixy), ("ixz", ine.ixz), ("iyy", ine.iyy),
                           ("iyz", ine.iyz), ("izz", ine.izz)):
            _finite((value,), f"{what}: inertia {key}")
        _pose(inertial.origin, what)


def _joint(joint: Joint) -> None:
    name = joint.name
    if not name:
        raise URDFParseError("unnamed joint found")
    if not joint.parent or not joint.child:
        raise URDFError(f"Joint [{name}] is missing a parent and/or child link specification.")
    if joint.type not in (JointType.FIXED, JointType.FLOATING):
        _finite(joint.axis, f"Malformed axis element for joint [{name}]")
        if all(v == 0.0 for v in joint.axis):
            raise URDFError(f"joint [{name}] has a zero axis")
    if joint.mimic is not None:
        if not joint.mimic.joint:
            raise URDFParseError(f"mimic element of joint [{name}] has no joint attribute")
        _finite((joint.mimic.multiplier, joint.mimic.offset), f"mimic of joint [{name}]")
    if joint.dynamics is not None:
        _finite((joint.dynamics.damping, joint.dynamics.friction), f"dynamics of joint [{name}]")
    sc = joint.safety_controller
    if sc is not None:
        _finite((sc.k_velocity, sc.k_position, sc.soft_lower_limit, sc.soft_upper_limit),
                f"safety_controller of joint [{name}]")
    _pose(joint.origin, f"joint [{name}]")
    limit = joint.limit
    if limit is None:
        if joint.type is JointType.REVOLUTE:
            raise URDFError(f"Joint [{name}] is of type REVOLUTE but it does not specify limits")
        if joint.type is JointType.PRISMATIC:
            raise URDFError(f"Joint [{name}] is of type PRISMATIC without limits")
        return
    bounds = [v for v in (limit.lower, limit.upper) if v is not None]
    _finite((limit.effort, limit.velocity, *bounds), f"limit of joint [{name}]")


def validate_description(
    name: str, links: Sequence[Link], joints: Sequence[Joint], materials: Sequence[Material],
) -> str:
    """Check a whole description as :func:`parse_urdf` does; return the root link's name."""
    if not name:
        raise URDFParseError("No name given for the robot.")
    seen: set[str] = set()
    for material in materials:
        _material(material, f"material [{material.name}]")
        if not material.name:
            raise URDFParseError("material without a name")
        if material.name in seen:
            raise URDFError(f"material '{material.name}' is not unique.")
        seen.add(material.name)
    seen = set()
    for link in links:
        _link(link)
        if link.name in seen:
            raise URDFError(f"link '{link.name}' is not unique.")
        seen.add(link.name)
    if not links:
        raise URDFError("No link elements found in urdf file")
    seen = set()
    for joint in joints:
        _joint(joint)
        if joint.name in seen:
            raise URDFError(f"joint '{joint.name}' is not unique.")
        seen.add(joint.name)
    return validate_tree([link.name for link in links], joints)
