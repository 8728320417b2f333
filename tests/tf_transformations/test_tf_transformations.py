"""robotmodel.tf_transformations against pytransform3d and hand-derived values.

Expected values come from pytransform3d (an independent implementation of all 24 Euler
conventions), from products of single-axis rotations written out here, and from the
numbers ROS's transformations module documents for itself.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import pytransform3d.rotations as pr

from robotmodel import tf_transformations as tft

AXIS = {"x": 0, "y": 1, "z": 2}
RNG = np.random.default_rng(20261123)


def _rot(axis: int, angle: float) -> np.ndarray:
    e = np.zeros(3)
    e[axis] = 1.0
    return pr.matrix_from_axis_angle([*e, angle])


def test_there_are_24_sequences_with_ros_tuple_codes() -> None:
    assert len(tft.AXES) == 24
    # A few codes as ROS's module documents them: (inner axis, parity, repetition, frame).
    assert tft.AXES["sxyz"] == (0, 0, 0, 0)
    assert tft.AXES["rzyx"] == (0, 0, 0, 1)
    assert tft.AXES["szxz"] == (2, 0, 1, 0)
    assert tft.AXES["rxyz"] == (2, 1, 0, 1)


@pytest.mark.parametrize("axes", sorted(tft.AXES))
def test_euler_matrix_matches_pytransform3d(axes: str) -> None:
    i, j, k = (AXIS[c] for c in axes[1:])
    for _ in range(20):
        angles = (RNG.random(3) - 0.5) * 4 * math.pi
        expected = pr.matrix_from_euler(angles, i, j, k, extrinsic=axes[0] == "s")
        got = tft.euler_matrix(*angles, axes=axes)
        np.testing.assert_allclose(got[:3, :3], expected, atol=1e-12)
        np.testing.assert_allclose(got[3], [0, 0, 0, 1])
        np.testing.assert_allclose(got[:3, 3], 0)
        # The tuple encoding means the same sequence.
        np.testing.assert_allclose(tft.euler_matrix(*angles, axes=tft.AXES[axes]), got)


@pytest.mark.parametrize("axes", sorted(tft.AXES))
def test_quaternion_from_euler_is_the_product_of_axis_turns(axes: str) -> None:
    i, j, k = (AXIS[c] for c in axes[1:])
    for _ in range(20):
        a = (RNG.random(3) - 0.5) * 4 * math.pi
        q = tft.quaternion_from_euler(*a, axes=axes)
        wxyz = pr.quaternion_from_euler(a, i, j, k, extrinsic=axes[0] == "s")
        # Same rotation; same sign too, since both multiply the single-axis quaternions out.
        np.testing.assert_allclose(q, [*wxyz[1:], wxyz[0]], atol=1e-12)
        np.testing.assert_allclose(tft.quaternion_matrix(q), tft.euler_matrix(*a, axes=axes), atol=1e-12)


@pytest.mark.parametrize("axes", sorted(tft.AXES))
def test_euler_from_matrix_round_trips_and_matches_pytransform3d(axes: str) -> None:
    i, j, k = (AXIS[c] for c in axes[1:])
    proper = axes[1] == axes[3]
    for _ in range(50):
        a = (RNG.random(3) - 0.5) * 4 * math.pi
        m = tft.euler_matrix(*a, axes=axes)
        got = tft.euler_from_matrix(m, axes)
        np.testing.assert_allclose(tft.euler_matrix(*got, axes=axes), m, atol=1e-12)
        # ROS's ranges: [-pi/2, pi/2] for three axes; [0, pi] for a repeated one, negated
        # when the sequence's first two axes run against x -> y -> z.
        middle = got[1] if tft.AXES[axes][1] == 0 else -got[1]
        assert (0 <= middle <= math.pi) if proper else (-math.pi / 2 <= middle <= math.pi / 2)
        extrinsic = axes[0] == "s"
        np.testing.assert_allclose(pr.matrix_from_euler(got, i, j, k, extrinsic), m[:3, :3], atol=1e-12)
        if tft.AXES[axes][1] == 0:  # same range as pytransform3d's: the same angles
            expected = pr.euler_from_matrix(m[:3, :3], i, j, k, extrinsic)
            np.testing.assert_allclose(np.cos(got), np.cos(expected), atol=1e-9)
            np.testing.assert_allclose(np.sin(got), np.sin(expected), atol=1e-9)
        q = tft.quaternion_from_euler(*a, axes=axes)
        np.testing.assert_allclose(tft.euler_from_quaternion(q, axes), got, atol=1e-12)


def test_roll_pitch_yaw_by_hand() -> None:
    roll, pitch, yaw = 0.1, -0.4, 2.5
    # URDF / tf2 rpy: R = Rz(yaw) Ry(pitch) Rx(roll), written out from single-axis rotations.
    r = _rot(2, yaw) @ _rot(1, pitch) @ _rot(0, roll)
    np.testing.assert_allclose(tft.euler_matrix(roll, pitch, yaw)[:3, :3], r, atol=1e-15)
    np.testing.assert_allclose(tft.quaternion_from_euler(0, 0, yaw), [0, 0, math.sin(yaw / 2), math.cos(yaw / 2)])
    assert tft.euler_from_quaternion([0, 0, math.sin(yaw / 2), math.cos(yaw / 2)]) == pytest.approx((0, 0, yaw))
    # Rotating z-y-x with the angles reversed is the same rotation.
    np.testing.assert_allclose(tft.euler_matrix(yaw, pitch, roll, "rzyx"), tft.euler_matrix(roll, pitch, yaw))


def test_gimbal_lock_puts_the_turn_in_the_first_angle() -> None:
    m = tft.euler_matrix(0.3, math.pi / 2, 0.5)
    a, b, c = tft.euler_from_matrix(m)
    # At pitch +pi/2, Rz(c) Ry(pi/2) Rx(a) depends on a - c only: ROS's module returns c = 0.
    assert (a, b, c) == pytest.approx((0.3 - 0.5, math.pi / 2, 0.0))
    m = tft.euler_matrix(0.3, 0.0, 0.5, "sxyx")
    assert tft.euler_from_matrix(m, "sxyx") == pytest.approx((0.8, 0.0, 0.0))
    assert tft.euler_from_matrix(tft.euler_matrix(0.5, -math.pi / 2, 0.3, "rzyx"), "rzyx") == pytest.approx(
        (0.0, -math.pi / 2, 0.3 + 0.5))


def test_documented_values() -> None:
    # Values ROS's transformations module states in its own documentation.
    np.testing.assert_allclose(tft.quaternion_from_euler(1, 2, 3, "ryxz"), [0.310622, -0.718287, 0.444435, 0.435953],
                               atol=1e-6)
    assert np.sum(tft.euler_matrix(1, 2, 3, "syxz")[0]) == pytest.approx(-1.34786452)
    assert np.sum(tft.euler_matrix(1, 2, 3, (0, 1, 0, 1))[0]) == pytest.approx(-0.383436184)
    assert tft.euler_from_quaternion([0.06146124, 0, 0, 0.99810947]) == pytest.approx((0.123, 0, 0), abs=1e-7)
    np.testing.assert_allclose(tft.quaternion_about_axis(0.123, (1, 0, 0)), [0.06146124, 0, 0, 0.99810947], atol=1e-8)
    np.testing.assert_allclose(tft.quaternion_from_matrix(tft.rotation_matrix(0.123, (1, 2, 3))),
                               [0.0164262, 0.0328524, 0.0492786, 0.9981095], atol=1e-7)


def test_quaternion_algebra_by_hand() -> None:
    # Hamilton product written out: w = w1 w0 - v1.v0, v = w1 v0 + w0 v1 + v1 x v0.
    q1, q0 = np.array([1.0, -2, 3, 4]), np.array([-5.0, 6, 7, 8])
    v = q1[3] * q0[:3] + q0[3] * q1[:3] + np.cross(q1[:3], q0[:3])
    w = q1[3] * q0[3] - q1[:3] @ q0[:3]
    np.testing.assert_allclose(tft.quaternion_multiply(q1, q0), [*v, w])
    np.testing.assert_allclose(tft.quaternion_multiply(q1, q0), [-44, -14, 48, 28])
    np.testing.assert_allclose(tft.quaternion_conjugate(q1), [-1, 2, -3, 4])
    np.testing.assert_allclose(tft.quaternion_multiply(q1, tft.quaternion_inverse(q1)), [0, 0, 0, 1], atol=1e-15)
    # Rotating by q0 then q1 is the matrix product R(q1) R(q0).
    a, b = tft.random_quaternion(RNG.random(3)), tft.random_quaternion(RNG.random(3))
    np.testing.assert_allclose(tft.quaternion_matrix(tft.quaternion_multiply(a, b)),
                               tft.quaternion_matrix(a) @ tft.quaternion_matrix(b), atol=1e-12)
    assert np.linalg.norm(a) == pytest.approx(1.0)
    np.testing.assert_allclose(tft.quaternion_matrix([0, 0, 0, 0]), np.eye(4))


def test_slerp() -> None:
    q0 = tft.quaternion_about_axis(0.2, (0, 0, 1))
    q1 = tft.quaternion_about_axis(1.4, (0, 0, 1))
    np.testing.assert_allclose(tft.quaternion_slerp(q0, q1, 0.25), tft.quaternion_about_axis(0.5, (0, 0, 1)))
    np.testing.assert_allclose(tft.quaternion_slerp(q0, q1, 0.0), q0)
    np.testing.assert_allclose(tft.quaternion_slerp(q0, -q1, 0.5), tft.quaternion_about_axis(0.8, (0, 0, 1)))
    other = tft.quaternion_slerp(q0, -q1, 0.5, shortestpath=False)
    assert abs(float(np.dot(other, tft.quaternion_about_axis(0.8, (0, 0, 1))))) < 0.999


def test_matrices() -> None:
    v = np.array([0.3, -1.2, 2.0])
    np.testing.assert_allclose(tft.translation_from_matrix(tft.translation_matrix(v)), v)
    np.testing.assert_allclose(tft.identity_matrix(), np.eye(4))
    point = np.array([1.0, 2.0, 3.0])
    r = tft.rotation_matrix(math.pi / 2, (0, 0, 1), point)
    # A quarter turn about the vertical line through (1, 2): (2, 2, 0) goes to (1, 3, 0).
    np.testing.assert_allclose(r @ [2, 2, 0, 1], [1, 3, 0, 1], atol=1e-15)
    angle, direction, p = tft.rotation_from_matrix(r)
    assert tft.is_same_transform(tft.rotation_matrix(angle, direction, p), r)
    assert angle == pytest.approx(math.pi / 2)
    s = tft.scale_matrix(2.0, origin=(1, 1, 1))
    np.testing.assert_allclose(s @ [2, 1, 1, 1], [3, 1, 1, 1])
    s = tft.scale_matrix(0.0, direction=(1, 0, 0))
    np.testing.assert_allclose(s @ [5, 6, 7, 1], [0, 6, 7, 1])
    t = tft.concatenate_matrices(tft.translation_matrix(v), tft.euler_matrix(0.1, 0.2, 0.3))
    np.testing.assert_allclose(tft.inverse_matrix(t) @ t, np.eye(4), atol=1e-12)
    assert tft.vector_norm([3.0, 4.0]) == 5.0
    np.testing.assert_allclose(tft.unit_vector([3.0, 4.0]), [0.6, 0.8])
    assert tft.random_vector(3).shape == (3,)


def test_bad_axes() -> None:
    with pytest.raises(ValueError, match="unknown Euler axes 'sxxz'"):
        tft.euler_matrix(0, 0, 0, "sxxz")
    with pytest.raises(ValueError, match="tuple"):
        tft.euler_from_matrix(np.eye(4), (3, 0, 0, 0))


def test_public_surface() -> None:
    # The names ported code imports; each documented.
    assert set(tft.__all__) == {
        "AXES", "compose_matrix", "concatenate_matrices", "decompose_matrix", "euler_from_matrix", "euler_from_quaternion", "euler_matrix",
        "identity_matrix", "inverse_matrix", "is_same_transform", "quaternion_about_axis", "quaternion_conjugate",
        "quaternion_from_euler", "quaternion_from_matrix", "quaternion_inverse", "quaternion_matrix",
        "quaternion_multiply", "quaternion_slerp", "random_quaternion", "random_rotation_matrix", "random_vector",
        "rotation_from_matrix", "rotation_matrix", "scale_matrix", "translation_from_matrix", "translation_matrix",
        "unit_vector", "vector_norm"}
    for name in tft.__all__:
        if name != "AXES":
            assert getattr(tft, name).__doc__, name


def test_compose_and_decompose() -> None:
    scale, shear, angles, translate = [1.5, 0.7, 2.0], [0.2, -0.1, 0.3], [0.3, -0.6, 2.1], [1.0, -2.0, 0.5]
    m = tft.compose_matrix(scale, shear, angles, translate)
    # T · R · Z · S written out: Z shears x by y (0.2) and by z (-0.1), y by z (0.3).
    z = np.array([[1, 0.2, -0.1], [0, 1, 0.3], [0, 0, 1]])
    r = pr.matrix_from_euler(angles, 0, 1, 2, extrinsic=True)
    np.testing.assert_allclose(m[:3, :3], r @ z @ np.diag(scale), atol=1e-12)
    np.testing.assert_allclose(m[:3, 3], translate)
    got = tft.decompose_matrix(m)
    np.testing.assert_allclose(got[0], scale, atol=1e-12)
    np.testing.assert_allclose(got[1], shear, atol=1e-12)
    np.testing.assert_allclose(got[2], angles, atol=1e-12)
    np.testing.assert_allclose(got[3], translate, atol=1e-12)
    np.testing.assert_allclose(got[4], [0, 0, 0, 1])
    mirror = tft.compose_matrix([-1.0, -2.0, -3.0], None, angles)
    s, _, a, _, _ = tft.decompose_matrix(mirror)
    np.testing.assert_allclose(s, [-1, -2, -3], atol=1e-12)
    np.testing.assert_allclose(tft.compose_matrix(s, None, a), mirror, atol=1e-12)
    with pytest.raises(ValueError, match="perspective"):
        tft.decompose_matrix(tft.compose_matrix(perspective=[0.1, 0, 0, 1]))
