"""tf2_echo, view_frames and the viewer on the ROS 2 wires with ``--ros-args -p use_sim_time:=true``, from ``bag play
--clock``.

view_frames dates its tree (the legend's ``Recorded at time``) by the node's clock, as tf2_tools'
does with ``node.get_clock().now()``: the recording's time under sim time. The viewer's TF buffer
is cleared when /clock jumps back, as rviz's tf2_ros buffer with the node's clock is, so a looping
replay is drawn again from its start on each pass.
"""

from __future__ import annotations

import itertools
import re
from pathlib import Path

import pytest
from livebus import Bus
from recording.bagfiles import NS, Msg, write
from recording.test_play import T0, drawn_step, drive

SIM = ("--ros-args", "-p", "use_sim_time:=true")


@pytest.mark.parametrize("wire", ["dds", "zenoh"])
def test_view_tf_draws_each_pass_of_a_looping_replay(tmp_path: Path, wire: str) -> None:
    """With sim time the robot goes back to the drive's start on each pass; a wall-clock viewer's buffer
    keeps the first pass's end as its newest transform, and the robot stays there."""
    from viewerws import viewer_state

    diffbot = Path(__file__).resolve().parents[2] / "urdf" / "diffbot.urdf.xacro"
    last = 40  # 2 s of the drive per pass
    msgs = [Msg(m.topic, m.log_ns, m.kind, [(p, "base_footprint", t, pose) for p, _c, t, pose in m.value])
            for m in drive()[1:last + 2]]
    path = write(tmp_path / "drive", "mcap", msgs)
    bus = Bus(tmp_path, wire)
    try:
        view = bus.robotmodel("view", str(diffbot), "--tf", "--fixed-frame", "odom", "--port", "0", *SIM)
        url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
        bus.robotmodel("bag", "play", str(path), "--clock", "100", "--loop")
        # (viewer_state gives the last state it saw when its deadline passes: checked below)
        late = drawn_step(viewer_state(url, lambda s: drawn_step(s[1]) in range(3 * last // 4, last + 1))[1])
        again = drawn_step(viewer_state(url, lambda s: drawn_step(s[1]) in range(last // 4 + 1), timeout=20)[1])
        assert late is not None and again is not None and again <= last // 4 < late, (late, again)
        view.wait_line("Detected jump back in time. Clearing TF buffer.", timeout=10, stream="err")
    finally:
        bus.reap()
    assert not [line for line in view.err if "use_sim_time" in line and "ignored" in line]


@pytest.mark.parametrize("wire", ["dds", "zenoh"])
def test_tf2_echo_view_frames_and_the_sliders_follow_a_looping_clock(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                     wire: str) -> None:
    """tf2_echo's buffer is cleared on each loop, so it prints the replayed transforms again (a wall-clock one
    keeps printing the first pass's last); view_frames dates its tree in /clock's time; joint_state_publisher_gui
    stamps the sliders' states in it."""
    from contextlib import contextmanager

    from livebus import joined
    from recording.test_play import echo_blocks

    from robotmodel.bus import Node
    from robotmodel.msgs import JointState

    diffbot = Path(__file__).resolve().parents[2] / "urdf" / "diffbot.urdf.xacro"
    path = write(tmp_path / "drive", "mcap", drive()[:42])  # /tf_static and 2 s of /tf
    states: list[int] = []

    def went_back() -> bool:
        stamps = [s for s, _ in echo_blocks(list(echo.out))]
        return any(b < a for a, b in itertools.pairwise(stamps))

    with contextmanager(joined)(Bus(tmp_path, wire), monkeypatch) as bus, Node("probe") as node:
        node.create_subscription(JointState, "/joint_states",
                                 lambda m: states.append(m.header.stamp.sec * NS + m.header.stamp.nanosec), 10)
        echo = bus.robotmodel("tf2_echo", "odom", "laser", "5", *SIM)
        gui = bus.robotmodel("joint_state_publisher_gui", str(diffbot), "--port", "0", *SIM)
        gui.wait_line(r"^http://127\.0\.0\.1:\d+/", timeout=120)
        echo.wait_line("Waiting for transform", stream="err")
        play = bus.robotmodel("bag", "play", str(path), "--clock", "100", "-r", "2", "--loop")
        play.wait_line("Playing", timeout=60, stream="err")
        frames = bus.robotmodel("view_frames", "--wait-time", "2", "-o", str(tmp_path / "frames"), *SIM)
        echo.wait_for(went_back, 30, "tf2_echo printing the replay again after a loop")
        echo.wait_line("Detected jump back in time. Clearing TF buffer.", timeout=10, stream="err")
        gui.wait_for(lambda: len(states) >= 5, 20, "five /joint_states from joint_state_publisher_gui")
        assert frames.popen.wait(60) == 0, frames.err[-5:]
    gv = (tmp_path / "frames.gv").read_text()
    recorded = re.search(r'"Recorded at time: ([\d.]+)"', gv)
    # view_frames' date is /clock's: inside the recording's 2 s (a wall-clock one dates it today)
    assert recorded and T0 / NS <= float(recorded[1]) <= T0 / NS + 2.5, gv
    assert '"base_link" -> "laser"' in gv
    assert not [line for line in frames.err + gui.err if "use_sim_time" in line]  # used, not 'ignored here'
    # (/clock may run a tick past a pass's last message on a loaded machine: 0.5 s of slack, far from today)
    assert states and not [s - T0 for s in states if not T0 <= s <= T0 + 2 * NS + NS // 2], states[:5]
