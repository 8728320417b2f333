"""robot-state-publisher and joint-state-publisher as real processes on a private loopback bus.

Every test has its own rendezvous port and ROS_DOMAIN_ID (the ``live`` fixture), waits
for conditions with deadlines, and reaps every process it started.
"""

from __future__ import annotations

import json
import random
import signal
import subprocess
import sys
import threading
import time
from typing import Any

import numpy as np
import pytest
from conftest import BUNDLED, ERD_ROBOTS

from robotmodel.bus import QOS_TF, Node
from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import JointType, load
from robotmodel.msgs import Header, JointState, TFMessage, stamp

ARM = BUNDLED / "arm.urdf.xacro"
TALOS = ERD_ROBOTS / "talos_data/robots/talos_full_v2.urdf"
SEC = 1_000_000_000
T0 = 1_700_000_000 * SEC

# A xacro document with an argument, to check FILE + name:=value end to end.
PREFIXED = """<?xml version="1.0"?>
<robot name="twolink" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="p" value="$(arg prefix)"/>
  <link name="${p}base"/><link name="${p}upper"/><link name="${p}tool"/>
  <joint name="${p}hinge" type="revolute"><parent link="${p}base"/><child link="${p}upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="${p}tool_mount" type="fixed"><parent link="${p}upper"/><child link="${p}tool"/>
    <origin xyz="0.3 0 0" rpy="0 0 1.5707963267948966"/></joint>
</robot>
"""


def records(proc: Any) -> list[dict[str, Any]]:
    out = []
    for line in list(proc.out):
        if line.startswith("{"):
            out.append(json.loads(line))
    return out


def wait_record(proc: Any, predicate: Any, timeout: float, what: str) -> dict[str, Any]:
    found: list[dict[str, Any]] = []

    def check() -> bool:
        for line in proc.out:
            if line.startswith("{"):
                rec = json.loads(line)
                if predicate(rec):
                    found.append(rec)
                    return True
        return False

    proc.wait_for(check, timeout, what)
    return found[0]


def stop_ok(*procs: Any) -> None:
    for proc in procs:
        assert proc.stop(signal.SIGTERM) == 0, proc.err[-10:]


def send_until_seen(pub: Any, values: dict[str, float], listener: Any, timeout: float = 30.0) -> dict[str, Any]:
    """Send ``values`` on the source topic until the listener reports a lookup made with them.

    Resent because joint_state_publisher, like ROS's, resets every value when a robot
    description arrives, and robot-state-publisher's may arrive after the first send.
    """
    msg = JointState(name=list(values), position=[float(v) for v in values.values()])
    found: list[dict[str, Any]] = []

    def seen() -> bool:
        found[:] = [r for r in records(listener)
                    if "positions" in r and all(r["positions"].get(n) == x for n, x in values.items())][:1]
        return bool(found)

    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        pub.publish(msg)
        with listener._cond:  # woken by each line the listener prints; resend every 0.5 s
            if listener._cond.wait_for(seen, 0.5):
                return found[0]
    pytest.fail(f"no lookup with {values}; listener said {listener.out[-5:]} {listener.err[-5:]}")


def test_arm_listener_lookup_equals_fk_and_tf_stamps_are_joint_state_stamps(live):
    link = "gripper_right_finger_link"  # behind a fixed joint and a mimic joint
    listener = live.listener("lookups", "world", link)
    listener.wait_line('"ready"')
    rsp = live.robotmodel("robot-state-publisher", str(ARM))
    jsp = live.robotmodel("joint-state-publisher", str(ARM), "--source-list", "/test_source")
    model = KinematicModel(load(ARM))
    state = KinematicState(model)
    rng = random.Random(11)
    configs = [{n: rng.uniform(lo, hi) for n, lo, hi in zip(model.variables, model.lower, model.upper, strict=True)}
               for _ in range(4)]
    with Node("test_source") as node:
        pub = node.create_publisher(JointState, "/test_source", 10)
        assert pub.wait_for_subscriptions(1, timeout=30)
        for values in configs:
            rec = send_until_seen(pub, values, listener)
            state.update(values)
            np.testing.assert_allclose(rec["matrix"], state.link_matrix(link), atol=1e-9, rtol=0)
            assert rec["lookup_stamp"] == rec["stamp"]
    done = records(listener)
    assert len([r for r in done if "stamp" in r]) >= 4
    # Every /tf stamp was the stamp of a joint state that joint-state-publisher sent.
    assert [r for r in done if "unmatched" in r] == []
    stop_ok(rsp, jsp, listener)


