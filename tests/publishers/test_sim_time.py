"""robot_state_publisher and joint_state_publisher on the ROS 2 wires with ``--ros-args -p use_sim_time:=true``.

Driven by ``bag play --clock --loop`` of a 1 s recording (rosbags' writer): joint_state_publisher
stamps and paces in /clock's time, so its stamps lie inside the recording, and it carries on
after each loop (rcl's timer restarts on a jump back); robot_state_publisher sees its ROS time
go back at the loop and re-publishes (rclcpp's "Moved backwards in time"), and its /tf_static,
sent before any /clock came, is stamped 0 (rclcpp's ``now()`` in its constructor).
"""

from __future__ import annotations

import itertools
import threading
from collections.abc import Callable
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from livebus import Bus, joined
from recording.bagfiles import NS, Msg, write

from robotmodel.bus import QOS_TF, QOS_TF_STATIC_LISTENER, Node
from robotmodel.msgs import JointState, TFMessage

DIFFBOT = Path(__file__).resolve().parents[2] / "urdf" / "diffbot.urdf.xacro"
T0 = 1_700_000_000 * NS
SPAN = NS  # the recording: 1 s of /tf at 20 Hz


def one_second() -> list[Msg]:
    """A frame far from the robot's, moving in 'world' for 1 s (only there to give the recording its length)."""
    return [Msg("/tf", T0 + k * NS // 20, "tf", [("world", "marker", T0 + k * NS // 20,
                                                  (0.1 * k, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0))]) for k in range(21)]


def stamp_ns(header: Any) -> int:
    return int(header.stamp.sec) * NS + int(header.stamp.nanosec)


def wait(event: threading.Event, timeout: float, what: str, why: Callable[[], object]) -> None:
    assert event.wait(timeout), f"{what} (got {why()})"


@pytest.mark.parametrize("wire", ["dds", "zenoh"])
def test_state_publishers_stamp_and_pace_in_clock_time(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                       wire: str) -> None:
    path = write(tmp_path / "second", "mcap", one_second())
    statics: list[int] = []
    states: list[int] = []
    wheels: list[int] = []  # RSP's /tf stamps of the wheels, which joint_state_publisher's states move
    got_static, looped = threading.Event(), threading.Event()

    def on_static(msg: TFMessage) -> None:
        statics.extend(stamp_ns(t.header) for t in msg.transforms)
        got_static.set()

    def on_tf(msg: TFMessage) -> None:
        for t in msg.transforms:
            if t.child_frame_id == "left_wheel":
                wheels.append(stamp_ns(t.header))
        # /tf went on after the stamps went back (the loop), three times
        back = [i for i in range(1, len(wheels)) if wheels[i] < wheels[i - 1]]
        if back and len(wheels) - back[0] >= 3:
            looped.set()

    with contextmanager(joined)(Bus(tmp_path, wire), monkeypatch) as bus:
        sim = ("--ros-args", "-p", "use_sim_time:=true")
        rsp = bus.robotmodel("robot_state_publisher", str(DIFFBOT), *sim)
        jsp = bus.robotmodel("joint_state_publisher", str(DIFFBOT), *sim)
        with Node("probe") as node:
            node.create_subscription(TFMessage, "/tf_static", on_static, QOS_TF_STATIC_LISTENER)
            node.create_subscription(TFMessage, "/tf", on_tf, QOS_TF)
            node.create_subscription(JointState, "/joint_states", lambda m: states.append(stamp_ns(m.header)), 10)
            wait(got_static, 60, "no /tf_static from robot_state_publisher", lambda: rsp.err[-5:])
            play = bus.robotmodel("bag", "play", str(path), "--clock", "100", "-r", "2", "--loop", "--topics", "/tf")
            wait(looped, 30, "robot_state_publisher's /tf did not go on after the loop",
                 lambda: (wheels[-20:], rsp.err[-5:], jsp.err[-5:], play.err[-5:]))
            play.kill()
        rsp.wait_line("Moved backwards in time, re-publishing joint transforms!", timeout=10, stream="err")
    # Stamped 0: the fixed transforms went out before any /clock (a wall-clock RSP stamps today's date).
    assert statics and set(statics) == {0}, statics
    # joint_state_publisher's stamps are /clock's: inside the recording, not today's wall time, and it
    # published in each pass, 0.1 s of recording apart (10 Hz of ROS time; the wall's would be 0.2 s at -r 2).
    # (/clock may run a tick past a pass's last message on a loaded machine: 0.5 s of slack, far from today)
    assert states and not [s - T0 for s in states if not T0 <= s <= T0 + SPAN + NS // 2], states[:5]
    runs = [b - a for a, b in itertools.pairwise(states) if b > a]
    assert runs and 0.08 <= sum(runs) / len(runs) / NS <= 0.13, runs
    assert sum(1 for a, b in itertools.pairwise(states) if b < a) >= 1  # it went on after a loop
    assert wheels and not [s - T0 for s in wheels if not T0 <= s <= T0 + SPAN + NS // 2]
