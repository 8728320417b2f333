"""Batch forward kinematics and robot_state_publisher's per-joint transforms, vectorized in NumPy."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robotmodel.kinematics._joints import KIND_FIXED, local_transforms
from robotmodel.kinematics._model import KinematicModel
from robotmodel.model import JointType
from robotmodel.spatial import FloatArray, matrix_to_quat

__all__ = ["JointTransforms", "batch_link_matrices", "joint_transforms", "static_transforms"]


@dataclass(frozen=True)
class JointTransforms:
    """T_parent_child for a set of joints: ``translations (J, 3)``, ``rotations (J, 4)`` as x y z w."""

    joints: tuple[str, ...]
    parents: tuple[str, ...]
    children: tuple[str, ...]
    translations: FloatArray
    rotations: FloatArray

    def matrices(self) -> FloatArray:
        """``(J, 4, 4)`` homogeneous matrices."""
        from robotmodel.spatial import quat_to_matrix

        out = np.zeros((len(self.joints), 4, 4))
        out[:, :3, :3] = quat_to_matrix(self.rotations)
        out[:, :3, 3] = self.translations
        out[:, 3, 3] = 1.0
        return out


def _select(model: KinematicModel, rows: list[int], values: FloatArray) -> JointTransforms:
    table = model.table
    idx = np.asarray(rows, dtype=np.intp)
    sub = type(table)(
        names=tuple(table.names[i] for i in rows), parents=tuple(table.parents[i] for i in rows),
        children=tuple(table.children[i] for i in rows), kinds=table.kinds[idx],
        origin_rotation=table.origin_rotation[idx], origin_translation=table.origin_translation[idx],
        axis=table.axis[idx],
    )
    rotation, translation = local_transforms(sub, values[idx])
    return JointTransforms(sub.names, sub.parents, sub.children, translation, matrix_to_quat(rotation))


def static_transforms(model: KinematicModel) -> JointTransforms:
    """What robot_state_publisher sends on /tf_static: fixed joints, and planar ones at their origin."""
    static = (JointType.FIXED, JointType.PLANAR)
    rows = [i for i, j in enumerate(model.description.joints) if j.type in static]
    return _select(model, rows, np.zeros(len(model.table.names)))


def joint_transforms(model: KinematicModel, positions: Mapping[str, float]) -> JointTransforms:
    """What robot_state_publisher sends on /tf for one joint state.

    Only joints named in ``positions`` are published, plus mimic joints whose master is
    (an explicit mimic value wins). Fixed, planar and floating joints are not (floating
    gets no transform at all, as in RSP). Values are taken as given: RSP does not clamp.
    """
    index = model._joint_index
    values = np.zeros(len(model.table.names))
    rows: list[int] = []
    for name, value in positions.items():
        i = index.get(name)
        if i is not None and model.table.kinds[i] != KIND_FIXED:
            values[i] = value
            rows.append(i)
    for rule in model.mimics.values():
        if rule.joint not in positions and rule.master in positions:
            i = index[rule.joint]
            values[i] = rule.multiplier * positions[rule.master] + rule.offset
            rows.append(i)
    rows.sort()
    return _select(model, rows, values)


def batch_link_matrices(model: KinematicModel, q: npt.ArrayLike) -> FloatArray:
    """``(N, L, 4, 4)`` T_root_link for ``N`` configurations ``(N, nv)``, without a per-config loop.

    Floating and planar joints stay at their origin. Values are not limit-checked here;
    validate with :meth:`KinematicModel.vector` where they come from users.
    """
    configs = np.asarray(q, dtype=np.float64)
    if configs.ndim != 2 or configs.shape[1] != model.nv:
        raise ValueError(f"expected an (N, {model.nv}) array of joint values, got shape {configs.shape}")
    n = configs.shape[0]
    rotation, translation = local_transforms(model.table, model.joint_values(configs))
    link_index = {name: i for i, name in enumerate(model.link_names)}
    out = np.empty((n, len(model.link_names), 4, 4))
    out[:, :, 3, :3] = 0.0
    out[:, :, 3, 3] = 1.0
    root = link_index[model.root]
    out[:, root, :3, :3] = np.eye(3)
    out[:, root, :3, 3] = 0.0
    for _, joint in model.description.walk():
        j = model._joint_index[joint.name]
        parent = out[:, link_index[joint.parent]]
        child = out[:, link_index[joint.child]]
        child[:, :3, :3] = parent[:, :3, :3] @ rotation[:, j]
        child[:, :3, 3] = np.einsum("nab,nb->na", parent[:, :3, :3], translation[:, j]) + parent[:, :3, 3]
    return out
