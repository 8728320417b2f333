"""Recordings written by rosbags' and mcap's writers in every format, read back into a Buffer.

Expected poses are computed here from the values the test wrote: hand-written lerp/slerp
and 4x4 matrices (pytransform3d for quaternion -> matrix), never through robotmodel.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from pytransform3d.rotations import matrix_from_quaternion
from recording.bagfiles import FORMATS, NS, Msg, write

from robotmodel.errors import ExtrapolationException, RecordingError, TransformException
from robotmodel.recording import Format, detect_format, load_buffer, load_recording
from robotmodel.tf import Buffer

T0 = 1_700_000_000 * NS
DT = 50_000_000  # 20 Hz
TICKS = 40
SWITCH = 20  # odom's parent is map before, world from here on
NAN_TICK = 7  # odom -> base has a NaN here: skipped


def quat_axis(axis: tuple[float, float, float], angle: float) -> tuple[float, float, float, float]:
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2) / n
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2))


STATIC_CAM = (0.1, 0.2, 0.3, *quat_axis((1, 0, 0), 0.4))
STATIC_MAP = (5.0, -1.0, 0.0, *quat_axis((0, 0, 1), 0.25))


def base_pose(k: int) -> tuple[float, ...]:
    return (0.05 * k, 0.01 * k * k, 0.0, *quat_axis((0, 0, 1), 0.07 * k))


def odom_in_map(k: int) -> tuple[float, ...]:
    return (1.0 + 0.002 * k, 2.0, 0.0, *quat_axis((0.3, 0.1, 1), 0.02 * k))


def odom_in_world(k: int) -> tuple[float, ...]:
    return (-3.0, 0.5 * k, 0.1, *quat_axis((1, 1, 0), 0.01 * k))


def stamp(k: int) -> int:
    return T0 + k * DT


def scenario() -> list[Msg]:
    msgs = [Msg("/tf_static", T0 - NS, "tf", [("base", "cam", T0 - NS, STATIC_CAM),
                                              ("world", "map", T0 - NS, STATIC_MAP)])]
    for k in range(TICKS):
        t = stamp(k)
        bp = base_pose(k)
        if k == NAN_TICK:
            bp = (math.nan, *bp[1:])
        odom = ("map", "odom", t, odom_in_map(k)) if k < SWITCH else ("world", "odom", t, odom_in_world(k))
        msgs.append(Msg("/tf", t + 1000, "tf", [("odom", "base", t, bp), odom]))
    return msgs


# --------------------------------------------------------------- independent reference
def mat(p: tuple[float, ...] | np.ndarray) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3] = matrix_from_quaternion([p[6], p[3], p[4], p[5]])
    m[:3, 3] = p[:3]
    return m


def slerp(a: tuple[float, ...], b: tuple[float, ...], f: float) -> tuple[float, ...]:
    qa, qb = np.array(a[3:]), np.array(b[3:])
    if qa @ qb < 0:
        qb = -qb
    omega = math.acos(min(1.0, float(qa @ qb)))
    q = qa if omega < 1e-12 else (math.sin((1 - f) * omega) * qa + math.sin(f * omega) * qb) / math.sin(omega)
    t = (1 - f) * np.array(a[:3]) + f * np.array(b[:3])
    return (*t, *q)


def series_at(fn, ticks: list[int], t: int) -> tuple[float, ...]:
    """Interpolate a recorded series (ticks present) at time t, as tf2: lerp + slerp."""
    times = [stamp(k) for k in ticks]
    i = int(np.searchsorted(times, t, side="right")) - 1
    if times[i] == t:
        return fn(ticks[i])
    f = (t - times[i]) / (times[i + 1] - times[i])
    return slerp(fn(ticks[i]), fn(ticks[i + 1]), f)


def expected_world_cam(t: int) -> np.ndarray:
    base_ticks = [k for k in range(TICKS) if k != NAN_TICK]
    odom_base = mat(series_at(base_pose, base_ticks, t))
    if t <= stamp(SWITCH - 1):
        world_odom = mat(STATIC_MAP) @ mat(series_at(odom_in_map, list(range(SWITCH)), t))
    elif t < stamp(SWITCH):
        # tf2 never interpolates across a parent change: the older sample holds.
        world_odom = mat(STATIC_MAP) @ mat(odom_in_map(SWITCH - 1))
    else:
        world_odom = mat(series_at(odom_in_world, list(range(SWITCH, TICKS)), t))
    return world_odom @ odom_base @ mat(STATIC_CAM)


def query_times() -> list[int]:
    recorded = [stamp(k) for k in range(TICKS)]
    between = [stamp(k) + DT // 3 for k in range(TICKS - 1)]
    return recorded + between + [stamp(SWITCH - 1) + 1, stamp(SWITCH) - 1]


@pytest.fixture(scope="module", params=FORMATS)
def recorded(request, tmp_path_factory) -> Path:
    return write(tmp_path_factory.mktemp(request.param) / "run", request.param, scenario())


def test_format_is_told_by_content(recorded):
    expected = {".bag": Format.ROS1_BAG, ".mcap": Format.MCAP, ".db3": Format.SQLITE3}.get(recorded.suffix,
                                                                                         Format.ROS2_FOLDER)
    assert detect_format(recorded) is expected


def test_lookups_equal_independent_interpolation(recorded):
    loaded = load_recording(recorded, progress=False)
    buffer = loaded.buffer
    assert loaded.skipped == 1  # the NaN transform
    assert loaded.transforms == 2 + 2 * TICKS - 1
    assert (loaded.start_ns, loaded.end_ns) == (stamp(0), stamp(TICKS - 1))
    for t in query_times():
        pose, used = buffer.lookup_ns("world", "cam", t)
        assert used == t
        np.testing.assert_allclose(mat(pose), expected_world_cam(t), atol=1e-12, err_msg=f"t={t}")
    # The vectorized path agrees with the scalar one over the same stamps.
    times = np.array(query_times(), dtype=np.int64)
    trans, quats = buffer.lookup_transforms("world", "cam", times)
    for t, tr, q in zip(times.tolist(), trans, quats, strict=True):
        np.testing.assert_allclose(mat((*tr, *q)), expected_world_cam(t), atol=1e-12)


def test_statics_valid_at_all_times(recorded):
    buffer = load_buffer(recorded, progress=False)
    for t in (1, stamp(0) - 10 * NS, 2**62):
        pose, _ = buffer.lookup_ns("base", "cam", t)
        np.testing.assert_allclose(mat(pose), mat(STATIC_CAM), atol=1e-15)
    with pytest.raises(ExtrapolationException):
        buffer.lookup_ns("odom", "cam", stamp(TICKS - 1) + 1)


def test_parent_change_as_tf2(recorded):
    buffer = load_buffer(recorded, progress=False)
    assert buffer.frames()["odom"] == "world"  # the newest parent
    # Before the switch odom hangs under map; after it, directly under world.
    pose, _ = buffer.lookup_ns("map", "odom", stamp(3))
    np.testing.assert_allclose(mat(pose), mat(odom_in_map(3)), atol=1e-12)
    pose, _ = buffer.lookup_ns("world", "odom", stamp(SWITCH + 2))
    np.testing.assert_allclose(mat(pose), mat(odom_in_world(SWITCH + 2)), atol=1e-12)
    # The same transforms inserted one by one, in file order, give the same answers everywhere.
    reference = Buffer(unbounded=True)
    for m in scenario():
        for parent, child, t, p in m.value:
            reference.insert(parent, child, t, p, "ref", is_static=m.topic == "/tf_static")
    for t in query_times():
        for target, source in (("world", "cam"), ("map", "base"), ("odom", "cam")):
            try:
                want = reference.lookup_ns(target, source, t)
            except TransformException as exc:
                with pytest.raises(type(exc)):
                    buffer.lookup_ns(target, source, t)
            else:
                got = buffer.lookup_ns(target, source, t)
                assert got[1] == want[1]
                np.testing.assert_allclose(got[0], want[0], rtol=0, atol=1e-14)


def test_selected_topics_only(recorded):
    buffer = load_buffer(recorded, topics=["/tf_static"], progress=False)
    assert sorted(buffer.frames()) == ["cam", "map"]


def test_out_of_order_and_repeated_stamps_as_single_inserts(tmp_path):
    # Messages whose stamps go back in time and repeat, across flush boundaries.
    order = [5, 1, 3, 3, 0, 9, 7, 7, 2, 8, 6, 4]
    msgs = [Msg("/tf", T0 + i, "tf", [("a", "b", stamp(k), base_pose(k + (i % 2)))]) for i, k in enumerate(order)]
    path = write(tmp_path / "ooo", "mcap", msgs)
    import robotmodel.recording._load as load_module

    reference = Buffer(unbounded=True)
    for m in msgs:
        for parent, child, t, p in m.value:
            reference.insert(parent, child, t, p, "ref")
    old = load_module._FLUSH_MESSAGES
    load_module._FLUSH_MESSAGES = 5
    try:
        buffer = load_buffer(path, progress=False)
    finally:
        load_module._FLUSH_MESSAGES = old
    for t in [stamp(k) + d for k in range(10) for d in (0, DT // 2)][:-1]:
        got, want = buffer.lookup_ns("a", "b", t), reference.lookup_ns("a", "b", t)
        assert got[1] == want[1]
        np.testing.assert_allclose(got[0], want[0], rtol=0, atol=1e-14)


def test_ros1_tf_tfmessage_of_old_bags(tmp_path):
    from recording.bagfiles import TS1, build
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import get_types_from_msg

    if "tf/msg/tfMessage" not in TS1.types:
        TS1.register(get_types_from_msg("geometry_msgs/TransformStamped[] transforms", "tf/msg/tfMessage"))
    path = tmp_path / "old.bag"
    with Writer(path) as w:
        conn = w.add_connection("/tf", "tf/msg/tfMessage", typestore=TS1)
        for k in range(5):
            msg = build(TS1, Msg("/tf", stamp(k), "tf", [("odom", "base", stamp(k), base_pose(k))]), True)
            w.write(conn, stamp(k), TS1.serialize_ros1(TS1.types["tf/msg/tfMessage"](transforms=msg.transforms),
                                                       "tf/msg/tfMessage"))
    buffer = load_buffer(path, progress=False)
    pose, _ = buffer.lookup_ns("odom", "base", stamp(2) + DT // 2)
    np.testing.assert_allclose(mat(pose), mat(slerp(base_pose(2), base_pose(3), 0.5)), atol=1e-12)


def test_pose_series_at_a_rate_over_a_damaged_span_is_refused():
    from robotmodel.recording import MAX_ROWS, pose_series

    buf = Buffer(unbounded=True)
    buf.insert("odom", "base", T0, (0, 0, 0, 0, 0, 0, 1), "test")
    buf.insert("odom", "base", T0 + (1 << 19) * NS, (1, 0, 0, 0, 0, 0, 1), "test")  # a flipped seconds bit
    assert len(pose_series(buf, "odom", "base", 1.0).stamps) == (1 << 19) + 1
    with pytest.raises(RecordingError, match=f"more than {MAX_ROWS:,}"):
        pose_series(buf, "odom", "base", 100.0)
