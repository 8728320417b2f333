"""robot_state_publisher's rules, checked without a bus against hand maths and Pinocchio FK."""

from __future__ import annotations

import logging
import math
import random

import numpy as np
import pytest
from conftest import BUNDLED, ERD_ROBOTS
from handfk import HandFK
from tfhelpers import compose, msg_matrix

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load
from robotmodel.msgs import JointState, stamp
from robotmodel.publishers import PublisherError, RobotStateLogic

SEC = 1_000_000_000
MS = 1_000_000
T0 = 1_700_000_000 * SEC
ARM = BUNDLED / "arm.urdf.xacro"
TALOS = ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf"


def joint_state(values: dict[str, float], stamp_ns: int) -> JointState:
    return JointState(header=stamp_header(stamp_ns), name=list(values), position=list(values.values()))


def stamp_header(stamp_ns: int):
    from robotmodel.msgs import Header

    return Header(stamp=stamp(stamp_ns))




@pytest.fixture(scope="module")
def arm():
    return load(ARM)


def random_values(model: KinematicModel, rng: random.Random) -> dict[str, float]:
    return {n: rng.uniform(lo, hi) for n, lo, hi in zip(model.variables, model.lower, model.upper, strict=True)}


@pytest.mark.parametrize("seed", range(5))
def test_arm_tree_matches_fk(arm, seed):
    rsp = RobotStateLogic(arm)
    rng = random.Random(seed)
    values = random_values(rsp.model, rng)
    stamp_ns = T0 + seed * SEC + 123
    moving = rsp.joint_state(joint_state(values, stamp_ns), now_ns=T0)
    assert moving is not None
    assert {t.header.stamp.sec * SEC + t.header.stamp.nanosec for t in moving} == {stamp_ns}
    # Every moving joint, the mimic finger included, and nothing fixed.
    assert sorted(t.child_frame_id for t in moving) == sorted(
        j.child for j in arm.joints if j.type.value in ("revolute", "continuous", "prismatic"))
    static = rsp.fixed_transforms(now_ns=T0 + 5)
    assert {t.header.stamp.nanosec for t in static} == {5}
    assert {(t.header.frame_id, t.child_frame_id) for t in static} == {
        ("world", "arm_base_link"), ("arm_wrist_yaw_link", "gripper_palm_link")}
    poses = compose(moving + static, arm.root)
    hand = HandFK(rsp.description_text).poses(values)
    state = KinematicState(rsp.model).update(values)
    for link in rsp.model.link_names:
        np.testing.assert_allclose(poses[link], hand[link], atol=1e-9)
        np.testing.assert_allclose(poses[link], state.link_matrix(link), atol=1e-9)


def test_mimic_follows_master_and_explicit_value_wins(arm):
    rsp = RobotStateLogic(arm)
    out = rsp.joint_state(joint_state({"gripper_left_finger_joint": 0.03}, T0), T0)
    by_child = {t.child_frame_id: t for t in out}
    left = by_child["gripper_left_finger_link"].transform.translation
    right = by_child["gripper_right_finger_link"].transform.translation
    origin = next(j for j in arm.joints if j.name == "gripper_right_finger_joint").origin.xyz
    axis = np.array(next(j for j in arm.joints if j.name == "gripper_right_finger_joint").axis)
    expect = np.array(origin) + 0.03 * axis / np.linalg.norm(axis)
    np.testing.assert_allclose([right.x, right.y, right.z], expect, atol=1e-12)
    assert len(out) == 2 and left is not right
    # The message's own value for the mimic joint is the one published.
    out = rsp.joint_state(joint_state({"gripper_left_finger_joint": 0.03, "gripper_right_finger_joint": 0.01},
                                      T0 + SEC), T0)
    right = {t.child_frame_id: t for t in out}["gripper_right_finger_link"].transform.translation
    np.testing.assert_allclose([right.x, right.y, right.z], np.array(origin) + 0.01 * axis / np.linalg.norm(axis),
                               atol=1e-12)


