"""Forward kinematics of one configuration in O(joints) time and memory, without Pinocchio.

Every joint's local transform comes from the same constants as robot_state_publisher's
cycle (``_fast.CycleTables``, a few array operations for all joints); they are composed
parents-first along the tree.
Floating joints take ``x y z qx qy qz qw`` and planar joints ``x y θ`` (a translation in
the joint's xy plane, then a turn about its z axis), as Pinocchio reads them.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from robotmodel.errors import KinematicsError
from robotmodel.kinematics._fast import CycleTables
from robotmodel.kinematics._joints import JointTable
from robotmodel.spatial import FloatArray, quat_to_matrix

__all__ = ["check_poses", "compose_tree", "free_motion"]


def free_motion(floating: bool, value: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Rotation and translation of a floating (7 values) or planar (3 values) joint's motion."""
    if floating:
        return quat_to_matrix(value[3:]), np.asarray(value[:3], dtype=np.float64)
    c, s = math.cos(value[2]), math.sin(value[2])
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]), np.array([value[0], value[1], 0.0])


def check_poses(robot: str, rotations: FloatArray, translations: FloatArray) -> None:
    """Raise :class:`KinematicsError` when a pose overflowed: a NaN or infinite pose is never returned."""
    if np.isfinite(translations).all() and np.isfinite(rotations).all():
        return
    raise KinematicsError(
        f"robot '{robot}': link poses overflow to infinity (origins or joint values too large)")


def compose_tree(
    table: JointTable, tables: CycleTables, values: FloatArray, free: dict[int, tuple[FloatArray, FloatArray]],
    walk: Iterable[tuple[int, int, int]], root: int, n_links: int, robot: str,
) -> tuple[FloatArray, FloatArray]:
    """T_root_link of every link: rotations ``(L, 3, 3)`` and translations ``(L, 3)``.

    ``tables`` are the publishing cycle's constants for every row of ``table`` (fixed rows
    give their origin); ``values`` holds every joint's value (table order); ``free`` the
    motion of floating and planar joints by table row; ``walk`` lists (joint row, parent
    link, child link) parents first. Raises :class:`KinematicsError` when a pose overflows.
    """
    # Overflow is checked once at the end instead of warned about on the way.
    with np.errstate(over="ignore", invalid="ignore"):
        local_t, quats = tables.evaluate(values)
        local_r = quat_to_matrix(quats)
        for row, (r, t) in free.items():
            origin = table.origin_rotation[row]
            local_r[row] = origin @ r
            local_t[row] = table.origin_translation[row] + origin @ t
        rotations = np.empty((n_links, 3, 3))
        translations = np.empty((n_links, 3))
        rotations[root] = np.eye(3)
        translations[root] = 0.0
        for row, parent, child in walk:
            r_parent = rotations[parent]
            np.matmul(r_parent, local_r[row], out=rotations[child])
            np.add(r_parent @ local_t[row], translations[parent], out=translations[child])
    check_poses(robot, rotations, translations)
    return rotations, translations
