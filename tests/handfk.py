"""An independent forward-kinematics reference written from the URDF spec, for tests only.

It reads the URDF XML itself and composes origins and joint motions with plain NumPy,
sharing no code with robotmodel.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np


def _rot_x(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def _rot_y(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def _rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _axis_angle(axis: np.ndarray, angle: float) -> np.ndarray:
    # Rotate the basis vectors with Rodrigues' vector formula (not the matrix form).
    k = axis / np.linalg.norm(axis)
    cols = []
    for v in np.eye(3):
        cols.append(v * math.cos(angle) + np.cross(k, v) * math.sin(angle) + k * np.dot(k, v) * (1 - math.cos(angle)))
    return np.array(cols).T


def _origin(elem: ET.Element | None) -> np.ndarray:
    t = np.eye(4)
    if elem is None:
        return t
    xyz = [float(v) for v in elem.get("xyz", "0 0 0").split()]
    r, p, y = (float(v) for v in elem.get("rpy", "0 0 0").split())
    t[:3, :3] = _rot_z(y) @ _rot_y(p) @ _rot_x(r)  # URDF: fixed-axis X, then Y, then Z
    t[:3, 3] = xyz
    return t


class HandFK:
    """FK of every link relative to the root, from joint values by name (mimics computed)."""

    def __init__(self, urdf_text: str) -> None:
        robot = ET.fromstring(urdf_text)
        self.joints = {j.get("name"): j for j in robot.findall("joint")}
        children = {j.find("child").get("link") for j in self.joints.values()}
        links = [link.get("name") for link in robot.findall("link")]
        self.root = next(n for n in links if n not in children)
        self.links = links

    def value(self, name: str, values: dict[str, float]) -> float:
        joint = self.joints[name]
        mimic = joint.find("mimic")
        if mimic is not None and mimic.get("joint") in self.joints:
            master = self.value(mimic.get("joint"), values)
            return float(mimic.get("multiplier", "1")) * master + float(mimic.get("offset", "0"))
        return values.get(name, 0.0)

    def local(self, name: str, values: dict[str, float]) -> np.ndarray:
        joint = self.joints[name]
        t = _origin(joint.find("origin"))
        kind = joint.get("type")
        axis_elem = joint.find("axis")
        axis = np.array([float(v) for v in (axis_elem.get("xyz") if axis_elem is not None else "1 0 0").split()])
        motion = np.eye(4)
        if kind in ("revolute", "continuous"):
            motion[:3, :3] = _axis_angle(axis, self.value(name, values))
        elif kind == "prismatic":
            motion[:3, 3] = axis / np.linalg.norm(axis) * self.value(name, values)
        return t @ motion

    def poses(self, values: dict[str, float]) -> dict[str, np.ndarray]:
        out = {self.root: np.eye(4)}
        pending = list(self.joints.values())
        while pending:
            rest = []
            for joint in pending:
                parent, child = joint.find("parent").get("link"), joint.find("child").get("link")
                if parent in out:
                    out[child] = out[parent] @ self.local(joint.get("name"), values)
                else:
                    rest.append(joint)
            pending = rest
        return out
