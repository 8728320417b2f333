"""RobotStatePublisher and JointStatePublisher wired on the in-process bus (one process, no sockets)."""

from __future__ import annotations

import itertools
import os
import threading

import numpy as np
import pytest
from conftest import BUNDLED
from tfhelpers import msg_matrix

from robotmodel.bus import QOS_LATCHED, Node
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load
from robotmodel.msgs import JointState, String, TFMessage
from robotmodel.publishers import JointStatePublisher, RobotStatePublisher
from robotmodel.tf import Buffer, Duration, Time
from robotmodel.tf_ros import TransformListener
from robotmodel.time import SimClock

ARM = BUNDLED / "arm.urdf.xacro"
_DOMAINS = itertools.count(150 + os.getpid() % 50)


@pytest.fixture
def node():
    with Node("test_node", backend="inprocess", domain_id=next(_DOMAINS)) as n:
        yield n


def other(node: Node, name: str) -> Node:
    return Node(name, backend="inprocess", domain_id=node.context.domain_id)


def test_arm_through_jsp_rsp_and_a_listener(node):
    desc = load(ARM)
    clock = SimClock(Time(seconds=1000))
    # The listener is up before the robot starts, as in a live system brought up in order.
    with TransformListener(buffer := Buffer(), node), \
            other(node, "rsp_node") as rsp_node, other(node, "jsp_node") as jsp_node, \
            RobotStatePublisher(desc, bus=rsp_node), \
            JointStatePublisher(desc, bus=jsp_node, rate=0, clock=clock) as jsp:
        state = KinematicState(KinematicModel(desc))
        for k, values in enumerate([{"arm_base_joint": 0.3, "arm_elbow_joint": -1.0},
                                    {"arm_shoulder_joint": 0.7, "gripper_left_finger_joint": 0.02}]):
            clock.set(Time(seconds=1000 + k))
            jsp.set(values)
            jsp.publish()
            t = buffer.lookup_transform("world", "gripper_right_finger_link", Time(seconds=1000 + k),
                                        timeout=Duration(seconds=2))
            state.update(jsp.positions())
            np.testing.assert_allclose(msg_matrix(t), state.link_matrix("gripper_right_finger_link"), atol=1e-9)
            assert (t.header.stamp.sec, t.header.stamp.nanosec) == (1000 + k, 0)


def test_late_subscriber_gets_description_and_statics(node):
    desc = load(ARM)
    with other(node, "rsp_node") as rsp_node, RobotStatePublisher(desc, bus=rsp_node, frame_prefix="p/") as rsp:
        got: list[str] = []
        statics: list[TFMessage] = []
        node.create_subscription(String, "/robot_description", lambda m: got.append(m.data), QOS_LATCHED)
        node.create_subscription(TFMessage, "/tf_static", statics.append, QOS_LATCHED)
        assert got == [desc.source_text] == [rsp.description_text]
        assert {(t.header.frame_id, t.child_frame_id) for t in statics[-1].transforms} == {
            ("p/world", "p/arm_base_link"), ("p/arm_wrist_yaw_link", "p/gripper_palm_link")}


def test_jsp_without_description_follows_robot_description(node):
    desc = load(ARM)
    got: list[JointState] = []
    arrived = threading.Event()
    with other(node, "jsp_node") as jsp_node, JointStatePublisher(bus=jsp_node, rate=0) as jsp:
        node.create_subscription(JointState, "/joint_states", got.append, 10)
        assert jsp.publish() is None  # no robot yet
        jsp.add_robot_description_callback(arrived.set)
        with other(node, "rsp_node") as rsp_node, RobotStatePublisher(desc, bus=rsp_node) as rsp:
            assert arrived.wait(2)
            assert jsp.publish().name[0] == "arm_base_joint"
            two = desc.source_text.replace('name="arm_base_joint"', 'name="turret"').replace(
                'joint="arm_base_joint"', 'joint="turret"')
            rsp.set_description(two)
            assert jsp.publish().name[0] == "turret"
        assert [m.name[0] for m in got] == ["arm_base_joint", "turret"]


def test_source_list_merges_latest_value(node):
    desc = load(ARM)
    with other(node, "jsp_node") as jsp_node, \
            JointStatePublisher(desc, bus=jsp_node, rate=0, source_list=["/a", "/b"]) as jsp:
        pa = node.create_publisher(JointState, "/a", 10)
        pb = node.create_publisher(JointState, "/b", 10)
        pa.publish(JointState(name=["arm_base_joint", "arm_elbow_joint"], position=[0.1, 0.2]))
        pb.publish(JointState(name=["arm_elbow_joint"], position=[0.5]))
        msg = jsp.publish()
        values = dict(zip(msg.name, msg.position, strict=True))
        assert (values["arm_base_joint"], values["arm_elbow_joint"]) == (0.1, 0.5)


def test_timer_publishes_at_the_rate(node):
    desc = load(ARM)
    got: list[JointState] = []
    enough = threading.Event()

    def on(msg: JointState) -> None:
        got.append(msg)
        if len(got) >= 5:
            enough.set()

    node.create_subscription(JointState, "/joint_states", on, 10)
    with other(node, "jsp_node") as jsp_node, JointStatePublisher(desc, bus=jsp_node, rate=50):
        assert enough.wait(5)
    stamps = [m.header.stamp.sec * 10**9 + m.header.stamp.nanosec for m in got[:5]]
    gaps = np.diff(stamps) / 1e9
    assert np.all(gaps > 0.005) and np.median(gaps) == pytest.approx(0.02, abs=0.01)
