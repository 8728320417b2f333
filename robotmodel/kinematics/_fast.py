"""Precomputed per-joint constants that make the publishing cycle and batch FK cheap.

Per-joint transform T_parent_child(q) = T_origin · M(q):

- As quaternions, rot(q) = q_origin ⊗ (axis·sin(θ/2), cos(θ/2)), which is linear in
  (sin, cos): rot = P·sin(θ/2) + Q·cos(θ/2) with P, Q fixed per joint. Translation is
  t_origin + d·(R_origin·axis) for prismatic joints.
- As matrices, R_parent·R_origin·Rot(axis, θ) = A + sin θ·(A·K) + (1 - cos θ)·(A·K²) with
  A = R_parent·R_origin and K the axis' cross-product matrix: only products with constant
  3x3 matrices, which BLAS does for N configurations at once.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from robotmodel.kinematics._joints import KIND_PRISMATIC, KIND_REVOLUTE, JointTable
from robotmodel.spatial import FloatArray, matrix_to_quat, quat_multiply

__all__ = ["CycleTables", "cross_matrix"]


def cross_matrix(axis: FloatArray) -> FloatArray:
    """The 3x3 matrix K with K·v = axis × v."""
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


@dataclass(frozen=True)
class CycleTables:
    """Constants for the joints in ``rows`` (indices into the joint table)."""

    rows: FloatArray
    half_i: npt.NDArray[np.complex128]  # 0.5j for revolute rows, 0 otherwise
    cos_sin: FloatArray  # (J, 2, 4): rows Q then P, weighted by cos(θ/2), sin(θ/2)
    t0: FloatArray  # (J, 3)
    slide_axis: FloatArray  # (J, 3): R_origin·axis on prismatic rows, 0 otherwise

    @classmethod
    def build(cls, table: JointTable, rows: list[int]) -> CycleTables:
        """Precompute for the given joint rows."""
        idx = np.asarray(rows, dtype=np.intp)
        kinds = table.kinds[idx]
        q0 = matrix_to_quat(table.origin_rotation[idx]).reshape(-1, 4)
        axis = table.axis[idx]
        # q0 ⊗ (axis·sin, cos) = sin·(q0 ⊗ (axis, 0)) + cos·q0: spatial's product, once per joint.
        ps = quat_multiply(q0, np.concatenate([axis, np.zeros((len(rows), 1))], axis=1)).reshape(-1, 4)
        r0_axis = np.einsum("jab,jb->ja", table.origin_rotation[idx], axis).reshape(-1, 3)
        return cls(
            rows=idx.astype(np.float64),
            half_i=np.where(kinds == KIND_REVOLUTE, 0.5j, 0.0j),
            cos_sin=np.stack([q0, ps], axis=1),
            t0=table.origin_translation[idx],
            slide_axis=np.where((kinds == KIND_PRISMATIC)[:, None], r0_axis, 0.0),
        )

    def evaluate(self, values: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Translations ``(J, 3)`` and quaternions ``(J, 4)`` for joint values ``(J,)``."""
        # exp(iθ/2) holds (cos, sin) side by side in memory: one call gives both.
        cos_sin = np.exp(values * self.half_i).view(np.float64).reshape(-1, 1, 2)
        rotations = (cos_sin @ self.cos_sin)[:, 0, :]
        translations = self.t0 + values[:, None] * self.slide_axis
        return translations, rotations
