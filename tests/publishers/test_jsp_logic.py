"""joint_state_publisher's joints, defaults, mimic chains and source merging, without a bus.

Expected values are worked out by hand from the URDF below and the rules in
joint_state_publisher's source (ros/joint_state_publisher, ros2 branch).
"""

from __future__ import annotations

import logging
import math

import pytest
from conftest import BUNDLED, ERD_ROBOTS

from robotmodel.errors import JointValueError, URDFError
from robotmodel.model import load
from robotmodel.msgs import Header, JointState
from robotmodel.publishers import JointStateLogic, read_layout

T0 = 1_700_000_000 * 1_000_000_000

ROBOT = """<robot name="r">
  <link name="l0"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="l4"/><link name="l5"/>
  <link name="l6"/><link name="l7"/><link name="l8"/><link name="l9"/><link name="l10"/><link name="l11"/>
  <joint name="fixed_j" type="fixed"><parent link="l0"/><child link="l1"/></joint>
  <joint name="around" type="revolute"><parent link="l1"/><child link="l2"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="above" type="revolute"><parent link="l2"/><child link="l3"/>
    <limit lower="0.5" upper="1.5" effort="1" velocity="1"/></joint>
  <joint name="below" type="prismatic"><parent link="l3"/><child link="l4"/>
    <limit lower="-2" upper="-1" effort="1" velocity="1"/></joint>
  <joint name="edge" type="prismatic"><parent link="l4"/><child link="l5"/>
    <limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="l5"/><child link="l6"/></joint>
  <joint name="soft" type="revolute"><parent link="l6"/><child link="l7"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <safety_controller k_velocity="1" soft_lower_limit="0.2"/></joint>
  <joint name="m2" type="revolute"><parent link="l7"/><child link="l8"/>
    <limit lower="-9" upper="9" effort="1" velocity="1"/><mimic joint="m1" multiplier="3" offset="0.5"/></joint>
  <joint name="m1" type="revolute"><parent link="l8"/><child link="l9"/>
    <limit lower="-9" upper="9" effort="1" velocity="1"/><mimic joint="around" multiplier="-2" offset="0.1"/></joint>
  <joint name="float_j" type="floating"><parent link="l9"/><child link="l10"/></joint>
  <joint name="plane_j" type="planar"><parent link="l10"/><child link="l11"/></joint>
</robot>"""


def test_joint_order_limits_and_defaults():
    layout = read_layout(ROBOT)
    # Document order; fixed, floating and planar left out; mimic joints kept.
    assert layout.names == ("around", "above", "below", "edge", "spin", "soft", "m2", "m1")
    free = layout.free
    assert list(free) == ["around", "above", "below", "edge", "spin", "soft"]
    assert free["around"].zero == 0.0
    assert free["above"].zero == 1.0  # 0 outside [0.5, 1.5]: the middle
    assert free["below"].zero == -1.5
    assert free["edge"].zero == 0.0  # 0 on the boundary is inside
    assert (free["spin"].lower, free["spin"].upper, free["spin"].continuous) == (-math.pi, math.pi, True)
    # One safety controller narrows the range by the attributes it has (no soft upper: 1 stays).
    assert (free["soft"].lower, free["soft"].upper, free["soft"].zero) == (0.2, 1.0, 0.6)
    assert read_layout(ROBOT, use_smallest_joint_limits=False).free["soft"].zero == 0.0


def test_mimic_chain_composed():
    layout = read_layout(ROBOT)
    # m1 = -2·around + 0.1; m2 = 3·m1 + 0.5 = -6·around + 0.8
    m1, m2 = layout.dependent["m1"], layout.dependent["m2"]
    assert (m1.parent, m1.factor, m1.offset) == ("around", -2.0, 0.1)
    assert (m2.parent, m2.factor) == ("around", -6.0)
    assert m2.offset == pytest.approx(0.8)


