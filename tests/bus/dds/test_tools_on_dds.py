"""Every live command on the DDS wire: one short chain of real robotmodel processes per command.

Each case starts the processes a user would (``RMW_IMPLEMENTATION=rmw_cyclonedds_cpp`` through
``livebus.Bus(..., "dds")``, its own ROS_DOMAIN_ID, discovery on loopback) and checks what the
command shows. The expected poses come from robotmodel's FK library on the same robot file, or
from the numbers given on the command line; nothing here is on zenoh.
"""

from __future__ import annotations

import math
import re
import signal
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np
import pytest
from conftest import BUNDLED
from livebus import Bus, Proc
from viewerws import State, viewer_state

from robotmodel.kinematics import KinematicModel, KinematicState
from robotmodel.model import load

ARM = BUNDLED / "arm.urdf.xacro"
JOINTS = {"arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.3}
ZEROS = [f"{name}={value}" for name, value in JOINTS.items()]
TRANSLATION = re.compile(r"^- Translation: \[(-?[\d.]+), (-?[\d.]+), (-?[\d.]+)\]$")
QUATERNION = re.compile(r"^- Rotation: in Quaternion \[(-?[\d.]+), (-?[\d.]+), (-?[\d.]+), (-?[\d.]+)\]$")
DEADLINE_S = 40.0


@pytest.fixture
def dds(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Bus]:
    """A DDS bus for the test; every process started on it is reaped."""
    bus = Bus(tmp_path, "dds")
    try:
        yield bus
    finally:
        bus.reap()


def fk_palm() -> np.ndarray:
    """T_world_gripper_palm_link of the arm at :data:`JOINTS`, from robotmodel's FK."""
    return KinematicState(KinematicModel(load(ARM))).update(dict(JOINTS)).link_matrix("gripper_palm_link")


def echoed_pose(echo: Proc, expected: np.ndarray) -> None:
    """Wait until tf2_echo prints ``expected``'s translation (3 decimals, as tf2_echo rounds), then its rotation."""
    want = tuple(f"{v:.3f}" for v in expected[:3, 3])

    def shown() -> bool:
        return any((m := TRANSLATION.match(line)) and tuple(f"{float(g):.3f}" for g in m.groups()) == want
                   for line in echo.out)

    echo.wait_for(shown, DEADLINE_S, f"tf2_echo printing translation {want}")
    quats = [np.array([float(g) for g in m.groups()]) for line in echo.out if (m := QUATERNION.match(line))]
    from robotmodel.spatial import Transform

    q = np.array(Transform.from_matrix(expected).rotation)
    assert any(np.allclose(got, q, atol=6e-4) or np.allclose(got, -q, atol=6e-4) for got in quats), quats


def topic_once(bus: Bus, *args: str) -> str:
    """``robotmodel topic echo ARGS --once``'s stdout (with a deadline)."""
    import subprocess

    done = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "topic", "echo", *args, "--once",
                           "--timeout", str(int(DEADLINE_S))], env=bus.env, cwd=bus.cwd, capture_output=True,
                          text=True, timeout=DEADLINE_S + 20, check=False)
    assert done.returncode == 0, done.stderr
    return done.stdout


def case_static_transform_publisher_tf2_echo_and_view_frames(bus: Bus) -> None:
    static = bus.robotmodel("static_transform_publisher", "--x", "1", "--y", "-2", "--z", "0.5", "--yaw", "0.3",
                            "--frame-id", "map", "--child-frame-id", "odom")
    echo = bus.robotmodel("tf2_echo", "map", "odom")
    expected = np.eye(4)
    expected[:3, :3] = [[math.cos(0.3), -math.sin(0.3), 0], [math.sin(0.3), math.cos(0.3), 0], [0, 0, 1]]
    expected[:3, 3] = (1, -2, 0.5)
    echoed_pose(echo, expected)
    name = static.wait_line(r"\] \[(static_transform_publisher_[0-9A-Za-z]{16})\]: Spinning", stream="err").group(1)
    view = bus.robotmodel("view_frames", "--wait-time", "1", "-o", "tree")
    view.wait_for(lambda: view.popen.poll() is not None, DEADLINE_S, "view_frames exiting")
    assert view.popen.returncode == 0, view.err
    gv = (bus.cwd / "tree.gv").read_text()
    assert re.search(rf'^"map" -> "odom"\[label=" Broadcaster: /{name}\\n', gv, re.M), gv