def test_only_named_joints_are_published(arm):
    rsp = RobotStateLogic(arm)
    out = rsp.joint_state(joint_state({"arm_elbow_joint": 0.5}, T0), T0)
    assert [(t.header.frame_id, t.child_frame_id) for t in out] == [("arm_upper_link", "arm_fore_link")]


def test_frame_prefix_is_verbatim_everywhere(arm):
    rsp = RobotStateLogic(arm, frame_prefix="robot1_")
    static = rsp.fixed_transforms(T0)
    moving = rsp.joint_state(joint_state({"arm_base_joint": 0.1}, T0), T0)
    frames = {f for t in static + moving for f in (t.header.frame_id, t.child_frame_id)}
    assert frames == {"robot1_world", "robot1_arm_base_link", "robot1_arm_wrist_yaw_link",
                      "robot1_gripper_palm_link", "robot1_arm_turret_link"}
    rsp.frame_prefix = "r2/"  # read on every publish, as robot_state_publisher reads its parameter
    moving = rsp.joint_state(joint_state({"arm_base_joint": 0.1}, T0 + SEC), T0)
    assert (moving[0].header.frame_id, moving[0].child_frame_id) == ("r2/arm_base_link", "r2/arm_turret_link")


@pytest.mark.parametrize(("hz", "interval_ms"), [(20.0, 50), (30.0, 33), (1000.0, 1), (7.0, 142)])
def test_publish_frequency_caps_by_stamp(arm, hz, interval_ms):
    rsp = RobotStateLogic(arm, publish_frequency=hz)
    values = {"arm_base_joint": 0.1}
    assert rsp.joint_state(joint_state(values, T0), T0) is not None
    # Within the (truncated, whole-millisecond) interval: dropped; at it: published.
    assert rsp.joint_state(joint_state(values, T0 + interval_ms * MS - 1), T0) is None
    assert rsp.joint_state(joint_state(values, T0 + interval_ms * MS), T0) is not None


def test_cap_takes_the_oldest_joint_and_unseen_joints_pass(arm):
    rsp = RobotStateLogic(arm)
    assert rsp.joint_state(joint_state({"arm_base_joint": 0.1}, T0), T0) is not None
    # A joint never published before counts as published at 0: the message passes.
    assert rsp.joint_state(joint_state({"arm_elbow_joint": 0.1}, T0 + MS), T0) is not None
    # Both named: the older one (T0) decides.
    both = {"arm_base_joint": 0.2, "arm_elbow_joint": 0.2}
    assert rsp.joint_state(joint_state(both, T0 + 49 * MS), T0) is None
    assert rsp.joint_state(joint_state(both, T0 + 50 * MS), T0) is not None


def test_zero_frequency_means_no_cap(arm):
    rsp = RobotStateLogic(arm, publish_frequency=0)
    for i in range(5):
        assert rsp.joint_state(joint_state({"arm_base_joint": 0.1}, T0 + i), T0) is not None


@pytest.mark.parametrize("hz", [-1.0, 1000.5, math.nan])
def test_frequency_out_of_range(arm, hz):
    with pytest.raises(PublisherError, match=r"^publish_frequency must be between 0 and 1000$"):
        RobotStateLogic(arm, publish_frequency=hz)


def test_zero_stamp_never_passes_without_ignore_timestamp(arm, caplog):
    rsp = RobotStateLogic(arm)
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        for _ in range(10):
            assert rsp.joint_state(joint_state({"arm_base_joint": 0.1}, 0), T0) is None
    assert len([r for r in caplog.records if "stamped 0" in r.getMessage()]) == 1


