"""urdfdom-compatible text: ``check_urdf``'s tree listing and ``urdf_to_graphviz``'s .gv file."""

from __future__ import annotations

import math

from robotmodel.model import RobotDescription, Vec3

__all__ = ["to_graphviz", "tree_report", "urdfdom_rpy"]


def tree_report(desc: RobotDescription) -> str:
    """The exact stdout of urdfdom's ``check_urdf`` for a valid robot."""
    lines = [
        f"robot name is: {desc.name}",
        "---------- Successfully Parsed XML ---------------",
        f"root Link: {desc.root} has {len(desc.child_joints(desc.root))} child(ren)",
    ]
    # Each child's index is its 1-based position among its siblings (joint-name order).
    index: dict[str, int] = {}
    for joints in (desc.child_joints(link.name) for link in desc.links):
        for i, joint in enumerate(joints, start=1):
            index[joint.name] = i
    for depth, joint in desc.walk():
        lines.append(f"{'    ' * depth}child({index[joint.name]}):  {joint.child}")
    return "\n".join(lines) + "\n"


def urdfdom_rpy(rpy: Vec3) -> Vec3:
    """RPY as urdfdom reports it: through its normalized quaternion and back (its ``getRPY``)."""
    half_r, half_p, half_y = rpy[0] / 2.0, rpy[1] / 2.0, rpy[2] / 2.0
    sr, cr = math.sin(half_r), math.cos(half_r)
    sp, cp = math.sin(half_p), math.cos(half_p)
    sy, cy = math.sin(half_y), math.cos(half_y)
    x = sr * cp * cy - cr * sp * sy
    y = cr * sp * cy + sr * cp * sy
    z = cr * cp * sy - sr * sp * cy
    w = cr * cp * cy + sr * sp * sy
    norm2 = x * x + y * y + z * z + w * w
    if norm2 <= 0.0:
        x, y, z, w = 0.0, 0.0, 0.0, 1.0
    else:
        s = math.sqrt(norm2)
        x, y, z, w = x / s, y / s, z / s, w / s
    sarg = -2 * (x * z - w * y)
    if sarg <= -0.99999:
        return (0.0, -math.pi / 2, 2 * math.atan2(x, -y))
    if sarg >= 0.99999:
        return (0.0, math.pi / 2, 2 * math.atan2(-x, y))
    roll = math.atan2(2 * (y * z + w * x), w * w - x * x - y * y + z * z)
    yaw = math.atan2(2 * (x * y + w * z), w * w + x * x - y * y - z * z)
    return (roll, math.asin(sarg), yaw)


def _g(value: float) -> str:
    # C++ ostream's default float format is printf's %g with 6 significant digits.
    return f"{value:g}"


def to_graphviz(desc: RobotDescription) -> str:
    """The .gv text urdfdom's ``urdf_to_graphviz`` writes, byte for byte."""
    out = ["digraph G {", "node [shape=box];"]
    out.append(f'"{desc.root}" [label="{desc.root}"];')
    out.extend(f'"{j.child}" [label="{j.child}"];' for _, j in desc.walk())
    out.append("node [shape=ellipse, color=blue, fontcolor=blue];")
    for _, joint in desc.walk():
        x, y, z = joint.origin.xyz
        r, p, yaw = urdfdom_rpy(joint.origin.rpy)
        label = f"xyz: {_g(x)} {_g(y)} {_g(z)} \\nrpy: {_g(r)} {_g(p)} {_g(yaw)}"
        out.append(f'"{joint.parent}" -> "{joint.name}" [label="{label}"]')
        out.append(f'"{joint.name}" -> "{joint.child}"')
    out.append("}")
    return "\n".join(out) + "\n"
