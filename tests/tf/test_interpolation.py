"""The buffer's interpolation itself, checked against matrices and pytransform3d's SLERP."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from pytransform3d import rotations as pr
from tfhelpers import SEC, make, msg_matrix

import robotmodel.spatial
from robotmodel.tf import Buffer, Time, _cache, _core, _vector

coord = st.floats(-50, 50, allow_nan=False)
quat = st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 4).filter(lambda q: sum(v * v for v in q) > 1e-2)


def _unit(q):
    n = math.sqrt(sum(v * v for v in q))
    return tuple(v / n for v in q)


def _expected(t0, q0, t1, q1, r) -> np.ndarray:
    a, b = _unit(q0), _unit(q1)
    slerped = pr.quaternion_slerp([a[3], *a[:3]], [b[3], *b[:3]], r, shortest_path=True)
    m = np.eye(4)
    m[:3, :3] = pr.matrix_from_quaternion(slerped)
    m[:3, 3] = np.array(t0) * (1 - r) + np.array(t1) * r
    return m


def test_production_calls_the_kernels_the_property_tests_check() -> None:
    assert _cache.pose_interpolate is robotmodel.spatial.pose_interpolate
    assert _core.pose_compose is robotmodel.spatial.pose_compose
    assert _core.quat_canonical is robotmodel.spatial.quat_canonical
    assert _vector.poses_interpolate is robotmodel.spatial.poses_interpolate
    assert _vector.quats_canonical is robotmodel.spatial.quats_canonical


@settings(max_examples=100, deadline=None)
@given(st.tuples(coord, coord, coord), quat, st.tuples(coord, coord, coord), quat,
       st.integers(1, 10 * SEC), st.integers(1, 5 * SEC), st.floats(0, 1))
def test_cache_interpolation_matches_lerp_and_slerp(t0, q0, t1, q1, s0, span, r) -> None:
    assume(abs(float(np.dot(_unit(q0), _unit(q1)))) > 1e-6)  # 360° apart: no unique shortest path
    buf = Buffer()
    for xyz, q, stamp in ((t0, q0, s0), (t1, q1, s0 + span)):
        msg = make("a", "b", xyz, quat=q)
        msg.header.stamp = Time(nanoseconds=stamp)
        buf.set_transform(msg, "me")
    t = s0 + round(r * span)
    exact_r = (t - s0) / span
    expected = _expected(t0, q0, t1, q1, exact_r)
    got = buf.lookup_transform("a", "b", Time(nanoseconds=t))
    np.testing.assert_allclose(msg_matrix(got), expected, atol=1e-7)
    translations, quats = buf.lookup_transforms("a", "b", [t, s0, s0 + span])
    np.testing.assert_allclose(translations[0], expected[:3, 3], atol=1e-7)
    np.testing.assert_allclose(pr.matrix_from_quaternion([quats[0, 3], *quats[0, :3]]), expected[:3, :3], atol=1e-7)