def test_ignore_timestamp_publishes_every_message_with_its_stamp(arm):
    rsp = RobotStateLogic(arm, ignore_timestamp=True)
    for stamp_ns in (0, T0, T0 + 1, T0 + 1, T0 - SEC):
        out = rsp.joint_state(joint_state({"arm_base_joint": 0.1}, stamp_ns), T0)
        assert out is not None
        assert out[0].header.stamp.sec * SEC + out[0].header.stamp.nanosec == stamp_ns


def test_clock_going_backwards_resets_the_cap(arm, caplog):
    rsp = RobotStateLogic(arm)
    values = {"arm_base_joint": 0.1}
    assert rsp.joint_state(joint_state(values, T0), T0) is not None
    assert rsp.joint_state(joint_state(values, T0 + MS), T0 + MS) is None
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        assert rsp.joint_state(joint_state(values, T0 + 2 * MS), T0 - SEC) is not None
    assert "Moved backwards in time, re-publishing joint transforms!" in caplog.text


def test_unknown_joints_are_ignored_and_said_once(arm, caplog):
    rsp = RobotStateLogic(arm)
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        for i in range(20):
            out = rsp.joint_state(joint_state({"nope": 1.0, "arm_base_joint": 0.1, "gripper_palm_joint": 3.0},
                                              T0 + i * SEC), T0)
            assert [t.child_frame_id for t in out] == ["arm_turret_link"]
    warnings = [r.getMessage() for r in caplog.records]
    assert warnings == ["joint_states names joint(s) that robot 'arm' lacks, ignored: nope"]


def test_mismatched_lengths_drop_the_message_and_say_so_once(arm, caplog):
    rsp = RobotStateLogic(arm)
    empty = JointState(header=stamp_header(T0), name=["arm_base_joint", "arm_elbow_joint"], position=[])
    short = JointState(header=stamp_header(T0), name=["arm_base_joint", "arm_elbow_joint"], position=[0.1])
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        for _ in range(5):
            assert rsp.joint_state(empty, T0) is None
            assert rsp.joint_state(short, T0) is None
    texts = [(r.levelname, r.getMessage()) for r in caplog.records]
    assert texts == [
        ("WARNING", 'Robot state publisher ignored a JointState message about joint(s) "arm_base_joint"(,...) '
                    "whose position member was empty."),
        ("ERROR", "Robot state publisher ignored an invalid JointState message"),
    ]
    assert rsp.joint_state(joint_state({"arm_base_joint": 0.1}, T0), T0) is not None


def test_nan_leaves_out_the_joint_and_its_mimics(arm, caplog):
    rsp = RobotStateLogic(arm, ignore_timestamp=True)
    values = {"arm_base_joint": math.nan, "arm_elbow_joint": 0.2, "gripper_left_finger_joint": math.inf}
    with caplog.at_level(logging.WARNING, "robot_state_publisher"):
        for _ in range(3):
            out = rsp.joint_state(joint_state(values, T0), T0)
            assert [t.child_frame_id for t in out] == ["arm_fore_link"]
    said = sorted(r.getMessage().split("'")[1] for r in caplog.records)
    assert said == ["arm_base_joint", "gripper_left_finger_joint"]
    assert all(math.isfinite(v) for v in (out[0].transform.rotation.w, out[0].transform.translation.z))


def test_repeated_name_first_value_wins(arm):
    rsp = RobotStateLogic(arm)
    msg = JointState(header=stamp_header(T0), name=["arm_base_joint", "arm_base_joint"], position=[0.5, 1.0])
    (t,) = rsp.joint_state(msg, T0)
    assert t.transform.rotation.z == pytest.approx(math.sin(0.25))


PLANAR = """<?xml version="1.0"?>
<robot name="odd">
  <link name="base"/><link name="slider"/><link name="flyer"/><link name="tip"/>
  <joint name="plane" type="planar"><parent link="base"/><child link="slider"/>
    <origin xyz="1 2 3" rpy="0 0 0.5"/></joint>
  <joint name="free" type="floating"><parent link="base"/><child link="flyer"/>
    <origin xyz="0 0 1"/></joint>
  <joint name="hinge" type="continuous"><parent link="flyer"/><child link="tip"/><axis xyz="0 0 1"/></joint>
</robot>
"""