def test_message_defaults_and_mimics():
    jsp = JointStateLogic()
    assert jsp.message(T0) is None
    jsp.configure(ROBOT)
    msg = jsp.message(T0 + 5)
    assert (msg.header.stamp.sec, msg.header.stamp.nanosec) == (1_700_000_000, 5)
    assert msg.name == ["around", "above", "below", "edge", "spin", "soft", "m2", "m1"]
    assert msg.position == pytest.approx([0.0, 1.0, -1.5, 0.0, 0.0, 0.6, 0.8, 0.1])
    assert msg.velocity == [] and msg.effort == []
    jsp.set(around=0.25)
    msg = jsp.message(T0)
    assert msg.position[6:] == pytest.approx([-6 * 0.25 + 0.8, -2 * 0.25 + 0.1])


def test_zeros_are_used_as_given():
    jsp = JointStateLogic(zeros={"above": 7.0, "around": -0.5})
    jsp.configure(ROBOT)
    assert jsp.message(T0).position[:2] == [-0.5, 7.0]


def test_without_mimic_tags_mimic_joints_are_free():
    jsp = JointStateLogic(use_mimic_tags=False)
    jsp.configure(ROBOT)
    assert "m1" in jsp.free_joints
    assert jsp.message(T0).position[6:] == [0.0, 0.0]


def test_merge_from_a_source_topic():
    jsp = JointStateLogic()
    jsp.configure(ROBOT)
    source = JointState(header=Header(), name=["above", "m1", "nope", "around"], position=[1.2, 5.0, 5.0, 0.5],
                        velocity=[0.1, 9.0, 9.0, 2.0])
    jsp.merge(source)
    msg = jsp.message(T0)
    # Free joints take the values; mimic and unknown names are ignored; velocities appear.
    assert msg.position == pytest.approx([0.5, 1.2, -1.5, 0.0, 0.0, 0.6, -6 * 0.5 + 0.8, -2 * 0.5 + 0.1])
    assert msg.velocity == pytest.approx([2.0, 0.1, 0.0, 0.0, 0.0, 0.0, -6 * 2.0, -2 * 2.0])
    assert msg.effort == []
    # Latest value per joint wins.
    jsp.merge(JointState(name=["above"], position=[0.7]))
    assert jsp.message(T0).position[1] == 0.7


def test_effort_is_not_scaled_for_mimics():
    jsp = JointStateLogic(publish_default_efforts=True)
    jsp.configure(ROBOT)
    jsp.merge(JointState(name=["around"], effort=[3.0]))
    assert jsp.message(T0).effort == [3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0, 3.0]


def test_short_source_arrays_are_said_once(caplog):
    jsp = JointStateLogic()
    jsp.configure(ROBOT)
    with caplog.at_level(logging.WARNING, "joint_state_publisher"):
        for _ in range(3):
            jsp.merge(JointState(name=["around", "above"], position=[0.3]))
    assert jsp.positions()["around"] == 0.3
    assert len(caplog.records) == 1 and "'above'" in caplog.records[0].getMessage()


def test_set_rejects_what_is_not_a_free_joint():
    jsp = JointStateLogic()
    jsp.configure(ROBOT)
    with pytest.raises(JointValueError, match="'m1' is not a movable, non-mimic joint of robot 'r'"):
        jsp.set(m1=0.1)
    with pytest.raises(JointValueError, match="'fixed_j'"):
        jsp.set({"fixed_j": 0.1})
    with pytest.raises(JointValueError, match="not finite"):
        jsp.set(around=math.nan)
    jsp.set({"around": 0.3}, above=0.9)
    assert jsp.positions()["around"] == 0.3 and jsp.positions()["above"] == 0.9


def test_new_description_resets_values():
    jsp = JointStateLogic()
    jsp.configure(ROBOT)
    jsp.set(around=0.3)
    jsp.configure(ROBOT.replace('name="r"', 'name="r2"'))
    assert jsp.positions()["around"] == 0.0
    assert jsp.layout.robot == "r2"


