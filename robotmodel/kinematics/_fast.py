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

import math
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
    columns: npt.NDArray[np.intp]  # 0 .. J-1
    # t0 itself (read-only) when t0 + θ·slide_axis is t0 bit for bit for every finite θ:
    # no prismatic row, and no -0.0 in t0 (-0.0 + 0.0 is +0.0).
    fixed_t: FloatArray | None

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
        t0 = table.origin_translation[idx]
        fixed_t = None
        if not (kinds == KIND_PRISMATIC).any() and not (np.signbit(t0) & (t0 == 0.0)).any():
            fixed_t = np.array(t0, dtype=np.float64, order="C")
            fixed_t.setflags(write=False)
        return cls(
            rows=idx.astype(np.float64),
            half_i=np.where(kinds == KIND_REVOLUTE, 0.5j, 0.0j),
            cos_sin=np.stack([q0, ps], axis=1),
            t0=t0,
            slide_axis=np.where((kinds == KIND_PRISMATIC)[:, None], r0_axis, 0.0),
            columns=np.arange(len(rows)),
            fixed_t=fixed_t,
        )

    def evaluate(self, values: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Translations ``(J, 3)`` and quaternions ``(J, 4)`` for joint values ``(J,)``."""
        # exp(iθ/2) holds (cos, sin) side by side in memory: one call gives both.
        cos_sin = np.exp(values * self.half_i).view(np.float64).reshape(-1, 1, 2)
        rotations = (cos_sin @ self.cos_sin)[:, 0, :]
        translations = self.t0 + values[:, None] * self.slide_axis
        return translations, rotations

    def evaluate_canonical(self, values: FloatArray) -> tuple[FloatArray, FloatArray]:
        """As :meth:`evaluate`, each quaternion in tf2's canonical form: robot_state_publisher's cycle.

        The same numbers as :meth:`evaluate` followed by :func:`robotmodel.spatial.quats_canonical`,
        bit for bit (the same operations in the same order; tests hold it to that), in half the
        array operations, which is what this costs for tens of joints: the quaternions are
        read component-major, where each step is one operation on all joints. Without
        prismatic joints the translations are the origins (a read-only array).
        """
        cos_sin = np.exp(values * self.half_i).view(np.float64).reshape(-1, 1, 2)
        # The same product as evaluate's (whose rounding is the matrix product's), read column by column.
        quats = (cos_sin @ self.cos_sin)[:, 0, :].T
        squares = quats * quats
        n2 = _add(squares, 0)  # x² + y² + z² + w², added in that order as tf2 adds them
        s = 2.0 / n2
        xyz = quats[:3]
        products = xyz * s
        products *= xyz
        # tf2's diagonal: 1 - (yy + zz), 1 - (xx + zz), 1 - (xx + yy); the 0/1 matrix adds exactly those two.
        diagonal = 1.0 - _PAIRS @ products
        # tf2's nested comparisons pick the largest diagonal element, the first of equals: argmax.
        lead = quats[diagonal.argmax(axis=0), self.columns]
        # A positive trace (summed in tf2's order) leads with w.
        lead = np.where(_add(diagonal, 0) > 0.0, quats[3], lead)
        quats *= np.copysign(1.0 / np.sqrt(n2), lead)
        # s is ≥ 0 or NaN, and n2 ≤ 16 (|Q| = |P| = 1): the sum is finite when every norm is usable.
        finite = math.isfinite(_add(s))
        if not finite:  # a zero or NaN norm, or 2/n2 overflowing: NaN, as tf2's round trip gives
            quats[:, ~((n2 > 0.0) & np.isfinite(n2) & np.isfinite(s))] = np.nan
        if finite and self.fixed_t is not None:
            return self.fixed_t, quats.T
        return self.t0 + values[:, None] * self.slide_axis, quats.T


_add = np.add.reduce  # ndarray.sum without its Python wrapper (a cost on a few-microsecond cycle)
# Row i sums the two squared components in the rotation matrix's i-th diagonal element.
_PAIRS = np.array([[0.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 0.0]])