def test_planar_is_static_at_origin_floating_is_not_published(caplog):
    with caplog.at_level(logging.INFO, "robot_state_publisher"):
        rsp = RobotStateLogic(PLANAR)
    assert rsp.description_text == PLANAR
    messages = [r.getMessage() for r in caplog.records]
    assert messages == ["Converting unknown joint type of joint 'plane' into a fixed joint",
                        "Converting unknown joint type of joint 'free' into a fixed joint"]
    (static,) = rsp.fixed_transforms(T0)
    assert (static.header.frame_id, static.child_frame_id) == ("base", "slider")
    expect = np.eye(4)
    expect[:3, :3] = [[math.cos(0.5), -math.sin(0.5), 0], [math.sin(0.5), math.cos(0.5), 0], [0, 0, 1]]
    expect[:3, 3] = [1, 2, 3]
    np.testing.assert_allclose(msg_matrix(static), expect, atol=1e-12)
    out = rsp.joint_state(joint_state({"plane": 1.0, "free": 2.0, "hinge": 0.3}, T0), T0)
    assert [(t.header.frame_id, t.child_frame_id) for t in out] == [("flyer", "tip")]


def test_new_description_replaces_the_robot(arm):
    rsp = RobotStateLogic(arm)
    rsp.setup(PLANAR)
    assert rsp.description.name == "odd"
    assert [t.child_frame_id for t in rsp.joint_state(joint_state({"hinge": 0.1, "arm_base_joint": 0.1}, T0), T0)] \
        == ["tip"]


def test_talos_every_link_from_one_message_plus_statics():
    desc = load(TALOS)
    rsp = RobotStateLogic(desc)
    model = rsp.model
    values = random_values(model, random.Random(7))
    moving = rsp.joint_state(joint_state(values, T0), T0)
    static = rsp.fixed_transforms(T0)
    assert len(moving) == 44 and len(static) == 15
    poses = compose(moving + static, desc.root)
    assert set(poses) == {link.name for link in desc.links}
    state = KinematicState(model).update(values)
    for link in model.link_names:
        np.testing.assert_allclose(poses[link], state.link_matrix(link), atol=1e-9)


def test_a_path_is_expanded_and_published_as_xacro_prints_it():
    from robotmodel.xacro import expand

    for source in (ARM, str(ARM)):
        rsp = RobotStateLogic(source)
        assert rsp.description_text == expand(ARM)
        assert rsp.description.name == "arm"


CHAIN = """<robot name="chain">
  <link name="l0"/><link name="l1"/><link name="l2"/><link name="l3"/>
  <joint name="root" type="continuous"><parent link="l0"/><child link="l1"/><axis xyz="0 0 1"/></joint>
  <joint name="z_mid" type="continuous"><parent link="l1"/><child link="l2"/><axis xyz="0 0 1"/>
    <mimic joint="root" multiplier="2" offset="0.1"/></joint>
  <joint name="a_dep" type="continuous"><parent link="l2"/><child link="l3"/><axis xyz="0 0 1"/>
    <mimic joint="z_mid" multiplier="-1" offset="0.5"/></joint>
</robot>"""


def test_mimic_chain_resolves_whatever_the_name_order():
    rsp = RobotStateLogic(CHAIN)
    out = {t.child_frame_id: t for t in rsp.joint_state(joint_state({"root": 0.3}, T0), T0)}
    # z_mid = 2·0.3 + 0.1 = 0.7; a_dep = -0.7 + 0.5 = -0.2 (RSP would drop a_dep: 'a_dep' < 'z_mid').
    assert out["l2"].transform.rotation.z == pytest.approx(math.sin(0.7 / 2))
    assert out["l3"].transform.rotation.z == pytest.approx(math.sin(-0.2 / 2))
