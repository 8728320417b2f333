"""robot_state_publisher's ROS 1 hot path agrees with its message path, byte for byte, rule for rule.

The hot path reads ROS 1 JointState bytes by hand (:class:`Ros1JointStateReader`), computes
every transform with array operations (:meth:`RobotStateLogic.state_arrays`, the cycle's
fused kernel) and writes ROS 1 TFMessage bytes from a template (:class:`Ros1TFTemplate`).
Each piece is checked against the path it stands in for: the generic ROS 1 codec (rosbags),
:meth:`RobotStateLogic.joint_state` with message objects, ``evaluate`` + spatial's canonical
kernel, and Pinocchio's FK of the links the transforms compose to.
"""

from __future__ import annotations

import logging
import math
import random
import struct

import numpy as np
import pinocchio as pin
import pytest
from conftest import ERD_ROBOTS, erd_urdfs
from tfhelpers import compose

from robotmodel.bus import ros1_codec
from robotmodel.kinematics import KinematicModel
from robotmodel.model import load
from robotmodel.msgs import Header, JointState, TFMessage, make_transform, stamp
from robotmodel.publishers import RobotStateLogic
from robotmodel.publishers._jointstate_cdr import CannotDecode
from robotmodel.publishers._jointstate_ros1 import Ros1JointStateReader
from robotmodel.publishers._tf_ros1 import Ros1TFTemplate
from robotmodel.spatial import quat_canonical, quats_canonical

SEC = 1_000_000_000
T0 = 1_700_000_000 * SEC
PANDA = ERD_ROBOTS / "panda_description/urdf/panda.urdf"
TALOS = ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf"
JOINT_STATE = ros1_codec(JointState)
TF = ros1_codec(TFMessage)


def frame(rng: random.Random) -> str:
    return "".join(rng.choice("ab/_é1") for _ in range(rng.randint(0, 11)))


def random_state(rng: random.Random, names: list[str] | None = None) -> JointState:
    if names is None:
        names = [frame(rng) for _ in range(rng.choice([0, 1, 3, 44]))]

    def values() -> list[float]:
        if rng.random() < 0.2:
            return []
        return [rng.choice([math.nan, math.inf, -0.0]) if rng.random() < 0.1 else rng.uniform(-9, 9) for _ in names]

    ns = rng.choice([0, 2**31 * SEC - 1, rng.randint(0, 2**31 * SEC - 1)])
    return JointState(Header(stamp(ns), frame(rng)), list(names), values(), values(), values())


# -- reading JointState ---------------------------------------------------------------------------
def test_reader_reads_what_the_generic_codec_reads() -> None:
    rng = random.Random(1)
    reader = Ros1JointStateReader()
    fixed = [frame(rng) for _ in range(7)]
    for i in range(400):
        # Mostly the same names (the remembered ones), sometimes others.
        msg = random_state(rng, None if i % 5 == 0 else fixed)
        data = JOINT_STATE.encode(msg)
        if i % 7 == 0:  # a ROS 1 peer's uint32 seconds past int32's range
            data = data[:4] + struct.pack("<I", 2**32 - 1 - i) + data[8:]
        got = reader.read(data)
        want = JOINT_STATE.decode(data)
        assert got.names == tuple(want.name)
        assert got.stamp_ns == want.header.stamp.sec * SEC + want.header.stamp.nanosec
        np.testing.assert_array_equal(got.positions, np.array(want.position, dtype=np.float64).reshape(-1))
        assert np.array_equal(np.signbit(got.positions), np.signbit(np.array(want.position).reshape(-1)))


def test_reader_refuses_what_it_cannot_read_and_the_generic_path_decides() -> None:
    data = JOINT_STATE.encode(JointState(Header(stamp(5), "f"), ["joint_a", "b"], [1.0, 2.0], [], [3.0]))
    reader = Ros1JointStateReader()
    bad = [data[:cut] for cut in range(len(data))]
    bad.append(data + b"\x00")  # bytes after the message
    name_at = 4 * 3 + 4 + 1 + 4 + 4  # header, "f", name count, first name's length
    bad.append(data[:name_at] + b"\xff" + data[name_at + 1:])  # not UTF-8
    bad.append(data[:name_at] + b"\x00" + data[name_at + 1:])  # a NUL in a name
    lying = bytearray(data)
    lying[4 * 3 + 4 + 1:4 * 3 + 4 + 1 + 4] = struct.pack("<I", 10**9)  # a billion names
    bad.append(bytes(lying))
    for each in bad:
        with pytest.raises(CannotDecode):
            reader.read(each)
    assert reader.read(data).names == ("joint_a", "b")


