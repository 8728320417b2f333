"""The typed robot description: parse URDF into immutable values, and write it back."""

from __future__ import annotations

from robotmodel.model._load import load
from robotmodel.model._parse import parse_urdf
from robotmodel.model._robot import RobotDescription
from robotmodel.model._source import load_source, read_stdin_document
from robotmodel.model._types import (
    RGBA,
    Box,
    Collision,
    Cylinder,
    Dynamics,
    Geometry,
    Inertia,
    Inertial,
    Joint,
    JointType,
    Limit,
    Link,
    Material,
    Mesh,
    Mimic,
    Pose,
    SafetyController,
    Sphere,
    Vec3,
    Visual,
)
from robotmodel.model._write import to_urdf

__all__ = [
    "RGBA",
    "Box",
    "Collision",
    "Cylinder",
    "Dynamics",
    "Geometry",
    "Inertia",
    "Inertial",
    "Joint",
    "JointType",
    "Limit",
    "Link",
    "Material",
    "Mesh",
    "Mimic",
    "Pose",
    "RobotDescription",
    "SafetyController",
    "Sphere",
    "Vec3",
    "Visual",
    "load",
    "load_source",
    "parse_urdf",
    "read_stdin_document",
    "to_urdf",
]
