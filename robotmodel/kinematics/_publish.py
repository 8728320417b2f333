"""Batch forward kinematics and robot_state_publisher's per-joint transforms, vectorized in NumPy."""

from __future__ import annotations

from collections.abc import Mapping
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from robotmodel.errors import JointValueError
from robotmodel.kinematics._joints import KIND_FIXED, KIND_PRISMATIC, KIND_REVOLUTE, local_transforms
from robotmodel.kinematics._model import KinematicModel, _Cycle
from robotmodel.kinematics._single import check_poses
from robotmodel.model import JointType
from robotmodel.spatial import FloatArray, matrix_to_quat, quat_canonical, quats_canonical

__all__ = [
    "JointTransforms", "batch_link_matrices", "batch_link_poses", "joint_transforms", "static_transforms",
    "variable_transforms",
]


class JointTransforms(NamedTuple):
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


# Below this many joints spatial's scalar kernel in a loop beats its batched one, whose cost
# is a fixed ~35 array operations (measured: 8 rows 17 us vs 76 us, 32 rows 63 us vs 77 us).
_SCALAR_ROWS = 24


def _canonical(quats: FloatArray) -> FloatArray:
    """tf2's canonical form of every quaternion, through spatial's kernels (the one definition)."""
    if len(quats) < _SCALAR_ROWS:
        return np.array([quat_canonical(q) for q in quats.tolist()]).reshape(-1, 4)
    return quats_canonical(quats)


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
    return JointTransforms(sub.names, sub.parents, sub.children, translation,
                           _canonical(matrix_to_quat(rotation)))


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
    cycle = model._cycle
    try:
        # The usual message names every movable joint: one array, no per-joint branching.
        values = np.array([positions[n] for n in cycle.independent])
        complete = True
    except KeyError:
        complete = False
    if complete:
        if cycle.has_mimics and len(positions) > len(values) and any(n in positions for n in cycle.explicit_mimic):
            full = values[cycle.source] * cycle.multiplier + cycle.offset
            for name, row in cycle.explicit_mimic.items():
                if name in positions:
                    full[row] = positions[name]
            return _cycle_result(cycle, full)
        return variable_transforms(model, values)
    index = model._joint_index
    table = model.table
    all_values = np.zeros(len(table.names))
    rows: list[int] = []
    for name, value in positions.items():
        i = index.get(name)
        if i is not None and table.kinds[i] != KIND_FIXED:
            all_values[i] = value
            rows.append(i)
    for rule in model.mimics.values():
        if rule.joint not in positions and rule.master in positions:
            i = index[rule.joint]
            all_values[i] = rule.multiplier * positions[rule.master] + rule.offset
            rows.append(i)
    rows.sort()
    return _select(model, rows, all_values)


def variable_transforms(model: KinematicModel, q: FloatArray) -> JointTransforms:
    """What robot_state_publisher sends when a joint state names every variable (and no mimic joint).

    ``q`` holds the values of ``model.variables`` in that order (a float64 array); every
    revolute, continuous and prismatic joint is published, mimic joints from their
    masters: :func:`joint_transforms` of the same values, without the mapping.
    """
    cycle = model._cycle
    if not cycle.has_mimics:
        return _cycle_result(cycle, q)
    full = q[cycle.source]  # q·multiplier + offset, in place
    full *= cycle.multiplier
    full += cycle.offset
    return _cycle_result(cycle, full)


def _cycle_result(cycle: _Cycle, full: FloatArray) -> JointTransforms:
    # The quaternion (P·sin + Q·cos) has either sign; tf2's is the one every path gives.
    translations, rotations = cycle.tables.evaluate_canonical(full)
    return JointTransforms(cycle.joints, cycle.parents, cycle.children, translations, rotations)