# -- writing TFMessage ----------------------------------------------------------------------------
@pytest.mark.parametrize("seed", range(60))
def test_template_writes_the_codecs_bytes(seed: int) -> None:
    rng = random.Random(seed)
    n = rng.choice([0, 1, 2, 5, 44])
    parents = [frame(rng) for _ in range(n)]
    children = [frame(rng) for _ in range(n)]
    translations = np.array([[rng.uniform(-5, 5) for _ in range(3)] for _ in range(n)]).reshape(n, 3)
    rotations = np.array([[rng.uniform(-1, 1) for _ in range(4)] for _ in range(n)]).reshape(n, 4)
    template = Ros1TFTemplate(parents, children)
    for stamp_ns in (0, 2**32 * SEC - 1, rng.randint(0, 2**32 * SEC - 1)):
        expected = TF.encode(TFMessage([make_transform(p, c, t, r, stamp_ns) for p, c, t, r in
                                        zip(parents, children, translations, rotations, strict=True)]))
        assert template.encode(stamp_ns, translations, rotations) == expected
        # Other layouts of the same numbers (component-major views) give the same bytes.
        assert template.encode(stamp_ns, np.asfortranarray(translations), rotations.T.copy().T) == expected


def test_template_reused_with_arrays_changed_in_place() -> None:
    template = Ros1TFTemplate(["a", "bb"], ["c", "d"])
    translations, rotations = np.ones((2, 3)), np.full((2, 4), 0.5)
    frozen = np.arange(6.0).reshape(2, 3)
    frozen.setflags(write=False)
    for k in range(3):
        translations[k % 2, k] = 7.0 + k  # the same array, other values
        rotations[0, k] = -k
        for t in (translations, frozen, translations):
            expected = TF.encode(TFMessage([make_transform(p, c, tt, r, k) for p, c, tt, r in
                                            zip(["a", "bb"], ["c", "d"], t, rotations, strict=True)]))
            assert template.encode(k, t, rotations) == expected


def test_template_refuses_stamps_outside_ros1_seconds() -> None:
    template = Ros1TFTemplate(["a"], ["b"])
    assert template.encode(-1, np.zeros((1, 3)), np.zeros((1, 4))) is None
    assert template.encode(2**32 * SEC, np.zeros((1, 3)), np.zeros((1, 4))) is None


