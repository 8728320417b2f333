"""Colours of visuals, resolved as rviz's RobotModel display does.

A visual's ``<material>`` gives its colour, directly or by the name of a material
declared at the top of the URDF. A mesh's own materials win over it for the parts that
have one (rviz assigns the URDF material only to sub-meshes without their own).
"""

from __future__ import annotations

from robotmodel.model import RGBA, Material, RobotDescription, Visual

__all__ = ["COLLISION_RGBA", "DEFAULT_RGBA", "PLACEHOLDER_RGBA", "visual_rgba"]

#: Links without any colour: rviz's light default.
DEFAULT_RGBA: RGBA = (0.8, 0.8, 0.8, 1.0)
#: Collision geometry: translucent orange, distinct from typical robot colours.
COLLISION_RGBA: RGBA = (1.0, 0.55, 0.0, 0.45)
#: Stand-in for a mesh that could not be loaded: loud magenta so it is noticed.
PLACEHOLDER_RGBA: RGBA = (1.0, 0.0, 1.0, 1.0)


def _named(desc: RobotDescription) -> dict[str, Material]:
    return {m.name: m for m in desc.materials}


def visual_rgba(desc: RobotDescription, visual: Visual, named: dict[str, Material] | None = None) -> RGBA | None:
    """The colour the URDF gives ``visual``, or None when it gives none."""
    material = visual.material
    if material is None:
        return None
    if material.color is not None:
        return material.color
    declared = (named if named is not None else _named(desc)).get(material.name)
    if declared is not None and declared.color is not None:
        return declared.color
    return None
