"""4x4 homogeneous matrices and vectors as ROS's transformations module builds them."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.spatial import FloatArray, matrix_to_quat, quat_to_matrix

__all__ = [
    "concatenate_matrices",
    "identity_matrix",
    "inverse_matrix",
    "is_same_transform",
    "random_vector",
    "rotation_from_matrix",
    "rotation_matrix",
    "scale_matrix",
    "translation_from_matrix",
    "translation_matrix",
    "unit_vector",
    "vector_norm",
]


def identity_matrix() -> FloatArray:
    """The 4x4 identity."""
    return np.eye(4)


def translation_matrix(direction: npt.ArrayLike) -> FloatArray:
    """4x4 matrix translating by ``direction`` (its first three elements)."""
    m = np.eye(4)
    m[:3, 3] = np.asarray(direction, dtype=np.float64)[:3]
    return m


def translation_from_matrix(matrix: npt.ArrayLike) -> FloatArray:
    """The translation part of a 4x4 matrix."""
    return np.array(np.asarray(matrix, dtype=np.float64)[:3, 3])


def rotation_matrix(angle: float, direction: npt.ArrayLike, point: npt.ArrayLike | None = None) -> FloatArray:
    """4x4 matrix rotating by ``angle`` about the axis along ``direction`` through ``point`` (default origin)."""
    axis = unit_vector(np.asarray(direction, dtype=np.float64)[:3])
    q = np.empty(4)
    q[:3] = axis * math.sin(angle / 2.0)
    q[3] = math.cos(angle / 2.0)
    m = np.eye(4)
    m[:3, :3] = quat_to_matrix(q)
    if point is not None:
        p = np.asarray(point, dtype=np.float64)[:3]
        m[:3, 3] = p - m[:3, :3] @ p
    return m


def rotation_from_matrix(matrix: npt.ArrayLike) -> tuple[float, FloatArray, FloatArray]:
    """``(angle, direction, point)`` of a rotation matrix; ``point`` is the axis point nearest the origin.

    The angle is in [0, pi] with the direction chosen to match; a matrix whose 3x3 part is
    not a rotation raises ValueError.
    """
    m = np.asarray(matrix, dtype=np.float64)
    r = m[:3, :3]
    if not np.allclose(r @ r.T, np.eye(3), atol=1e-8) or np.linalg.det(r) <= 0:
        raise ValueError("no rotation: the 3x3 part is not orthonormal with determinant 1")
    q = matrix_to_quat(r)
    s = float(np.linalg.norm(q[:3]))
    angle = 2.0 * math.atan2(s, float(q[3]))
    direction = q[:3] / s if s > 0 else np.array([0.0, 0.0, 1.0])
    t = m[:3, 3] if m.shape[0] >= 4 and m.shape[1] >= 4 else np.zeros(3)
    # Points on the axis satisfy (I - R) p = t; least squares picks the one nearest the origin.
    point = np.linalg.lstsq(np.eye(3) - r, t, rcond=None)[0]
    return angle, np.array(direction, dtype=np.float64), np.asarray(point, dtype=np.float64)


def scale_matrix(factor: float, origin: npt.ArrayLike | None = None,
                 direction: npt.ArrayLike | None = None) -> FloatArray:
    """4x4 matrix scaling by ``factor`` about ``origin``, uniformly or along ``direction`` only."""
    m = np.eye(4)
    if direction is None:
        m[:3, :3] *= factor
        if origin is not None:
            m[:3, 3] = (1.0 - factor) * np.asarray(origin, dtype=np.float64)[:3]
        return m
    d = unit_vector(np.asarray(direction, dtype=np.float64)[:3])
    m[:3, :3] -= (1.0 - factor) * np.outer(d, d)
    if origin is not None:
        o = np.asarray(origin, dtype=np.float64)[:3]
        m[:3, 3] = (1.0 - factor) * float(np.dot(o, d)) * d
    return m


def inverse_matrix(matrix: npt.ArrayLike) -> FloatArray:
    """The inverse of a square matrix."""
    return np.asarray(np.linalg.inv(np.asarray(matrix, dtype=np.float64)), dtype=np.float64)


def concatenate_matrices(*matrices: npt.ArrayLike) -> FloatArray:
    """The product ``M0 · M1 · ...`` (the identity for none)."""
    m = np.eye(4)
    for each in matrices:
        m = m @ np.asarray(each, dtype=np.float64)
    return m


def is_same_transform(matrix0: npt.ArrayLike, matrix1: npt.ArrayLike) -> bool:
    """Whether two homogeneous matrices are the same transform (each divided by its [3, 3] first)."""
    a = np.asarray(matrix0, dtype=np.float64)
    b = np.asarray(matrix1, dtype=np.float64)
    return bool(np.allclose(a / a[3, 3], b / b[3, 3]))


def vector_norm(data: npt.ArrayLike, axis: int | None = None, out: FloatArray | None = None) -> Any:
    """Euclidean length of ``data`` (along ``axis``); with ``out``, written there and None returned."""
    a = np.asarray(data, dtype=np.float64)
    if out is not None:
        np.sqrt(np.sum(a * a, axis=axis), out=out)
        return None
    if a.ndim == 1:
        return math.sqrt(float(np.dot(a, a)))
    return np.atleast_1d(np.sqrt(np.sum(a * a, axis=axis)))


def unit_vector(data: npt.ArrayLike, axis: int | None = None, out: FloatArray | None = None) -> Any:
    """``data`` divided by its Euclidean length (along ``axis``); with ``out``, written there."""
    a = np.array(data, dtype=np.float64)
    if a.ndim == 1 and axis is None:
        result: FloatArray = a / math.sqrt(float(np.dot(a, a))) if a.size else a
    else:
        norm = np.sqrt(np.sum(a * a, axis=axis, keepdims=True))
        result = a / norm
    if out is not None:
        out[...] = result
        return None
    return result


def random_vector(size: int | tuple[int, ...]) -> FloatArray:
    """Uniform random numbers in [0, 1) of the given shape."""
    return np.random.default_rng().random(size)