# -- the kernel -----------------------------------------------------------------------------------
def bits(a: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def kernel_robots() -> list:
    """One robot of each example-robot-data folder, and the Tiagos: with Panda, they hit tf2's sign-rule ties."""
    robots = [p for p in erd_urdfs() if p.name != "ur3.urdf"]  # ur3.urdf is an empty robot
    firsts = {}
    for path in robots:
        firsts.setdefault(path.parent, path)
    return sorted(set(firsts.values()) | {p for p in robots if p.stem in ("tiago_dual", "tiago_pro")})


@pytest.mark.parametrize("path", kernel_robots(), ids=lambda p: p.stem)
def test_fused_kernel_is_evaluate_then_canonical_bit_for_bit(path) -> None:
    tables = KinematicModel(load(path))._cycle.tables
    rng = np.random.default_rng(len(path.name))
    rows = len(tables.rows)
    special = [0.0, -0.0, math.pi, -math.pi, math.pi / 2, 2 * math.pi / 3, 1e-300, -7.5]
    for k in range(40):
        values = rng.uniform(-7, 7, rows) if k % 2 else rng.choice(special, rows)
        if k == 7 and rows:
            values[0] = math.nan
        translations, rotations = tables.evaluate(values)
        fused_t, fused_r = tables.evaluate_canonical(values)
        assert np.array_equal(bits(fused_t), bits(translations))
        assert np.array_equal(bits(fused_r), bits(quats_canonical(rotations)))
        # spatial's scalar kernel is the definition the batched one follows.
        for q, got in zip(rotations.tolist()[:3], fused_r.tolist()[:3], strict=False):
            assert np.array_equal(bits(np.array(quat_canonical(q))), bits(np.array(got)))


# -- the logic ------------------------------------------------------------------------------------
def run_both(desc, messages, **settings):
    """Each message through the message path and through the hot path: what each publishes, as bytes."""
    slow = RobotStateLogic(desc, **settings)
    fast = RobotStateLogic(desc, **settings)
    reader = Ros1JointStateReader()
    out = []
    for msg, now_ns in messages:
        data = JOINT_STATE.encode(msg)
        transforms = slow.joint_state(JOINT_STATE.decode(data), now_ns)
        state = reader.read(data)
        found = fast.state_arrays(state.names, state.positions, state.stamp_ns, now_ns)
        assert (transforms is None) == (found is None), msg
        if found is not None:
            assert fast.encode_tf(*found, Ros1TFTemplate) == TF.encode(TFMessage(transforms))
            out.append(found)
    return out


@pytest.mark.parametrize("path", [PANDA, TALOS], ids=["panda", "talos"])
def test_hot_path_publishes_what_the_message_path_does(path) -> None:
    desc = load(path)
    variables = list(KinematicModel(desc).variables)
    mimics = [j.name for j in desc.joints if j.mimic is not None]
    rng = random.Random(3)
    messages = []
    now = T0
    for k in range(300):
        names = list(variables)
        if k % 3 == 0:
            rng.shuffle(names)
        values = [rng.uniform(-3, 3) for _ in names]
        if k % 50 == 7:
            values[2] = math.nan  # left out with its mimics, said once
        if k % 50 == 11:
            names, values = names[:3], values[:3]  # some joints only
        if k % 50 == 13:
            names, values = [*names, "no_such_joint"], [*values, 1.0]
        if k % 50 == 17 and mimics:
            names, values = [*names, mimics[0]], [*values, 0.25]  # an explicit mimic value wins
        if k % 50 == 19:
            names, values = [*names, names[0]], [*values, 9.0]  # a repeated name: the first value wins
        if k % 50 == 23:
            values = values[:-1]  # lengths differ: dropped
        if k % 50 == 29:
            now -= 5 * SEC  # time goes backwards: the cap is reset
        now += SEC // 1000
        stamp_ns = 0 if k % 50 == 31 else now + rng.choice([-SEC // 100, 0, SEC // 2000])
        messages.append((JointState(Header(stamp(stamp_ns)), names, values), now))
    published = run_both(desc, messages, publish_frequency=200.0)
    assert 30 < len(published) < 150  # the 5 ms cap over 1 ms steps let about one in five through
    assert len(run_both(desc, messages, publish_frequency=0.0)) >= len(published)
    assert len(run_both(desc, messages, ignore_timestamp=True)) > len(published)


@pytest.mark.parametrize("path", [PANDA, TALOS], ids=["panda", "talos"])
def test_hot_path_composes_to_pinocchio_fk(path) -> None:
    desc = load(path)
    rsp = RobotStateLogic(desc)
    model = pin.buildModelFromXML(rsp.description_text)
    data = model.createData()
    rng = np.random.default_rng(4)
    names = tuple(rsp.model.variables)
    for k in range(5):
        values = rng.uniform(-2, 2, len(names))
        transforms, _ = rsp.state_arrays(names, values, T0 + k * SEC, T0 + k * SEC)
        # Pinocchio's own configuration vector, from the same values (mimic joints from their masters).
        q = pin.neutral(model)
        by_name = dict(zip(names, values.tolist(), strict=True))
        for rule in rsp.model.mimics.values():
            by_name[rule.joint] = rule.multiplier * by_name[rule.master] + rule.offset
        for name, value in by_name.items():
            if model.existJointName(name):
                joint = model.joints[model.getJointId(name)]
                if joint.nq == 2:  # continuous: (cos, sin)
                    q[joint.idx_q:joint.idx_q + 2] = [math.cos(value), math.sin(value)]
                else:
                    q[joint.idx_q] = value
        pin.framesForwardKinematics(model, data, q)
        messages = rsp.stamped(transforms, T0) + rsp.fixed_transforms(T0)
        poses = compose(messages, desc.root)
        checked = 0
        for frame_id in range(model.nframes):
            name = model.frames[frame_id].name
            if model.frames[frame_id].type == pin.FrameType.BODY and name in poses:
                np.testing.assert_allclose(poses[name], data.oMf[frame_id].homogeneous, atol=1e-9, err_msg=name)
                checked += 1
        assert checked >= len(desc.links) - 1


def test_name_sets_that_alternate_keep_the_cap_per_joint(caplog) -> None:
    desc = load(PANDA)
    names = list(KinematicModel(desc).variables)
    messages = []
    for k in range(60):
        subset = names if k % 4 else names[:2]
        messages.append((JointState(Header(stamp(T0 + k * SEC // 100)), subset, [0.1 * k] * len(subset)),
                         T0 + k * SEC // 100))
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        assert 10 < len(run_both(desc, messages, publish_frequency=40.0)) < 60
