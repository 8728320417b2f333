"""Property tests of the pose kernels (the exact functions production calls) and rotation conversions."""

from __future__ import annotations

import math

import numpy as np
import pytest
from handfk import _rot_x, _rot_y, _rot_z
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from pytransform3d import rotations as pr

from robotmodel.spatial import (
    Transform,
    matrix_to_quat,
    matrix_to_rpy,
    pose_compose,
    pose_interpolate,
    pose_inverse,
    poses_compose,
    poses_interpolate,
    poses_inverse,
    quat_canonical,
    quat_multiply,
    quat_to_matrix,
    quats_canonical,
    rpy_to_matrix,
    rpy_to_quat,
    slerp,
)

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


xyz = st.tuples(coord, coord, coord)


@given(xyz, quat, xyz, quat)
def test_compose_and_inverse_match_matrices(t1, q1, t2, q2) -> None:
    a, b = _pose(t1, q1), _pose(t2, q2)
    np.testing.assert_allclose(_mat(pose_compose(a, b)), _mat(a) @ _mat(b), atol=1e-9)
    np.testing.assert_allclose(_mat(pose_inverse(a)), np.linalg.inv(_mat(a)), atol=1e-9)
    np.testing.assert_allclose(_mat(pose_compose(a, pose_inverse(a))), np.eye(4), atol=1e-9)
    ta, tb = Transform(t1, _unit(q1)), Transform(t2, _unit(q2))
    np.testing.assert_allclose((ta @ tb).matrix(), _mat(a) @ _mat(b), atol=1e-9)
    np.testing.assert_allclose(ta.inverse().matrix(), np.linalg.inv(_mat(a)), atol=1e-9)
    # tf2's inverse is the conjugate, not q^-1 scaled by the norm.
    assert pose_inverse(a)[3:] == (-a[3], -a[4], -a[5], a[6])


@given(quat, quat)
def test_quaternion_product_is_hamilton_as_pytransform3d(q1, q2) -> None:
    a, b = _unit(q1), _unit(q2)
    theirs = pr.concatenate_quaternions([a[3], *a[:3]], [b[3], *b[:3]])  # wxyz, a ⊗ b
    np.testing.assert_allclose(quat_multiply(a, b), [*theirs[1:], theirs[0]], atol=1e-12)


@settings(max_examples=200)
@given(xyz, quat, xyz, quat, st.floats(0, 1))
def test_interpolation_is_lerp_and_shortest_slerp(t1, q1, t2, q2, r) -> None:
    a, b = _pose(t1, q1), _pose(t2, q2)
    np.testing.assert_allclose(_mat(pose_interpolate(a, b, 0.0)), _mat(a), atol=1e-9)
    # tf2 returns q0 when acos rounds the angle to exactly 0 (quaternions 1e-9 apart): allow that.
    np.testing.assert_allclose(_mat(pose_interpolate(a, b, 1.0)), _mat(b), atol=1e-8)
    mid = pose_interpolate(a, b, r)
    np.testing.assert_allclose(mid[:3], np.array(t1) * (1 - r) + np.array(t2) * r, atol=1e-9)
    # pytransform3d's SLERP on the shortest path is the same rotation (unless "shortest" is ambiguous: 360° apart).
    qa, qb = [a[6], *a[3:6]], [b[6], *b[3:6]]
    assume(abs(float(np.dot(qa, qb))) > 1e-6)
    theirs = pr.quaternion_slerp(qa, qb, r, shortest_path=True)
    np.testing.assert_allclose(_mat(mid)[:3, :3], pr.matrix_from_quaternion(theirs), atol=1e-7)
    np.testing.assert_allclose(slerp(a[3:], b[3:], r), mid[3:], atol=1e-15)


def _tf2_sign_rule(c) -> bool:
    """tf2's getRotation: w > 0 when the matrix trace is positive, else the largest diagonal's component > 0."""
    m = quat_to_matrix(c)
    if np.trace(m) > 1e-9:
        return c[3] > 0
    d = np.diag(m)
    if np.trace(m) > -1e-9 or np.sort(d)[-1] - np.sort(d)[-2] < 1e-9:
        return True  # on a tie the branch depends on rounding: only the rotation is pinned
    return c[int(np.argmax(d))] > 0


@given(quat)
def test_canonical_quaternion_is_the_same_rotation_with_tf2s_sign(q) -> None:
    c = quat_canonical(q)
    assert abs(math.sqrt(sum(v * v for v in c)) - 1.0) < 1e-12
    np.testing.assert_allclose(quat_to_matrix(c), quat_to_matrix(_unit(q)), atol=1e-12)
    assert _tf2_sign_rule(c)
    assert quat_canonical(tuple(-v for v in q)) == pytest.approx(c, abs=1e-12)


def _tf2_round_trip(q):
    """tf2's Matrix3x3::setRotation then getRotation, transcribed from the notes (Appendix A.3)."""
    x, y, z, w = q
    s = 2.0 / (x * x + y * y + z * z + w * w)
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    m = [[1.0 - (yy + zz), xy - wz, xz + wy], [xy + wz, 1.0 - (xx + zz), yz - wx], [xz - wy, yz + wx, 1.0 - (xx + yy)]]
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0.0:
        root = math.sqrt(trace + 1.0)
        half = 0.5 / root
        return ((m[2][1] - m[1][2]) * half, (m[0][2] - m[2][0]) * half, (m[1][0] - m[0][1]) * half, root * 0.5)
    i = (2 if m[1][1] < m[2][2] else 1) if m[0][0] < m[1][1] else (2 if m[0][0] < m[2][2] else 0)
    j, k = (i + 1) % 3, (i + 2) % 3
    root = math.sqrt(m[i][i] - m[j][j] - m[k][k] + 1.0)
    out = [0.0] * 4
    out[i] = root * 0.5
    half = 0.5 / root
    out[3] = (m[k][j] - m[j][k]) * half
    out[j] = (m[j][i] + m[i][j]) * half
    out[k] = (m[k][i] + m[i][k]) * half
    return tuple(out)


