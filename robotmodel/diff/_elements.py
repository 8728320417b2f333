"""What differs in one joint, link or material present on both sides.

Joint ends and mimic masters are compared through the rename map, so a renamed link or
joint does not show up again as a changed parent, child or mimic. Visuals and collisions
are compared by position in the link (``visual[0]``, ``collision[1]``); extra ones on
either side are reported as added or removed with their geometry.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from robotmodel.diff._compare import DEGREES, Fields, in_units
from robotmodel.diff._types import FieldChange, Json
from robotmodel.model import (
    Box,
    Collision,
    Cylinder,
    Dynamics,
    Geometry,
    Joint,
    JointType,
    Limit,
    Link,
    Material,
    Mesh,
    Pose,
    Sphere,
    Visual,
)

__all__ = ["compare_joint", "compare_link", "compare_material", "geometry_json", "joint_json", "material_json"]

_AXIS_TYPES = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC, JointType.PLANAR)
_INERTIA = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
RGBA = tuple[float, float, float, float]


def geometry_json(geometry: Geometry) -> dict[str, Json]:
    """A geometry as JSON: its kind and parameters (metres; a mesh's URI as written and its scale)."""
    if isinstance(geometry, Box):
        return {"type": "box", "size": list(geometry.size)}
    if isinstance(geometry, Cylinder):
        return {"type": "cylinder", "radius": geometry.radius, "length": geometry.length}
    if isinstance(geometry, Sphere):
        return {"type": "sphere", "radius": geometry.radius}
    return {"type": "mesh", "filename": geometry.filename, "scale": list(geometry.scale)}


def _origin_json(origin: Pose) -> dict[str, Json]:
    return {"xyz_mm": in_units(origin.xyz, 1000.0), "rpy_deg": in_units(origin.rpy, DEGREES)}


def _shape_json(shape: Visual | Collision) -> dict[str, Json]:
    out: dict[str, Json] = {"geometry": geometry_json(shape.geometry), "origin": _origin_json(shape.origin)}
    if shape.name is not None:
        out["name"] = shape.name
    if isinstance(shape, Visual) and shape.material is not None:
        out["material"] = shape.material.name
    return out


def joint_json(joint: Joint) -> dict[str, Json]:
    """A joint's summary for the added/removed lists: name, type, parent and child."""
    return {"name": joint.name, "type": joint.type.value, "parent": joint.parent, "child": joint.child}


def material_json(material: Material) -> dict[str, Json]:
    """A material's summary for the added/removed lists: name, colour (rgba) and texture."""
    return {"name": material.name, "color": None if material.color is None else list(material.color),
            "texture": material.texture}


def _geometry(fields: Fields, prefix: str, old: Geometry, new: Geometry) -> None:
    if type(old) is not type(new):
        fields.add(FieldChange(f"{prefix}.geometry", geometry_json(old), geometry_json(new)))
    elif isinstance(old, Box) and isinstance(new, Box):
        fields.vector(f"{prefix}.geometry.size", old.size, new.size, "m")
    elif isinstance(old, Cylinder) and isinstance(new, Cylinder):
        fields.number(f"{prefix}.geometry.radius", old.radius, new.radius, "m")
        fields.number(f"{prefix}.geometry.length", old.length, new.length, "m")
    elif isinstance(old, Sphere) and isinstance(new, Sphere):
        fields.number(f"{prefix}.geometry.radius", old.radius, new.radius, "m")
    elif isinstance(old, Mesh) and isinstance(new, Mesh):
        fields.text(f"{prefix}.geometry.filename", old.filename, new.filename)
        fields.vector(f"{prefix}.geometry.scale", old.scale, new.scale)


def _color(material: Material | None, named: Mapping[str, Material]) -> RGBA | None:
    """The colour a visual shows: its own, else that of the robot's material of the same name."""
    if material is None:
        return None
    if material.color is not None:
        return material.color
    found = named.get(material.name)
    return None if found is None else found.color


def _shapes(fields: Fields, kind: str, old: Sequence[Visual | Collision], new: Sequence[Visual | Collision],
            materials: tuple[Mapping[str, Material], Mapping[str, Material]]) -> None:
    for i, (a, b) in enumerate(zip(old, new, strict=False)):
        prefix = f"{kind}[{i}]"
        _geometry(fields, prefix, a.geometry, b.geometry)
        fields.pose(f"{prefix}.origin", a.origin, b.origin)
        fields.text(f"{prefix}.name", a.name, b.name)
        if isinstance(a, Visual) and isinstance(b, Visual):
            ma, mb = a.material, b.material
            names = (None if ma is None else ma.name, None if mb is None else mb.name)
            fields.text(f"{prefix}.material", *names)
            # Under one name a colour change is the named material's (reported once, in materials)
            # unless the visual gives its own; under a new name, the colour the visual now shows.
            if names[0] == names[1]:
                fields.vector(f"{prefix}.material.color", None if ma is None else ma.color,
                              None if mb is None else mb.color, "rgba")
            else:
                fields.vector(f"{prefix}.material.color", _color(ma, materials[0]), _color(mb, materials[1]), "rgba")
            fields.text(f"{prefix}.material.texture", None if ma is None else ma.texture,
                        None if mb is None else mb.texture)
    for i in range(len(new), len(old)):
        fields.add(FieldChange(f"{kind}[{i}]", _shape_json(old[i]), None))
    for i in range(len(old), len(new)):
        fields.add(FieldChange(f"{kind}[{i}]", None, _shape_json(new[i])))


def compare_link(old: Link, new: Link, tolerance: float,
                 materials: tuple[Mapping[str, Material], Mapping[str, Material]]) -> tuple[FieldChange, ...]:
    """The fields of a link that differ: inertial (mass, origin, inertia), visuals and collisions."""
    fields = Fields(tolerance)
    a, b = old.inertial, new.inertial
    if a is None or b is None:
        if a is not b:
            fields.add(FieldChange("inertial", None if a is None else a.mass, None if b is None else b.mass, "kg"))
    else:
        fields.number("inertial.mass", a.mass, b.mass, "kg")
        fields.pose("inertial.origin", a.origin, b.origin)
        for key in _INERTIA:
            fields.number(f"inertial.inertia.{key}", getattr(a.inertia, key), getattr(b.inertia, key), "kg·m²")
    _shapes(fields, "visual", old.visuals, new.visuals, materials)
    _shapes(fields, "collision", old.collisions, new.collisions, materials)
    return tuple(fields.changes)


def compare_joint(old: Joint, new: Joint, tolerance: float, links: Mapping[str, str],
                  joints: Mapping[str, str]) -> tuple[FieldChange, ...]:
    """The fields of a joint that differ; ``links``/``joints`` map old names to new ones."""
    fields = Fields(tolerance)
    fields.text("type", old.type.value, new.type.value)
    if links.get(old.parent) != new.parent:
        fields.add(FieldChange("parent", old.parent, new.parent))
    if links.get(old.child) != new.child:
        fields.add(FieldChange("child", old.child, new.child))
    fields.pose("origin", old.origin, new.origin)
    # A fixed or floating joint has no axis (urdfdom leaves its default): no change to report there.
    if old.type in _AXIS_TYPES and new.type in _AXIS_TYPES:
        fields.vector("axis", old.axis, new.axis)
    unit = "m" if new.type is JointType.PRISMATIC else "rad"
    la, lb = old.limit, new.limit
    if la is None or lb is None:
        if la is not lb:
            fields.add(FieldChange("limit", _limit_json(la), _limit_json(lb)))
    else:
        fields.number("limit.lower", la.lower, lb.lower, unit)
        fields.number("limit.upper", la.upper, lb.upper, unit)
        fields.number("limit.effort", la.effort, lb.effort, "N" if unit == "m" else "N·m")
        fields.number("limit.velocity", la.velocity, lb.velocity, f"{unit}/s")
    ma, mb = old.mimic, new.mimic
    if ma is None or mb is None:
        if ma is not mb:
            fields.add(FieldChange("mimic", None if ma is None else ma.joint, None if mb is None else mb.joint))
    else:
        if joints.get(ma.joint, ma.joint) != mb.joint:
            fields.add(FieldChange("mimic.joint", ma.joint, mb.joint))
        fields.number("mimic.multiplier", ma.multiplier, mb.multiplier)
        fields.number("mimic.offset", ma.offset, mb.offset, unit)
    da, db = old.dynamics, new.dynamics
    if da is None or db is None:
        if da is not db:
            fields.add(FieldChange("dynamics", _dynamics_json(da), _dynamics_json(db)))
    else:
        fields.number("dynamics.damping", da.damping, db.damping)
        fields.number("dynamics.friction", da.friction, db.friction)
    sa, sb = old.safety_controller, new.safety_controller
    if sa is None or sb is None:
        if sa is not sb:
            fields.add(FieldChange("safety_controller", sa is not None, sb is not None))
    else:
        for key in ("k_velocity", "k_position", "soft_lower_limit", "soft_upper_limit"):
            fields.number(f"safety_controller.{key}", getattr(sa, key), getattr(sb, key))
    return tuple(fields.changes)


def _limit_json(limit: Limit | None) -> Json:
    if limit is None:
        return None
    return {"lower": limit.lower, "upper": limit.upper, "effort": limit.effort, "velocity": limit.velocity}


def _dynamics_json(dynamics: Dynamics | None) -> Json:
    return None if dynamics is None else {"damping": dynamics.damping, "friction": dynamics.friction}


def compare_material(old: Material, new: Material, tolerance: float) -> tuple[FieldChange, ...]:
    """The fields of a robot-level named material that differ: colour and texture."""
    fields = Fields(tolerance)
    fields.vector("color", old.color, new.color, "rgba")
    fields.text("texture", old.texture, new.texture)
    return tuple(fields.changes)
