"""Forward kinematics of one configuration in O(joints) time and memory, without Pinocchio.

Every joint's local transform comes from the same constants as robot_state_publisher's
cycle (``_fast.CycleTables``, a few array operations for all joints); they are composed
along the tree by pointer jumping (``⌈log2 depth⌉`` whole-array rounds).
Floating joints take ``x y z qx qy qz qw`` and planar joints ``x y θ`` (a translation in
the joint's xy plane, then a turn about its z axis), as Pinocchio reads them.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robotmodel.errors import KinematicsError
from robotmodel.kinematics._fast import CycleTables
from robotmodel.kinematics._joints import JointTable
from robotmodel.spatial import FloatArray, quat_to_matrix

__all__ = ["LinkTree", "check_poses", "compose_tree", "free_motion"]


def free_motion(floating: bool, value: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Rotation and translation of a floating (7 values) or planar (3 values) joint's motion."""
    if floating:
        return quat_to_matrix(value[3:]), np.asarray(value[:3], dtype=np.float64)
    c, s = math.cos(value[2]), math.sin(value[2])
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]), np.array([value[0], value[1], 0.0])


def check_poses(robot: str, rotations: FloatArray, translations: FloatArray) -> None:
    """Raise :class:`KinematicsError` when a pose overflowed: a NaN or infinite pose is never returned.

    With finite joint values (checked where they enter) rotations are products of
    rotation matrices, whose entries stay in [-1, 1]: only translations can overflow.
    """
    if np.isfinite(translations).all():
        return
    raise KinematicsError(
        f"robot '{robot}': link poses overflow to infinity (origins or joint values too large)")


def compose_tree(
    table: JointTable, tables: CycleTables, values: FloatArray, free: dict[int, tuple[FloatArray, FloatArray]],
    tree: LinkTree, robot: str,
) -> tuple[FloatArray, FloatArray]:
    """T_root_link of every link: rotations ``(L, 3, 3)`` and translations ``(L, 3)``.

    ``tables`` are the publishing cycle's constants for every row of ``table`` (fixed rows
    give their origin); ``values`` holds every joint's value (table order); ``free`` the
    motion of floating and planar joints by table row. Raises :class:`KinematicsError`
    when a pose overflows.
    """
    # Overflow is checked once at the end instead of warned about on the way.
    with np.errstate(over="ignore", invalid="ignore"):
        local_t, quats = tables.evaluate(values)
        local_r = quat_to_matrix(quats)
        for row, (r, t) in free.items():
            origin = table.origin_rotation[row]
            local_r[row] = origin @ r
            local_t[row] = table.origin_translation[row] + origin @ t
        if not len(local_r):
            # A robot of one link: nothing to compose.
            return np.eye(3)[None].repeat(len(tree.parent), axis=0), np.zeros((len(tree.parent), 3))
        rotations = local_r[tree.joint_row]
        translations = local_t[tree.joint_row]
        rotations[tree.root] = np.eye(3)
        translations[tree.root] = 0.0
        # Pointer jumping: each link holds T_ancestor_link and its ancestor; every round
        # prepends the ancestor's own transform and doubles the span, so ⌈log2 depth⌉ rounds
        # of whole-array products replace a Python loop over the joints.
        ancestor = tree.parent.copy()
        active = np.flatnonzero(ancestor != tree.root)
        while active.size:
            up = ancestor[active]
            r_up = rotations[up]
            translations[active] = np.einsum("nij,nj->ni", r_up, translations[active]) + translations[up]
            rotations[active] = r_up @ rotations[active]
            ancestor[active] = ancestor[up]
            active = active[ancestor[active] != tree.root]
    check_poses(robot, rotations, translations)
    return rotations, translations


@dataclass(frozen=True)
class LinkTree:
    """The tree by link index: each link's parent link and the table row of the joint above it.

    The root is its own parent; its joint row is 0, a placeholder overwritten by identity.
    """

    root: int
    parent: npt.NDArray[np.intp]
    joint_row: npt.NDArray[np.intp]

    @classmethod
    def build(cls, root: int, n_links: int, walk: Iterable[tuple[int, int, int]]) -> LinkTree:
        """From (joint row, parent link, child link) triples."""
        parent = np.full(n_links, root, dtype=np.intp)
        joint_row = np.zeros(n_links, dtype=np.intp)
        for row, up, child in walk:
            parent[child] = up
            joint_row[child] = row
        return cls(root, parent, joint_row)