def test_talos_every_link_reachable_fixed_links_only_from_tf_static(live):
    desc = load(TALOS)
    assert len(desc.joints) >= 30 and any(link.visuals for link in desc.links)
    listener = live.listener("reach", desc.root, str(len(desc.links)))
    listener.wait_line('"ready"')
    rsp = live.robotmodel("robot-state-publisher", str(TALOS))
    jsp = live.robotmodel("joint-state-publisher", str(TALOS))
    rec = wait_record(listener, lambda r: "reachable" in r, 60, "every Talos link reachable")
    assert set(rec["reachable"]) == {link.name for link in desc.links}
    fixed = {j.child for j in desc.joints if j.type is JointType.FIXED}
    moving = {j.child for j in desc.joints if j.type is not JointType.FIXED}
    assert set(rec["tf_static"]) == fixed
    assert set(rec["tf"]) == moving
    stop_ok(rsp, jsp, listener)


@pytest.mark.parametrize("robot", ["twolink", "talos"])
def test_late_joiner_gets_the_xacro_output_byte_for_byte_and_every_static(live, tmp_path, robot):
    if robot == "talos":
        source, args = TALOS, []
    else:
        source, args = tmp_path / "twolink.urdf.xacro", ["prefix:=left_"]
        source.write_text(PREFIXED)
    expected = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "xacro", str(source), *args],
                              capture_output=True, check=True).stdout
    desc = load(source, dict(a.split(":=") for a in args))
    statics = sorted((j.parent, j.child) for j in desc.joints if j.type is JointType.FIXED)
    rsp = live.robotmodel("robot-state-publisher", *args, str(source))
    rsp.wait_line(r"\[INFO\] \[\d+\.\d{9}\] \[robot_state_publisher\]: Robot initialized", stream="err")
    # The scenario itself: a process that starts two seconds after robot-state-publisher.
    time.sleep(2.0)
    late = live.listener("late")
    # Its start-up alone (imports, session) can take several seconds on a loaded machine.
    rec = wait_record(late, lambda r: "description" in r, 60, "latched description and statics")
    assert rec["description"].encode() == expected
    assert [tuple(p) for p in rec["static"]] == statics
    assert len(statics) == (1 if robot == "twolink" else 15)
    stop_ok(rsp, late)


def test_frame_prefix_on_every_frame(live):
    desc = load(ARM)
    listener = live.listener("reach", "r1/world", str(len(desc.links)))
    listener.wait_line('"ready"')
    rsp = live.robotmodel("robot-state-publisher", str(ARM), "--frame-prefix", "r1/")
    jsp = live.robotmodel("joint-state-publisher", str(ARM))
    rec = wait_record(listener, lambda r: "reachable" in r, 30, "prefixed arm tree")
    assert set(rec["reachable"]) == {f"r1/{link.name}" for link in desc.links}
    assert all(f.startswith("r1/") for f in rec["tf"] + rec["tf_static"])
    stop_ok(rsp, jsp, listener)


class TfRecorder:
    """The test process's own /tf subscription: stamps received, and a wait for one."""

    def __init__(self, node: Node) -> None:
        self.stamps: list[int] = []
        self.frames: list[str] = []
        self._cond = threading.Condition()
        node.create_subscription(TFMessage, "/tf", self._on, QOS_TF)

    def _on(self, msg: TFMessage) -> None:
        with self._cond:
            for t in msg.transforms:
                self.stamps.append(t.header.stamp.sec * SEC + t.header.stamp.nanosec)
                self.frames.append(t.child_frame_id)
            self._cond.notify_all()

    def wait(self, predicate: Any, timeout: float = 20.0) -> bool:
        with self._cond:
            return self._cond.wait_for(lambda: predicate(self.stamps), timeout)


def joint_state(names: list[str], positions: list[float], stamp_ns: int) -> JointState:
    return JointState(header=Header(stamp=stamp(stamp_ns)), name=names, position=positions)


def send_when_heard(node: Node) -> Any:
    pub = node.create_publisher(JointState, "/joint_states", 10)
    assert pub.wait_for_subscriptions(1, timeout=30)
    return pub


