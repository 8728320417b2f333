"""Write a :class:`RobotDescription` back to URDF XML (numbers in ``repr`` form, so they round-trip)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from robotmodel.model._robot import RobotDescription
from robotmodel.model._types import (
    Box,
    Cylinder,
    Geometry,
    Joint,
    Link,
    Material,
    Mesh,
    Pose,
    Sphere,
)

__all__ = ["to_urdf"]


def _f(values: tuple[float, ...]) -> str:
    return " ".join(repr(float(v)) for v in values)


def _origin(parent: ET.Element, pose: Pose) -> None:
    if pose != Pose():
        ET.SubElement(parent, "origin", xyz=_f(pose.xyz), rpy=_f(pose.rpy))


def _geometry(parent: ET.Element, geometry: Geometry) -> None:
    geom = ET.SubElement(parent, "geometry")
    if isinstance(geometry, Box):
        ET.SubElement(geom, "box", size=_f(geometry.size))
    elif isinstance(geometry, Cylinder):
        ET.SubElement(geom, "cylinder", radius=repr(geometry.radius), length=repr(geometry.length))
    elif isinstance(geometry, Sphere):
        ET.SubElement(geom, "sphere", radius=repr(geometry.radius))
    elif isinstance(geometry, Mesh):
        ET.SubElement(geom, "mesh", filename=geometry.filename, scale=_f(geometry.scale))


def _material(parent: ET.Element, material: Material) -> None:
    elem = ET.SubElement(parent, "material", name=material.name)
    if material.color is not None:
        ET.SubElement(elem, "color", rgba=_f(material.color))
    if material.texture is not None:
        ET.SubElement(elem, "texture", filename=material.texture)


def _named(name: str | None) -> dict[str, str]:
    return {"name": name} if name else {}


def _link(parent: ET.Element, link: Link) -> None:
    elem = ET.SubElement(parent, "link", name=link.name)
    if link.inertial is not None:
        inertial = ET.SubElement(elem, "inertial")
        _origin(inertial, link.inertial.origin)
        ET.SubElement(inertial, "mass", value=repr(link.inertial.mass))
        i = link.inertial.inertia
        ET.SubElement(inertial, "inertia", ixx=repr(i.ixx), ixy=repr(i.ixy), ixz=repr(i.ixz),
                      iyy=repr(i.iyy), iyz=repr(i.iyz), izz=repr(i.izz))
    for visual in link.visuals:
        v = ET.SubElement(elem, "visual", _named(visual.name))
        _origin(v, visual.origin)
        _geometry(v, visual.geometry)
        if visual.material is not None:
            _material(v, visual.material)
    for collision in link.collisions:
        c = ET.SubElement(elem, "collision", _named(collision.name))
        _origin(c, collision.origin)
        _geometry(c, collision.geometry)


def _joint(parent: ET.Element, joint: Joint) -> None:
    elem = ET.SubElement(parent, "joint", name=joint.name, type=joint.type.value)
    _origin(elem, joint.origin)
    ET.SubElement(elem, "parent", link=joint.parent)
    ET.SubElement(elem, "child", link=joint.child)
    ET.SubElement(elem, "axis", xyz=_f(joint.axis))
    if joint.limit is not None:
        attrs: dict[str, str] = {"effort": repr(joint.limit.effort), "velocity": repr(joint.limit.velocity)}
        if joint.limit.lower is not None:
            attrs["lower"] = repr(joint.limit.lower)
        if joint.limit.upper is not None:
            attrs["upper"] = repr(joint.limit.upper)
        ET.SubElement(elem, "limit", attrs)
    if joint.mimic is not None:
        ET.SubElement(elem, "mimic", joint=joint.mimic.joint, multiplier=repr(joint.mimic.multiplier),
                      offset=repr(joint.mimic.offset))
    if joint.dynamics is not None:
        ET.SubElement(elem, "dynamics", damping=repr(joint.dynamics.damping),
                      friction=repr(joint.dynamics.friction))
    if joint.safety_controller is not None:
        s = joint.safety_controller
        ET.SubElement(elem, "safety_controller", k_velocity=repr(s.k_velocity),
                      k_position=repr(s.k_position), soft_lower_limit=repr(s.soft_lower_limit),
                      soft_upper_limit=repr(s.soft_upper_limit))


def to_urdf(desc: RobotDescription) -> str:
    """Serialise ``desc`` as URDF XML text; ``parse_urdf(to_urdf(d)) == d``."""
    robot = ET.Element("robot", name=desc.name)
    for material in desc.materials:
        _material(robot, material)
    for link in desc.links:
        _link(robot, link)
    for joint in desc.joints:
        _joint(robot, joint)
    ET.indent(robot, space="  ")
    return '<?xml version="1.0"?>\n' + ET.tostring(robot, encoding="unicode") + "\n"
