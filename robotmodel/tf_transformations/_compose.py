"""Building a 4x4 matrix from scale, shear, angles, translation and perspective, and taking one apart.

The order is ROS's transformations module's: M = T · P · R · Z · S, where S scales along
x, y, z, Z is the shear (x by y, x by z, y by z), R the ``'sxyz'`` Euler rotation, P the
perspective row and T the translation. Taking apart is a QR factorization of the 3x3
part: R is its orthonormal factor (diagonal signs fixed so the scales come out positive,
all negated for a mirror), S and Z its upper-triangular factor.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from robotmodel.spatial import FloatArray
from robotmodel.tf_transformations._euler import euler_from_matrix, euler_matrix

__all__ = ["compose_matrix", "decompose_matrix"]

_EPS = float(np.finfo(float).eps) * 4.0


def compose_matrix(scale: npt.ArrayLike | None = None, shear: npt.ArrayLike | None = None,
                   angles: npt.ArrayLike | None = None, translate: npt.ArrayLike | None = None,
                   perspective: npt.ArrayLike | None = None) -> FloatArray:
    """M = T · P · R · Z · S from the parts given (each optional)."""
    m = np.eye(4)
    if perspective is not None:
        p = np.eye(4)
        p[3, :] = np.asarray(perspective, dtype=np.float64)[:4]
        m = m @ p
    if angles is not None:
        a = np.asarray(angles, dtype=np.float64)
        m = m @ euler_matrix(a[0], a[1], a[2], "sxyz")
    if shear is not None:
        z = np.eye(4)
        sh = np.asarray(shear, dtype=np.float64)
        z[0, 1], z[0, 2], z[1, 2] = sh[0], sh[1], sh[2]
        m = m @ z
    if scale is not None:
        s = np.eye(4)
        s[:3, :3] = np.diag(np.asarray(scale, dtype=np.float64)[:3])
        m = m @ s
    if translate is not None:
        t = np.eye(4)
        t[:3, 3] = np.asarray(translate, dtype=np.float64)[:3]
        m = t @ m
    m /= m[3, 3]
    return m


def decompose_matrix(matrix: npt.ArrayLike) -> tuple[FloatArray, FloatArray, tuple[float, float, float],
                                                     FloatArray, FloatArray]:
    """``(scale, shear, angles, translate, perspective)`` of an affine 4x4 matrix.

    ValueError for a singular matrix or one with a perspective part (a bottom row other
    than (0, 0, 0, w)).
    """
    m = np.array(matrix, dtype=np.float64)
    if abs(m[3, 3]) < _EPS:
        raise ValueError("M[3, 3] is zero")
    m /= m[3, 3]
    if np.any(np.abs(m[3, :3]) > _EPS):
        raise ValueError("matrix has a perspective part, which is not decomposed here")
    a = m[:3, :3]
    if abs(np.linalg.det(a)) < _EPS:
        raise ValueError("matrix is singular")
    q, u = np.linalg.qr(a)
    signs = np.where(np.diag(u) < 0, -1.0, 1.0)
    q, u = q * signs, (u.T * signs).T
    if np.linalg.det(q) < 0:  # a mirror: all three scales negative, a proper rotation left
        q, u = -q, -u
    scale = np.diag(u).copy()
    shear = np.array([u[0, 1] / scale[1], u[0, 2] / scale[2], u[1, 2] / scale[2]])
    angles = euler_from_matrix(q, "sxyz")
    return scale, shear, angles, m[:3, 3].copy(), np.array([0.0, 0.0, 0.0, 1.0])