@pytest.mark.parametrize("ignore", [False, True])
def test_ignore_timestamp(live, ignore):
    args = ["robot-state-publisher", str(ARM)] + (["--ignore-timestamp"] if ignore else [])
    rsp = live.robotmodel(*args)
    with Node("test_driver") as node:
        tf = TfRecorder(node)
        pub = send_when_heard(node)
        for _ in range(5):
            pub.publish(joint_state(["arm_base_joint"], [0.1], 0))
        # A stamped message after them: once it is through, the unstamped ones have been handled.
        pub.publish(joint_state(["arm_base_joint"], [0.2], T0))
        assert tf.wait(lambda s: T0 in s)
        if ignore:
            assert tf.stamps == [0, 0, 0, 0, 0, T0]
        else:
            assert tf.stamps == [T0]
            rsp.wait_line("joint states stamped 0 are never published", stream="err")
    stop_ok(rsp)
    zero_warnings = [line for line in rsp.err if "stamped 0" in line]
    assert len(zero_warnings) == (0 if ignore else 1)


def test_bad_joint_states_are_said_once_and_rsp_keeps_running(live):
    rsp = live.robotmodel("robot-state-publisher", str(ARM))
    step = SEC // 10  # 100 ms apart: the 20 Hz cap lets each one through
    with Node("test_driver") as node:
        tf = TfRecorder(node)
        pub = send_when_heard(node)
        k = 0
        for _ in range(20):
            k += 1
            pub.publish(joint_state(["ghost", "arm_base_joint"], [1.0, 0.1], T0 + k * step))
            k += 1
            pub.publish(joint_state(["arm_elbow_joint", "arm_base_joint"], [float("nan"), 0.1], T0 + k * step))
            k += 1
            pub.publish(joint_state(["arm_elbow_joint", "arm_base_joint"], [0.5], T0 + k * step))
            k += 1
            pub.publish(joint_state(["arm_elbow_joint", "arm_base_joint"], [], T0 + k * step))
        for _ in range(3):  # bytes that are no JointState at all
            pub.publish_raw(b"\x00\x01\x00\x00" + b"\xff" * 12)
        last = T0 + (k + 1) * step
        pub.publish(joint_state(["arm_elbow_joint", "arm_base_joint"], [0.3, 0.4], last))
        assert tf.wait(lambda s: last in s)
        assert rsp.popen.poll() is None
        # Bad lengths publish nothing; unknown names and NaN leave out only what they concern.
        assert len(tf.stamps) == 20 + 20 + 2
        assert "arm_fore_link" not in tf.frames[:-2]
    stop_ok(rsp)
    err = rsp.err
    expected_once = [
        "joint_states names joint(s) that robot 'arm' lacks, ignored: ghost",
        "joint 'arm_elbow_joint' has a non-finite position (nan)",
        "[ERROR]",
        'Robot state publisher ignored a JointState message about joint(s) "arm_elbow_joint"(,...) '
        "whose position member was empty.",
        "dropped a message on '/joint_states' that does not decode as sensor_msgs/msg/JointState",
    ]
    for text in expected_once:
        assert len([line for line in err if text in line]) == 1, (text, err)
    assert len([line for line in err if "[WARN]" in line or "[ERROR]" in line]) == 5, err


def test_jsp_without_file_follows_robot_description(live, tmp_path):
    source = tmp_path / "twolink.urdf.xacro"
    source.write_text(PREFIXED)
    names = live.listener("names")
    names.wait_line('"ready"')
    jsp = live.robotmodel("joint-state-publisher", "--rate", "20")
    jsp.wait_line(r"\[INFO\] .* \[joint_state_publisher\]: Waiting for robot_description to be published on "
                  r"the robot_description topic\.\.\.", stream="err")
    rsp = live.robotmodel("robot-state-publisher", str(ARM))
    arm_joints = [j.name for j in load(ARM).joints if j.type is not JointType.FIXED]
    wait_record(names, lambda r: r["names"] == arm_joints if "names" in r else False, 30, "arm joint states")
    stop_ok(rsp)
    rsp2 = live.robotmodel("robot-state-publisher", str(source), "prefix:=right_")
    rec = wait_record(names, lambda r: r.get("names") == ["right_hinge"], 30, "the new robot's joint states")
    assert rec["position"] == [0.0]
    assert jsp.popen.poll() is None
    stop_ok(rsp2, jsp, names)
