"""ROS 2 remaps and parameters on the publisher commands, as real processes on a private bus.

Each test has its own port and ROS_DOMAIN_ID (the ``live`` fixture), waits for conditions with
deadlines and reaps its processes. Expected transforms come from the URDF below by hand.
"""

from __future__ import annotations

import itertools
import math
import statistics
import threading
from pathlib import Path
from typing import Any

import pytest

from robotmodel.bus import QOS_LATCHED, QOS_TF, QOS_TF_STATIC_LISTENER, Node
from robotmodel.msgs import Header, JointState, String, TFMessage, stamp

SEC = 1_000_000_000
T0 = 1_700_000_000 * SEC

# base -(hinge: revolute about y, 0.5 up)-> upper -(tool_mount: fixed, 0.3 along x, yaw 90 deg)-> tool
URDF = """<?xml version="1.0"?>
<robot name="twolink">
  <link name="base"/>
  <link name="upper"/>
  <link name="tool"/>
  <joint name="hinge" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="tool_mount" type="fixed">
    <parent link="upper"/><child link="tool"/>
    <origin xyz="0.3 0 0" rpy="0 0 1.5707963267948966"/>
  </joint>
</robot>
"""


class Inbox:
    """Messages of one subscription, with a wait for a condition on them."""

    def __init__(self, node: Node, msg_type: Any, topic: str, qos: Any) -> None:
        self.items: list[Any] = []
        self._cond = threading.Condition()
        node.create_subscription(msg_type, topic, self._on, qos)

    def _on(self, msg: Any) -> None:
        with self._cond:
            self.items.append(msg)
            self._cond.notify_all()

    def wait(self, predicate: Any, timeout: float = 30.0) -> bool:
        with self._cond:
            return self._cond.wait_for(lambda: predicate(self.items), timeout)


def transforms(msgs: list[Any]) -> list[Any]:
    return [t for m in msgs for t in m.transforms]


def xyz(t: Any) -> tuple[float, float, float]:
    v = t.transform.translation
    return (v.x, v.y, v.z)


def quat(t: Any) -> tuple[float, float, float, float]:
    q = t.transform.rotation
    return (q.x, q.y, q.z, q.w)


def exited(proc: Any, timeout: float = 60.0) -> int:
    code = proc.popen.wait(timeout)
    for reader in proc._readers:
        reader.join(5)
    return int(code)


@pytest.fixture
def urdf(tmp_path: Path) -> Path:
    path = tmp_path / "twolink.urdf"
    path.write_text(URDF)
    return path


def test_rsp_follows_remaps_and_frame_prefix_parameter(live, urdf):
    rsp = live.robotmodel("robot-state-publisher", str(urdf), "--ros-args", "-r", "/joint_states:=/arm/joint_states",
                          "-p", "frame_prefix:=r1/", "-r", "/tf_static:=/r1/tf_static", "-p", "use_sim_time:=false")
    with Node("test_driver") as node:
        tf = Inbox(node, TFMessage, "/tf", QOS_TF)
        static = Inbox(node, TFMessage, "/r1/tf_static", QOS_TF_STATIC_LISTENER)
        pub = node.create_publisher(JointState, "/arm/joint_states", 10)
        assert pub.wait_for_subscriptions(1, timeout=30), rsp.err[-5:]
        # Its one joint_states subscription is the remapped one; its static transforms went to the new topic.
        assert node.count_subscribers("/joint_states") == 0
        assert node.count_publishers("/tf_static") == 0
        q = 0.6
        for i in range(60):  # resent (1 s of stamp apart each, past the rate cap) until one is through
            pub.publish(JointState(header=Header(stamp=stamp(T0 + i * SEC)), name=["hinge"], position=[q]))
            if tf.wait(bool, 0.5):
                break
        assert tf.items, f"nothing on /tf from /arm/joint_states; rsp said {rsp.err[-5:]}"
        moving = transforms(tf.items)[0]
        assert (moving.header.frame_id, moving.child_frame_id) == ("r1/base", "r1/upper")
        assert (moving.header.stamp.sec * SEC + moving.header.stamp.nanosec - T0) % SEC == 0
        assert xyz(moving) == pytest.approx((0.0, 0.0, 0.5), abs=1e-12)
        assert quat(moving) == pytest.approx((0.0, math.sin(q / 2), 0.0, math.cos(q / 2)), abs=1e-12)
        assert static.wait(lambda m: bool(transforms(m)))
        fixed = transforms(static.items)[0]
        assert (fixed.header.frame_id, fixed.child_frame_id) == ("r1/upper", "r1/tool")
        assert xyz(fixed) == pytest.approx((0.3, 0.0, 0.0), abs=1e-12)
        assert quat(fixed) == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)), abs=1e-12)
    assert rsp.stop() == 0
    # use_sim_time is one of RSP's parameters on the ROS 2 wires too (its clock): taken without a warning
    assert not [line for line in rsp.err if "use_sim_time" in line]