def batch_link_poses(model: KinematicModel, q: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    """T_root_link of every link for ``N`` configurations ``(N, nv)``, without a per-config loop.

    Link-major: rotations ``(L, N, 3, 3)`` and translations ``(L, N, 3)``, in
    ``model.link_names`` order.

    Floating and planar joints stay at their origin. Values are not limit-checked here;
    validate with :meth:`KinematicModel.vector` where they come from users.
    """
    try:
        configs = np.asarray(q, dtype=np.float64)
    except (TypeError, ValueError):
        raise JointValueError(f"expected {model.nv} joint values per configuration, an (N, {model.nv}) "
                              "array of numbers") from None
    if configs.ndim != 2 or configs.shape[1] != model.nv:
        raise JointValueError(f"expected {model.nv} joint values per configuration, an (N, {model.nv}) "
                              f"array; got shape {configs.shape}")
    n = configs.shape[0]
    rotations = np.empty((len(model.link_names), n, 3, 3))
    translations = np.empty((len(model.link_names), n, 3))
    # Chunks small enough to stay in cache; each chunk is fully vectorized.
    # Overflow is checked once at the end instead of warned about on the way.
    with np.errstate(over="ignore", invalid="ignore"):
        for start in range(0, n, _CHUNK):
            stop = min(n, start + _CHUNK)
            _batch_chunk(model, configs[start:stop], rotations[:, start:stop], translations[:, start:stop])
    check_poses(model.description.name, rotations, translations)
    return rotations, translations


_CHUNK = 16384
# For a rotation about axis k, the (p, q) plane it turns: R = I except [p,p]=[q,q]=c, [p,q]=-s, [q,p]=s.
_PLANE = {0: (1, 2), 1: (2, 0), 2: (0, 1)}


def _batch_chunk(model: KinematicModel, configs: FloatArray, rotations: FloatArray,
                 translations: FloatArray) -> None:
    n = configs.shape[0]
    values = model.joint_values(configs)
    model.check_finite(values)
    table = model.table
    link_index = model._link_index
    root = link_index[model.root]
    rotations[root] = np.eye(3)
    translations[root] = 0.0
    scratch = np.empty((n, 3, 3))
    identity = model._origin_identity
    for j, parent, child in model._walk_rows:
        r_parent = rotations[parent].reshape(n * 3, 3)
        # Products with constant 3x3 matrices only: BLAS does all N at once.
        a = rotations[parent] if identity[j] else (r_parent @ table.origin_rotation[j]).reshape(n, 3, 3)
        out_t = translations[child]
        np.add(translations[parent], r_parent.dot(table.origin_translation[j]).reshape(n, 3), out=out_t)
        kind = table.kinds[j]
        out_r = rotations[child]
        aligned = model._aligned[j]
        if kind == KIND_REVOLUTE and aligned is not None:
            # Axis along ±x/±y/±z (most URDF joints): A·R(θ) only mixes two columns of A.
            axis_index, sign = aligned
            theta = values[:, j] if sign > 0 else -values[:, j]
            c, s = np.cos(theta)[:, None], np.sin(theta)[:, None]
            p, q = _PLANE[axis_index]
            col_p, col_q = a[:, :, p], a[:, :, q]
            out_r[:, :, axis_index] = a[:, :, axis_index]
            np.multiply(col_p, c, out=out_r[:, :, p])
            out_r[:, :, p] += col_q * s
            np.multiply(col_q, c, out=out_r[:, :, q])
            out_r[:, :, q] -= col_p * s
        elif kind == KIND_REVOLUTE:
            k = model._cross[j]
            theta = values[:, j]
            b = (a.reshape(n * 3, 3) @ k).reshape(n, 3, 3)
            np.multiply(b, np.sin(theta)[:, None, None], out=out_r)
            out_r += a
            np.multiply((b.reshape(n * 3, 3) @ k).reshape(n, 3, 3),
                        (1.0 - np.cos(theta))[:, None, None], out=scratch)
            out_r += scratch
        else:
            out_r[...] = a
            if kind == KIND_PRISMATIC:
                out_t += values[:, j][:, None] * (a.reshape(n * 3, 3) @ table.axis[j]).reshape(n, 3)


def batch_link_matrices(model: KinematicModel, q: npt.ArrayLike) -> FloatArray:
    """``(N, L, 4, 4)`` T_root_link for ``N`` configurations ``(N, nv)``; see :func:`batch_link_poses`."""
    rotations, translations = batch_link_poses(model, q)
    out = np.zeros((rotations.shape[1], rotations.shape[0], 4, 4))
    out[:, :, :3, :3] = rotations.transpose(1, 0, 2, 3)
    out[:, :, :3, 3] = translations.transpose(1, 0, 2)
    out[:, :, 3, 3] = 1.0
    return out
