"""Property tests of the transform algebra and rotation conversions (hypothesis)."""

from __future__ import annotations

import math

import numpy as np
from handfk import _rot_x, _rot_y, _rot_z
from hypothesis import given, settings
from hypothesis import strategies as st
from pytransform3d import rotations as pr

from robotmodel.spatial import (
    Transform,
    matrix_to_quat,
    matrix_to_rpy,
    quat_to_matrix,
    rpy_to_matrix,
    rpy_to_quat,
    slerp,
)
from robotmodel.tf._math import canonical_quat, compose, inverse, lerp_slerp

angle = st.floats(-math.pi, math.pi, allow_nan=False)
coord = st.floats(-100, 100, allow_nan=False)
quat = st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 4).filter(lambda q: sum(v * v for v in q) > 1e-3)


def _unit(q):
    n = math.sqrt(sum(v * v for v in q))
    return tuple(v / n for v in q)


def _pose(xyz, q):
    return (*xyz, *_unit(q))


def _mat(p):
    m = np.eye(4)
    m[:3, :3] = quat_to_matrix(p[3:])
    m[:3, 3] = p[:3]
    return m


@given(angle, st.floats(-1.5, 1.5), angle)
def test_rpy_is_fixed_axis_xyz(r, p, y) -> None:
    expected = _rot_z(y) @ _rot_y(p) @ _rot_x(r)  # URDF: R = Rz(yaw) Ry(pitch) Rx(roll)
    np.testing.assert_allclose(rpy_to_matrix([r, p, y]), expected, atol=1e-12)
    np.testing.assert_allclose(quat_to_matrix(rpy_to_quat([r, p, y])), expected, atol=1e-12)
    np.testing.assert_allclose(matrix_to_rpy(expected), [r, p, y], atol=1e-9)


@given(quat)
def test_quaternion_matrix_round_trip_against_pytransform3d(q) -> None:
    x, y, z, w = _unit(q)
    ours = quat_to_matrix([x, y, z, w])
    np.testing.assert_allclose(ours, pr.matrix_from_quaternion([w, x, y, z]), atol=1e-12)  # pytransform3d is wxyz
    back = matrix_to_quat(ours)
    assert abs(abs(np.dot(back, [x, y, z, w])) - 1.0) < 1e-12


@given(st.tuples(coord, coord, coord), quat, st.tuples(coord, coord, coord), quat)
def test_compose_and_inverse_match_matrices(t1, q1, t2, q2) -> None:
    a, b = _pose(t1, q1), _pose(t2, q2)
    np.testing.assert_allclose(_mat(compose(a, b)), _mat(a) @ _mat(b), atol=1e-9)
    np.testing.assert_allclose(_mat(inverse(a)), np.linalg.inv(_mat(a)), atol=1e-9)
    np.testing.assert_allclose(_mat(compose(a, inverse(a))), np.eye(4), atol=1e-9)
    ta, tb = Transform(t1, _unit(q1)), Transform(t2, _unit(q2))
    np.testing.assert_allclose((ta @ tb).matrix(), _mat(a) @ _mat(b), atol=1e-9)
    np.testing.assert_allclose(ta.inverse().matrix(), np.linalg.inv(_mat(a)), atol=1e-9)


@settings(max_examples=200)
@given(st.tuples(coord, coord, coord), quat, st.tuples(coord, coord, coord), quat, st.floats(0, 1))
def test_interpolation_endpoints_and_geodesic(t1, q1, t2, q2, r) -> None:
    a, b = _pose(t1, q1), _pose(t2, q2)
    np.testing.assert_allclose(_mat(lerp_slerp(a, b, 0.0)), _mat(a), atol=1e-9)
    # tf2 returns q0 when acos rounds the angle to exactly 0 (quaternions 1e-9 apart): allow that.
    np.testing.assert_allclose(_mat(lerp_slerp(a, b, 1.0)), _mat(b), atol=1e-8)
    mid = lerp_slerp(a, b, r)
    np.testing.assert_allclose(mid[:3], np.array(t1) * (1 - r) + np.array(t2) * r, atol=1e-9)
    # SLERP moves at constant angular speed along the shortest arc.
    qa, qb, qm = np.array(a[3:]), np.array(b[3:]), np.array(mid[3:])
    total = 2 * math.acos(min(1.0, abs(float(qa @ qb))))
    part = 2 * math.acos(min(1.0, abs(float(qa @ qm)) / np.linalg.norm(qm)))
    assert abs(part - r * total) < 1e-6
    np.testing.assert_allclose(np.abs(slerp(qa, qb, r) @ qm) / np.linalg.norm(qm), 1.0, atol=1e-9)


@given(quat)
def test_canonical_quaternion_is_the_same_rotation(q) -> None:
    c = canonical_quat(*q)
    assert abs(math.sqrt(sum(v * v for v in c)) - 1.0) < 1e-12
    np.testing.assert_allclose(quat_to_matrix(c), quat_to_matrix(_unit(q)), atol=1e-12)