def case_record(bus: Bus) -> None:
    out = bus.cwd / "rec.mcap"
    rec = bus.robotmodel("record", "-o", str(out), "--flush-interval", "0.2", "/tf", "/tf_static")
    rec.wait_line(r"Subscribed to topic '/tf'", stream="err", timeout=DEADLINE_S)
    bus.robotmodel("robot_state_publisher", str(ARM))
    bus.robotmodel("joint_state_publisher", str(ARM), "--zeros", *ZEROS)
    from mcap.records import Channel, Message
    from mcap.stream_reader import StreamReader

    from robotmodel.recording import load_recording
    from robotmodel.tf import Time

    def tf_messages() -> int:
        # An open recording has no footer yet: read its records as far as they are complete.
        channels: dict[int, str] = {}
        count = 0
        try:
            with out.open("rb") as f:
                for record in StreamReader(f, skip_magic=False).records:
                    if isinstance(record, Channel):
                        channels[record.id] = record.topic
                    elif isinstance(record, Message) and channels.get(record.channel_id) == "/tf":
                        count += 1
        except Exception:  # the first incomplete record ends what is readable now
            pass
        return count

    end = time.monotonic() + DEADLINE_S
    while not (out.exists() and tf_messages() >= 3):
        assert time.monotonic() < end and rec.popen.poll() is None, rec.err[-10:]
        time.sleep(0.2)
    assert rec.stop(signal.SIGINT) == 0, rec.err[-10:]
    # joint_state_publisher sends the zeros from its first message on: every /tf is the FK pose.
    t = load_recording(out, progress=False).buffer.lookup_transform("world", "gripper_palm_link", Time()).transform
    assert np.allclose((t.translation.x, t.translation.y, t.translation.z), fk_palm()[:3, 3], atol=1e-9)


def case_joint_state_publisher_gui_and_topic(bus: Bus) -> None:
    gui = bus.robotmodel("joint_state_publisher_gui", str(ARM), "--joint", "arm_elbow_joint=0.4", "--port", "0")
    gui.wait_line(r"^http://127\.0\.0\.1:\d+/", timeout=DEADLINE_S)
    text = topic_once(bus, "/joint_states", "--flow-style")
    names = re.search(r"\bname: \[([^]]*)\]", text)
    positions = re.search(r"\bposition: \[([^]]*)\]", text)
    assert names and positions, text
    state = dict(zip(names.group(1).split(", "), map(float, positions.group(1).split(", ")), strict=True))
    assert state["arm_elbow_joint"] == 0.4 and state["arm_shoulder_joint"] == 0.0
    # topic list in a new process: the sliders' node is known to the bus by now, the lister
    # still has to discover it within its spin time, so a slow discovery is given another go.
    end = time.monotonic() + DEADLINE_S
    while True:
        lister = bus.robotmodel("topic", "list", "-t", "--spin-time", "1")
        lister.popen.wait(DEADLINE_S)  # it exits on its own after its spin time
        assert lister.stop() == 0, lister.err  # reaped, its output read to the end
        if "/joint_states [sensor_msgs/msg/JointState]" in lister.out or time.monotonic() > end:
            break
    assert "/joint_states [sensor_msgs/msg/JointState]" in lister.out, lister.out


def case_view_follow(bus: Bus) -> None:
    # No FILE: the robot comes from /robot_description, its joints from /joint_states, and the
    # --tf frames from /tf and /tf_static, all on DDS.
    bus.robotmodel("robot_state_publisher", str(ARM))
    bus.robotmodel("joint_state_publisher", str(ARM), "--zeros", *ZEROS)
    view = bus.robotmodel("view", "--follow", "--tf", "--port", "0")
    url = view.wait_line(r"^(http://127\.0\.0\.1:\d+/)", timeout=DEADLINE_S).group(1)

    def followed(state: State) -> bool:
        config, frames = state
        values = {j["name"]: j["value"] for j in config.get("joints", [])}
        palm = frames.get("gripper_palm_link")
        return all(abs(values.get(name, 9.0) - value) < 1e-9 for name, value in JOINTS.items()) and \
            palm is not None and np.allclose(palm, fk_palm(), atol=1e-5)

    config, frames = viewer_state(url, followed)
    assert config["robot"] == "arm" and config["follow"] is True
    assert followed((config, frames)), (config.get("joints"), frames.get("gripper_palm_link"))


def case_launch(bus: Bus) -> None:
    top = bus.cwd / "arm.launch.xml"
    top.write_text(f"""<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="robot_description" value="$(command 'xacro {ARM}')"/>
  </node>
  <node pkg="joint_state_publisher" exec="joint_state_publisher">
    <param name="zeros.arm_shoulder_joint" value="{JOINTS['arm_shoulder_joint']}"/>
    <param name="zeros.arm_elbow_joint" value="{JOINTS['arm_elbow_joint']}"/>
  </node>
</launch>
""")
    bus.robotmodel("launch", "--no-browser", str(top))
    echoed_pose(bus.robotmodel("tf2_echo", "world", "gripper_palm_link"), fk_palm())


# Each command is in at least one chain; robot_state_publisher and joint_state_publisher
# (from FILE) feed record, view and launch, so they have no chain of their own.
CASES: dict[str, Callable[[Bus], None]] = {
    "static_transform_publisher+tf2_echo+view_frames": case_static_transform_publisher_tf2_echo_and_view_frames,
    "joint_state_publisher_gui+topic_echo+list": case_joint_state_publisher_gui_and_topic,
    "record+robot_state_publisher+joint_state_publisher": case_record,
    "view--follow--tf": case_view_follow,
    "launch": case_launch,
}


@pytest.mark.parametrize("case", list(CASES), ids=list(CASES))
def test_a_live_command_works_on_dds(dds: Bus, case: str) -> None:
    CASES[case](dds)