def test_rsp_takes_the_robot_from_the_robot_description_parameter(live, urdf):
    rsp = live.robotmodel("robot-state-publisher", "--ros-args", "-p", f"robot_description:={URDF}")
    with Node("test_driver") as node:
        description = Inbox(node, String, "/robot_description", QOS_LATCHED)
        static = Inbox(node, TFMessage, "/tf_static", QOS_TF_STATIC_LISTENER)
        assert description.wait(bool), rsp.err[-5:]
        assert static.wait(lambda m: bool(transforms(m)))
        # The value went through YAML as rcl reads it: a plain scalar's lines fold into one.
        assert description.items[0].data == " ".join(line.strip() for line in URDF.splitlines())
        assert [(t.header.frame_id, t.child_frame_id) for t in transforms(static.items)] == [("upper", "tool")]
    assert rsp.stop() == 0


@pytest.mark.parametrize(("argv", "code", "text"), [
    (["robot-state-publisher", "{urdf}", "--ros-args", "-p", "publish_frequency:=50"], 2,
     "robotmodel robot-state-publisher: error: parameter 'publish_frequency' has invalid type: Wrong parameter "
     "type, parameter {publish_frequency} is of type {double}, setting it to {integer} is not allowed."),
    (["robot-state-publisher", "{urdf}", "--ros-args", "-p", "ignore_timestamp:=1"], 2,
     "robotmodel robot-state-publisher: error: parameter 'ignore_timestamp' has invalid type: Wrong parameter "
     "type, parameter {ignore_timestamp} is of type {bool}, setting it to {integer} is not allowed."),
    (["robot-state-publisher", "{urdf}", "--ros-args", "-p", "publish_frequency:=2000.0"], 1,
     "publish_frequency must be between 0 and 1000"),
    (["robot-state-publisher", "--ros-args", "-p", "robot_description:=''"], 1,
     "robot_description parameter must not be empty"),
    (["robot-state-publisher", "{urdf}", "--ros-args", "-r", "joint_states:=/a/*"], 2,
     "robotmodel robot-state-publisher: error: Couldn't parse remap rule: '-r joint_states:=/a/*'. Error: "),
    (["joint-state-publisher", "{urdf}", "--ros-args", "-p", "rate:=fast"], 2,
     "robotmodel joint-state-publisher: error: parameter 'rate' has invalid type: Wrong parameter type, parameter "
     "{rate} is of type {integer}, setting it to {string} is not allowed."),
    (["joint-state-publisher", "{urdf}", "--ros-args", "-p", "rate:=0"], 2,
     "robotmodel joint-state-publisher: error: rate must be a positive number of Hz, got '0'"),
    (["joint-state-publisher", "{urdf}", "--ros-args", "-p", "source_list:=/a/joint_states"], 2,
     "{source_list} is of type {string_array}, setting it to {string} is not allowed."),
])
def test_bad_parameters_stop_the_command_with_one_line(live, urdf, argv, code, text):
    proc = live.robotmodel(*[w.replace("{urdf}", str(urdf)) for w in argv])
    assert exited(proc) == code
    assert len(proc.err) == 1 and text in proc.err[0], proc.err
    assert "Traceback" not in "\n".join(proc.err)


PARAMS = """\
joint_state_publisher:
  ros__parameters:
    rate: 50
    publish_default_velocities: true
    zeros:
      hinge: 0.25
    dependent_joints:
      x: {parent: hinge}
"""


