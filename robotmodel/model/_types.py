"""Typed, immutable values describing a robot's elements as URDF does (the whole robot: :mod:`._robot`).

Poses follow URDF: ``xyz`` in metres, ``rpy`` in radians, where rpy means roll about
the fixed X axis, then pitch about fixed Y, then yaw about fixed Z (R = Rz·Ry·Rx).
A joint's ``origin`` is ``T_parent_joint``: it maps points in the joint frame (which
coincides with the child link frame at zero position) into the parent link frame.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

Vec3 = tuple[float, float, float]
RGBA = tuple[float, float, float, float]

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
    "SafetyController",
    "Sphere",
    "Vec3",
    "Visual",
]


class JointType(Enum):
    """URDF joint types; the value is the spelling used in the XML."""

    REVOLUTE = "revolute"
    CONTINUOUS = "continuous"
    PRISMATIC = "prismatic"
    FIXED = "fixed"
    FLOATING = "floating"
    PLANAR = "planar"

    @property
    def is_movable(self) -> bool:
        """Whether the joint has at least one degree of freedom."""
        return self is not JointType.FIXED


@dataclass(frozen=True, slots=True)
class Pose:
    """A URDF ``<origin>``: translation ``xyz`` and fixed-axis ``rpy``."""

    xyz: Vec3 = (0.0, 0.0, 0.0)
    rpy: Vec3 = (0.0, 0.0, 0.0)


@dataclass(frozen=True, slots=True)
class Box:
    """Box geometry with full side lengths."""

    size: Vec3


@dataclass(frozen=True, slots=True)
class Cylinder:
    """Cylinder geometry along the local Z axis."""

    radius: float
    length: float


@dataclass(frozen=True, slots=True)
class Sphere:
    """Sphere geometry."""

    radius: float


@dataclass(frozen=True, slots=True)
class Mesh:
    """Mesh geometry; ``filename`` is the URI as written (``package://``, ``file://`` or a path)."""

    filename: str
    scale: Vec3 = (1.0, 1.0, 1.0)


Geometry = Box | Cylinder | Sphere | Mesh


@dataclass(frozen=True, slots=True)
class Material:
    """A named material; ``color`` and ``texture`` are None when only referenced by name."""

    name: str
    color: RGBA | None = None
    texture: str | None = None


@dataclass(frozen=True, slots=True)
class Visual:
    """A visual element of a link."""

    geometry: Geometry
    origin: Pose = field(default_factory=Pose)
    name: str | None = None
    material: Material | None = None


@dataclass(frozen=True, slots=True)
class Collision:
    """A collision element of a link."""

    geometry: Geometry
    origin: Pose = field(default_factory=Pose)
    name: str | None = None


@dataclass(frozen=True, slots=True)
class Inertia:
    """The rotational inertia tensor's six independent entries (kg·m²)."""

    ixx: float = 0.0
    ixy: float = 0.0
    ixz: float = 0.0
    iyy: float = 0.0
    iyz: float = 0.0
    izz: float = 0.0


@dataclass(frozen=True, slots=True)
class Inertial:
    """Mass properties; ``origin`` places the centre of mass and inertia frame in the link frame."""

    mass: float
    inertia: Inertia
    origin: Pose = field(default_factory=Pose)


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid body."""

    name: str
    visuals: tuple[Visual, ...] = ()
    collisions: tuple[Collision, ...] = ()
    inertial: Inertial | None = None


@dataclass(frozen=True, slots=True)
class Limit:
    """Joint limits; ``lower``/``upper`` are None where the URDF gives none."""

    effort: float
    velocity: float
    lower: float | None = None
    upper: float | None = None


@dataclass(frozen=True, slots=True)
class Mimic:
    """Mimicry of another joint: value = multiplier × value of ``joint`` + offset."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class Dynamics:
    """Joint damping and friction."""

    damping: float = 0.0
    friction: float = 0.0


@dataclass(frozen=True, slots=True)
class SafetyController:
    """Soft limits of a joint's safety controller."""

    k_velocity: float
    k_position: float = 0.0
    soft_lower_limit: float = 0.0
    soft_upper_limit: float = 0.0


@dataclass(frozen=True, slots=True)
class Joint:
    """A joint between ``parent`` and ``child`` links; ``origin`` is T_parent_joint."""

    name: str
    type: JointType
    parent: str
    child: str
    origin: Pose = field(default_factory=Pose)
    axis: Vec3 = (1.0, 0.0, 0.0)
    limit: Limit | None = None
    mimic: Mimic | None = None
    dynamics: Dynamics | None = None
    safety_controller: SafetyController | None = None