def test_delta_bounces_between_limits():
    jsp = JointStateLogic(delta=0.3)
    jsp.configure(ROBOT)
    seen = [jsp.message(T0).position[0] for _ in range(12)]
    # around: 0.3, 0.6, 0.9, 1.0 (clamped, turns), 0.7, ... down to -1.0, then back up.
    assert seen[:5] == pytest.approx([0.3, 0.6, 0.9, 1.0, 0.7])
    assert min(seen) == pytest.approx(-1.0)
    spin = [jsp.message(T0).position[4] for _ in range(20)]
    assert min(spin) == pytest.approx(-math.pi)  # a continuous joint wraps from max to min


@pytest.mark.parametrize(("joint", "text"), [
    ('<joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint>',
     'Limits must be specified for joint "j" of type "revolute"'),
    ('<joint name="j" type="prismatic"><parent link="a"/><child link="b"/><limit upper="1"/></joint>',
     '"lower" limit must be specified for joint "j" of type "prismatic"'),
    ('<joint name="j" type="revolute"><parent link="a"/><child link="b"/><limit lower="x" upper="1"/></joint>',
     '"lower" limit must be a float for joint "j" of type "revolute"'),
])
def test_limit_errors_have_jsp_texts(joint, text):
    with pytest.raises(URDFError) as info:
        read_layout(f'<robot name="x"><link name="a"/><link name="b"/>{joint}</robot>')
    assert str(info.value) == text


def test_mimic_cycle_is_an_error():
    cycle = """<robot name="c"><link name="a"/><link name="b"/><link name="c"/>
      <joint name="j1" type="continuous"><parent link="a"/><child link="b"/><mimic joint="j2"/></joint>
      <joint name="j2" type="continuous"><parent link="b"/><child link="c"/><mimic joint="j1"/></joint></robot>"""
    with pytest.raises(URDFError, match=r"^Found an infinite recursive mimic chain: \['j1', 'j2', 'j1'\]$"):
        read_layout(cycle)


def test_mimic_of_a_missing_joint_is_left_out(caplog):
    robot = """<robot name="m"><link name="a"/><link name="b"/>
      <joint name="j1" type="continuous"><parent link="a"/><child link="b"/><mimic joint="ghost"/></joint></robot>"""
    jsp = JointStateLogic()
    with caplog.at_level(logging.WARNING, "joint_state_publisher"):
        jsp.configure(robot)
    assert "'j1'" in caplog.text
    assert jsp.message(T0) is None


def test_arm_defaults_agree_with_the_kinematic_model():
    from robotmodel.kinematics import KinematicModel

    desc = load(BUNDLED / "arm.urdf.xacro")
    jsp = JointStateLogic()
    jsp.configure(desc.source_text)
    model = KinematicModel(desc)
    assert jsp.positions() == model.default_positions()
    assert jsp.message(T0).name == [j.name for j in desc.joints if j.type.value != "fixed"]


def test_talos_publishes_all_44_joints_with_mimics():
    desc = load(ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf")
    jsp = JointStateLogic()
    jsp.configure(desc.source_text)
    jsp.set(gripper_left_joint=-0.5)
    msg = jsp.message(T0)
    assert len(msg.name) == 44 and len(jsp.free_joints) == 32
    values = dict(zip(msg.name, msg.position, strict=True))
    for joint in desc.joints:
        if joint.mimic is not None and joint.type.value != "fixed":
            master = values[joint.mimic.joint]
            assert values[joint.name] == pytest.approx(joint.mimic.multiplier * master + joint.mimic.offset)


def test_zeros_for_unknown_joints_are_said_mimic_ones_silently_ignored(caplog):
    jsp = JointStateLogic(zeros={"m1": 3.0, "fixed_j": 1.0, "typo": 2.0})
    with caplog.at_level(logging.WARNING, "joint_state_publisher"):
        jsp.configure(ROBOT)
    assert [r.getMessage() for r in caplog.records] == [
        "zeros names joint 'typo', which robot 'r' does not have; ignored"]
    assert jsp.message(T0).position[7] == pytest.approx(0.1)  # m1 still follows its master