def test_jsp_params_file_rate_zeros_source_list_and_remap(live, urdf, tmp_path):
    params = tmp_path / "jsp.yaml"
    params.write_text(PARAMS)
    jsp = live.robotmodel("joint-state-publisher", str(urdf), "--ros-args", "--params-file", str(params),
                          "-p", "source_list:=['/src/joint_states']", "-r", "joint_states:=/r2/joint_states")
    with Node("test_driver") as node:
        states = Inbox(node, JointState, "/r2/joint_states", 10)
        assert states.wait(lambda m: len(m) >= 12), jsp.err[-5:]
        first = states.items[0]
        assert list(first.name) == ["hinge"]
        assert list(first.position) == [0.25]   # zeros.hinge from the file
        assert list(first.velocity) == [0.0]    # publish_default_velocities
        stamps = [m.header.stamp.sec * SEC + m.header.stamp.nanosec for m in states.items[:12]]
        # rate 50 (the default would be 10 Hz, 100 ms apart); the median ignores a stalled tick.
        assert statistics.median(b - a for a, b in itertools.pairwise(stamps)) < 0.075 * SEC
        assert node.count_publishers("/joint_states") == 0
        src = node.create_publisher(JointState, "/src/joint_states", 10)
        assert src.wait_for_subscriptions(1, timeout=30)
        for _ in range(60):
            src.publish(JointState(name=["hinge"], position=[0.7]))
            if states.wait(lambda m: list(m[-1].position) == [0.7], 0.5):
                break
        assert list(states.items[-1].position) == [0.7], jsp.err[-5:]
    assert jsp.stop() == 0
    warned = [line for line in jsp.err if "dependent_joints" in line]
    assert len(warned) == 1 and "[WARN]" in warned[0]


def test_jsp_command_line_parameter_after_the_file_wins(live, urdf, tmp_path):
    params = tmp_path / "jsp.yaml"
    params.write_text("/**:\n  ros__parameters:\n    zeros:\n      hinge: 0.25\n")
    jsp = live.robotmodel("joint-state-publisher", str(urdf), "--zeros", "hinge=0.1", "--ros-args",
                          "--params-file", str(params), "-p", "zeros.hinge:=0.5", "-p", "rate:=20")
    with Node("test_driver") as node:
        states = Inbox(node, JointState, "/joint_states", 10)
        assert states.wait(bool), jsp.err[-5:]
        assert list(states.items[0].position) == [0.5]
    assert jsp.stop() == 0


def test_static_transform_publisher_and_tf2_echo_follow_remaps(live):
    # Both parse their own words; the remap takes /tf_static to /r1/tf_static for each of them.
    static = live.robotmodel("static-transform-publisher", "--x", "1.5", "--frame-id", "a", "--child-frame-id", "b",
                             "--ros-args", "-r", "/tf_static:=/r1/tf_static", "-p", "use_sim_time:=true")
    static.wait_line("Spinning until stopped", stream="err")
    with Node("test_driver") as node:
        got = Inbox(node, TFMessage, "/r1/tf_static", QOS_TF_STATIC_LISTENER)
        assert got.wait(lambda m: bool(transforms(m)))
        assert [(t.header.frame_id, t.child_frame_id, xyz(t)) for t in transforms(got.items)] == [
            ("a", "b", (1.5, 0.0, 0.0))]
        assert node.count_publishers("/tf_static") == 0
    echo = live.robotmodel("tf2-echo", "a", "b", "--ros-args", "-r", "/tf_static:=/r1/tf_static")
    echo.wait_line(r"^- Translation: \[1\.500, 0\.000, 0\.000\]$", timeout=30)
    assert echo.stop() == 0 and static.stop() == 0
    assert len([line for line in static.err if "use_sim_time" in line and "[WARN]" in line]) == 1


def test_jsp_gui_takes_joint_state_publishers_parameters(live, urdf):
    gui = live.robotmodel("joint-state-publisher-gui", str(urdf), "--joint", "hinge=0.1", "--port", "0",
                          "--ros-args", "-p", "zeros.hinge:=0.3", "-p", "rate:=50", "-p", "publish_default_efforts:=true",
                          "-r", "joint_states:=/g/joint_states", "-p", "robot_description:=x")
    gui.wait_line(r"^http://127\.0\.0\.1:\d+/", timeout=60)
    with Node("test_driver") as node:
        states = Inbox(node, JointState, "/g/joint_states", 10)
        assert states.wait(lambda m: len(m) >= 12), gui.err[-5:]
        assert [(list(m.position), list(m.effort)) for m in states.items[:3]] == [([0.3], [0.0])] * 3
        stamps = [m.header.stamp.sec * SEC + m.header.stamp.nanosec for m in states.items[:12]]
        assert statistics.median(b - a for a, b in itertools.pairwise(stamps)) < 0.075 * SEC
    assert gui.stop() == 0
    assert len([line for line in gui.err if "'robot_description' is ignored" in line]) == 1