@settings(max_examples=300)
@given(quat)
def test_canonical_quaternion_equals_tf2s_matrix_round_trip(q) -> None:
    expected = _tf2_round_trip(q)
    assert quat_canonical(q) == pytest.approx(expected, abs=1e-12)
    np.testing.assert_allclose(quats_canonical([q])[0], expected, atol=1e-12)


def test_canonical_quaternion_examples_from_tf2() -> None:
    # 270° about z comes back as -90°; -135° about z keeps w < 0 (Appendix A.3 of the tf2 notes).
    s = math.sqrt(0.5)
    assert quat_canonical((0.0, 0.0, s, -s)) == pytest.approx((0.0, 0.0, -s, s))  # sin, cos of 135°
    c = quat_canonical((0.0, 0.0, -math.sin(3 * math.pi / 8), math.cos(3 * math.pi / 8)))
    assert c == pytest.approx((0.0, 0.0, 0.9238795, -0.3826834), abs=1e-7)
    assert quat_canonical((0.0, 0.0, 0.0, -2.0)) == (0.0, 0.0, 0.0, 1.0)
    assert all(math.isnan(v) for v in quat_canonical((0.0, 0.0, 0.0, 0.0)))
    # |q|² so small that tf2's 2/|q|² overflows: its matrix holds inf - inf, the result is NaN.
    assert all(math.isnan(v) for v in quat_canonical((1e-160, 0.0, 0.0, 0.0)))
    assert quat_canonical((1e-150, 0.0, 0.0, 0.0)) == (1.0, 0.0, 0.0, 0.0)
    assert np.isnan(quats_canonical([[0.0, 0.0, 0.0, 0.0], [math.inf, 0, 0, 1]])).all()


poses = st.lists(st.tuples(xyz, quat), min_size=1, max_size=20)


@given(poses, poses, st.lists(st.floats(0, 1), min_size=20, max_size=20))
def test_batched_kernels_equal_the_scalar_ones(p1, p2, rs) -> None:
    n = min(len(p1), len(p2))
    a = [_pose(*p) for p in p1[:n]]
    b = [_pose(*p) for p in p2[:n]]
    A, B, R = np.array(a), np.array(b), np.array(rs[:n])
    np.testing.assert_allclose(poses_compose(A, B), [pose_compose(x, y) for x, y in zip(a, b, strict=True)], atol=1e-12)
    np.testing.assert_allclose(poses_inverse(A), [pose_inverse(x) for x in a], atol=1e-12)
    np.testing.assert_allclose(poses_interpolate(A, B, R), [pose_interpolate(x, y, r) for x, y, r in zip(a, b, R, strict=True)],
                               atol=1e-12)
    raw = np.array([q for _, q in p1[:n]])
    np.testing.assert_allclose(quats_canonical(raw), [quat_canonical(tuple(q)) for q in raw], atol=1e-12)
    # Broadcasting one pose against many.
    np.testing.assert_allclose(poses_compose(A[0], B), [pose_compose(a[0], y) for y in b], atol=1e-12)


def test_batched_interpolation_returns_the_first_rotation_at_zero_angle() -> None:
    a = np.array([[0, 0, 0, 0, 0, 0, 1.0]])
    out = poses_interpolate(a, np.array([[2, 0, 0, 0, 0, 0, 1.0]]), [0.25])
    np.testing.assert_array_equal(out, [[0.5, 0, 0, 0, 0, 0, 1.0]])
    assert pose_interpolate(tuple(a[0]), (2, 0, 0, 0, 0, 0, 1.0), 0.25) == (0.5, 0, 0, 0, 0, 0, 1.0)


@given(quat, st.lists(st.floats(1e-9, 1e-2), min_size=1, max_size=10), st.floats(0, 1))
def test_batched_interpolation_is_exact_for_the_small_steps_of_real_streams(q, angles, r) -> None:
    # Consecutive TF samples differ by small rotations, where SLERP's sine ratios matter most.
    a = _pose((0.0, 0.0, 0.0), q)
    qa = np.array(a[3:])
    rows_a, rows_b = [], []
    for k, angle in enumerate(angles):
        axis = np.array([1.0, -2.0, 0.5 + k])
        axis /= np.linalg.norm(axis)
        step = np.array([*(math.sin(angle / 2) * axis), math.cos(angle / 2)])
        rows_a.append(a)
        rows_b.append((1.0, 2.0, 3.0, *quat_multiply(qa, step)))
    batched = poses_interpolate(np.array(rows_a), np.array(rows_b), np.full(len(angles), r))
    scalar = [pose_interpolate(x, tuple(y), r) for x, y in zip(rows_a, rows_b, strict=True)]
    np.testing.assert_allclose(batched, scalar, rtol=1e-13, atol=1e-15)
