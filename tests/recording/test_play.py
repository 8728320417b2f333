"""``robotmodel bag play``: every format onto the bus with its types, latching, topic selection and offset;
``--clock`` driving a tf2_echo with ROS 2's ``use_sim_time`` that prints what ``tf2_echo --bag --time`` says."""

from __future__ import annotations

import contextlib
import itertools
import math
import re
import sys
import threading
import time
from pathlib import Path
from typing import Any

import pytest
from livebus import Bus
from recording.bagfiles import NS, Msg, write
from robotmodel.cli.main import main

from robotmodel.bus import QOS_TF_STATIC_LISTENER, Node
from robotmodel.msgs import typestore
from robotmodel.recording import Player, PlayOptions, Recording

T0 = 1_700_000_000 * NS
STEPS = 121  # /tf at 20 Hz over 6 s of recording


def drive() -> list[Msg]:
    """A robot driving in odom (x = 0.05 k, yaw = 0.01 k) with a laser fixed on it, as /tf and /tf_static."""
    msgs = [Msg("/tf_static", T0, "tf", [("base_link", "laser", T0, (0.2, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0))])]
    for k in range(STEPS):
        t, yaw = T0 + k * NS // 20, 0.01 * k
        msgs.append(Msg("/tf", t, "tf", [("odom", "base_link", t,
                                          (0.05 * k, 0.0, 0.0, 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)))]))
    return msgs


def play_inprocess(path: Path, options: PlayOptions, domain: int) -> dict[str, list[Any]]:
    """Play ``path`` on the in-process wire; what a subscriber there got, decoded, by topic (+ late /tf_static)."""
    got: dict[str, list[Any]] = {"/tf": [], "/tf_static": [], "/clock": [], "late /tf_static": []}
    store = typestore()

    def keep(key: str) -> Any:
        return lambda m: got[key].append(store.deserialize_cdr(m.payload, m.typename))

    with Node("sub", backend="inprocess", domain_id=domain) as node, Recording(path) as rec:
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", keep("/tf"), 100, raw=True)
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf_static", keep("/tf_static"), QOS_TF_STATIC_LISTENER,
                                 raw=True)
        node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", keep("/clock"), 10, raw=True)
        Player(rec, node, options).play(threading.Event())
        # A subscriber after the end still gets the latched /tf_static, as from tf2's static broadcaster.
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf_static", keep("late /tf_static"),
                                 QOS_TF_STATIC_LISTENER, raw=True)
    return got


@pytest.mark.parametrize("fmt", ["ros1", "db3_folder", "mcap_folder", "mcap"])
def test_every_format_plays_types_latching_selection_and_offset(tmp_path: Path, fmt: str) -> None:
    path = write(tmp_path / "drive", fmt, drive())
    got = play_inprocess(path, PlayOptions(rate=20.0, start_offset_ns=3 * NS, clock_hz=50.0), 150)
    # --start-offset 3 s: /tf from k = 60 on, as written; the /tf_static at t0 is before it and not played.
    xs = [m.transforms[0].transform.translation.x for m in got["/tf"]]
    assert xs == pytest.approx([0.05 * k for k in range(60, STEPS)])
    assert got["/tf_static"] == [] and got["late /tf_static"] == []
    clocks = [m.clock.sec * NS + m.clock.nanosec for m in got["/clock"]]
    assert clocks and clocks == sorted(clocks) and clocks[0] >= T0 + 3 * NS and clocks[-1] <= T0 + 6 * NS

    got = play_inprocess(path, PlayOptions(rate=50.0, topics=("/tf_static",)), 151)
    assert got["/tf"] == [] and got["/clock"] == []
    (late,) = got["late /tf_static"]
    assert late.transforms[0].child_frame_id == "laser" and late.transforms[0].transform.translation.z == 0.3


def test_clock_never_runs_ahead_of_the_message_to_play(tmp_path: Path) -> None:
    """A player held up (here by a subscriber that blocks the in-process delivery for 0.3 s, 6 s of
    recording at -r 20) sends /clock no later than the next recorded message, never past the end."""
    path = write(tmp_path / "drive", "mcap", drive())
    ticks: list[int] = []
    order: list[tuple[str, int]] = []
    stalled = threading.Event()

    def on_tf(m: Any) -> None:
        t = m.transforms[0].header.stamp
        order.append(("tf", t.sec * NS + t.nanosec))
        if not stalled.is_set():
            stalled.set()
            time.sleep(0.3)  # the player's thread delivers this: it is held up as by a loaded machine

    def on_clock(m: Any) -> None:
        ns = m.clock.sec * NS + m.clock.nanosec
        ticks.append(ns)
        order.append(("clock", ns))

    with Node("sub", backend="inprocess", domain_id=153) as node, Recording(path) as rec:
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", on_tf, 1000)
        node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", on_clock, 1000)
        Player(rec, node, PlayOptions(rate=20.0, clock_hz=50.0, topics=("/tf",))).play(threading.Event())
    assert stalled.is_set() and ticks and max(ticks) <= T0 + (STEPS - 1) * NS // 20
    # Each tick is at most the time of the /tf message played after it.
    for (kind, ns), later in itertools.pairwise(order):
        if kind == "clock" and later[0] == "tf":
            assert ns <= later[1], (ns, later)


def test_loop_plays_again(tmp_path: Path) -> None:
    path = write(tmp_path / "drive", "mcap", drive()[:5])
    stop = threading.Event()
    seen: list[float] = []

    def on_tf(m: Any) -> None:
        seen.append(m.transforms[0].transform.translation.x)
        if len(seen) >= 9:
            stop.set()

    with Node("sub", backend="inprocess", domain_id=152) as node, Recording(path) as rec:
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", on_tf, 100)
        Player(rec, node, PlayOptions(rate=10.0, loop=True, topics=("/tf",))).play(stop)
    assert seen[:9] == pytest.approx([0.0, 0.05, 0.1, 0.15] * 2 + [0.0])


@pytest.mark.parametrize(("words", "needle"), [
    (["bag", "play", "nothere.mcap"], "robotmodel bag: error: nothere.mcap: cannot read"),
    (["rosbag", "play", "nothere.bag"], "robotmodel rosbag: error: nothere.bag: cannot read"),  # ROS 1's word
    (["bag", "play", "DRIVE", "--topics", "/odom"], "no topic /odom in the recording (it has /tf, /tf_static)"),
    (["bag", "play", "DRIVE", "-r", "0"], "rate must be a positive number"),
])
def test_bad_input_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
                               words: list[str], needle: str) -> None:
    monkeypatch.chdir(tmp_path)
    path = write(tmp_path / "drive", "mcap", drive()[:3])
    code = main([str(path) if w == "DRIVE" else w for w in words])
    err = capsys.readouterr().err
    assert code != 0 and needle in err and len(err.strip().splitlines()) == 1, err


def echo_blocks(lines: list[str]) -> list[tuple[int, list[str]]]:
    """tf2_echo's printouts: (stamp ns, the lines after 'At time')."""
    out: list[tuple[int, list[str]]] = []
    for i, line in enumerate(lines):
        m = re.fullmatch(r"At time (\d+)\.(\d+)", line)
        if m and i + 8 < len(lines):
            # tf2_echo prints sec.nanosec with the nanoseconds unpadded, as ROS does.
            out.append((int(m[1]) * NS + int(m[2]), lines[i + 1:i + 9]))
    return out


@pytest.mark.parametrize("wire", ["dds", "zenoh"])
def test_play_clock_drives_sim_time_tf2_echo_as_bag_echo_says(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                                wire: str) -> None:
    path = write(tmp_path / "drive", "mcap", drive())
    bus = Bus(tmp_path, wire)
    try:
        echo = bus.robotmodel("tf2_echo", "odom", "laser", "--ros-args", "-p", "use_sim_time:=true")
        echo.wait_line("Waiting for transform", stream="err")
        play = bus.robotmodel("bag", "play", str(path), "--clock", "100", "-r", "2")
        play.wait_line("Playback finished", timeout=60, stream="err")
        assert play.popen.wait(30) == 0  # it ends by itself at the recording's end
        echo.stop()
    finally:
        bus.reap()
    assert not [line for line in echo.err if "use_sim_time" in line]  # used, not 'ignored here'
    blocks = echo_blocks(echo.out)
    assert len(blocks) >= 3, echo.out
    # The first printout comes when the transform does; from then on tf2_echo sleeps 1 s of ROS time: with sim time at rate 2 its printouts are ~1 s of recording apart
    # (a wall-clock tf2_echo would print them ~2 s apart).
    gaps = [(b[0] - a[0]) / NS for a, b in itertools.pairwise(blocks[1:])]
    assert gaps and all(0.8 <= g <= 1.25 for g in gaps), gaps
    for stamp, live in blocks:
        t = f"{stamp // NS}.{stamp % NS:09d}"
        assert main(["tf2_echo", "odom", "laser", "--bag", str(path), "--time", t, "--no-progress"]) == 0
        assert echo_blocks(capsys.readouterr().out.splitlines()) == [(stamp, live)]


ECHO_PY = Path("/usr/lib/tf2_tools/echo.py")


@pytest.mark.parametrize("fmt", ["ros1", "mcap"])
def test_play_clock_on_ros1_drives_the_real_echo_py_in_sim_time(tmp_path: Path, ros1: Any, fmt: str,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    from ros1helpers import SYSTEM_PYTHON, wait_until

    if not ECHO_PY.exists():
        pytest.skip(f"{ECHO_PY} is absent")
    path = write(tmp_path / "drive", fmt, drive())  # a .bag as it is; an MCAP's CDR converted to ROS 1
    ros1.node("setter").params.set_param("/use_sim_time", True)
    echo = ros1.start(SYSTEM_PYTHON, str(ECHO_PY), "odom", "laser", "-p", "6")
    wait_until(lambda: any(topic == "/clock" for topic, _ in ros1.master.get_system_state()[1]), 60,
               "echo.py's /clock subscription")
    ros1.env["ROS_VERSION"] = "1"
    play = ros1.start(sys.executable, "-m", "robotmodel.cli.main", "bag", "play", str(path), "--clock", "-r", "2")
    play.wait_line("Playback finished", 60)
    printed = [(m[1], float(m[2])) for line in echo.lines
               if (m := re.match(r"At time (\S+), \(current time (\S+)\)", line))]
    assert len(printed) >= 3, echo.lines[-20:]
    # rospy's time is /clock's: inside the recording (2023), not the wall clock's now
    assert all(T0 / NS <= now <= T0 / NS + 6.1 for _, now in printed), printed
    stamp = printed[-2][0]  # as echo.py prints it: to_sec()'s shortest repr, exact in decimal
    i = next(i for i, line in enumerate(echo.lines) if line.startswith(f"At time {stamp},"))
    live = [float(v) for v in re.findall(r"-?\d+\.\d+", echo.lines[i + 1] + echo.lines[i + 2])]
    assert main(["tf2_echo", "odom", "laser", "--bag", str(path), "--time", stamp, "--no-progress"]) == 0
    (block,) = echo_blocks(capsys.readouterr().out.splitlines())
    sec, _, frac = stamp.partition(".")
    assert block[0] == int(sec) * NS + int(frac.ljust(9, "0"))
    from_bag = [float(v) for v in re.findall(r"-?\d+\.\d+", block[1][0] + block[1][1])]
    assert live == pytest.approx(from_bag, abs=6e-4)  # tf2_echo prints 3 decimals, echo.py 6


@pytest.mark.parametrize(("words", "clock", "rate", "offset_ns", "topics", "loop"), [
    ([], None, 1.0, 0, (), False),
    (["--clock"], 40.0, 1.0, 0, (), False),  # rosbag2's default
    (["--clock", "100", "-r", "0.5", "--start-offset", "1.25", "-l"], 100.0, 0.5, 1_250_000_000, (), True),
    (["--clock", "--hz=200", "-s", "2", "--loop"], 200.0, 1.0, 2 * NS, (), True),  # rosbag play's spellings
    (["--rate", "3", "--topics", "/tf", "tf_static"], None, 3.0, 0, ("/tf", "/tf_static"), False),
])
def test_play_words(words: list[str], clock: float | None, rate: float, offset_ns: int, topics: tuple[str, ...],
                    loop: bool) -> None:
    from robotmodel.cli.bag_cmd import play_options
    from robotmodel.cli.main import build_parser

    options = play_options(build_parser().parse_args(["bag", "play", "F", *words]))
    assert options == PlayOptions(rate=rate, loop=loop, start_offset_ns=offset_ns, topics=topics, clock_hz=clock)


def drawn_step(frames: dict[str, Any]) -> int | None:
    """The drive's step k whose recorded pose base_footprint is drawn at (None: not drawn, or not a recorded pose)."""
    m = frames.get("base_footprint")
    if m is None:
        return None
    k = round(m[0, 3] / 0.05)
    yaw = 0.01 * k
    recorded = [[math.cos(yaw), -math.sin(yaw), 0.05 * k], [math.sin(yaw), math.cos(yaw), 0.0]]
    return k if 0 <= k < STEPS and bool((abs(m[:2, [0, 1, 3]] - recorded) < 1e-5).all()) else None


def test_view_tf_replays_the_drive(tmp_path: Path) -> None:
    """``view --tf`` with ``use_sim_time`` draws the drive played with ``--clock``: base_footprint in odom at
    recorded poses, moving as recorded; a screenshot shows the robot where the drive ends."""
    from viewerhelpers import HIDE_HELPERS, READY, grey_points, robot_fraction
    from viewerws import viewer_state

    from robotmodel.model import load
    from robotmodel.viewer import Browser

    diffbot = Path(__file__).resolve().parents[2] / "urdf" / "diffbot.urdf.xacro"
    msgs = [Msg(m.topic, m.log_ns, m.kind, [(p, "base_footprint", t, pose) for p, _c, t, pose in m.value])
            for m in drive() if m.topic == "/tf"]
    path = write(tmp_path / "drive", "mcap", msgs)
    bus = Bus(tmp_path, "zenoh")

    try:
        view = bus.robotmodel("view", str(diffbot), "--tf", "--fixed-frame", "odom", "--track", "base_footprint",
                              "--port", "0", "--ros-args", "-p", "use_sim_time:=true")
        url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
        looping = bus.robotmodel("bag", "play", str(path), "--loop", "-r", "2", "--clock")
        first = drawn_step(viewer_state(url, lambda s: drawn_step(s[1]) is not None)[1])
        later = drawn_step(viewer_state(url, lambda s: drawn_step(s[1]) not in (None, first))[1])
        assert first is not None and later is not None and later != first
        looping.kill()
        # The last second once more, so that the robot stays where the drive ends (k = STEPS - 1) for the screenshot.
        bus.robotmodel("bag", "play", str(path), "--start-offset", "5.5", "-r", "2", "--clock").wait_line(
            "Playback finished", timeout=60, stream="err")
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.evaluate(HIDE_HELPERS)
            browser.wait_for("""(() => { const m = viewer.scene_tree.find(["robot"]).object.matrix;
                return Math.abs(m.elements[12] - 6.0) < 1e-6; })()""", timeout=30)
            png = browser.screenshot()
            (tmp_path / "replay.png").write_bytes(png)  # kept for a look when this fails
            hits, grey_corners = robot_fraction(browser, png, grey_points(load(diffbot), {}))
    finally:
        bus.reap()
    # The robot is drawn where the drive ended, in the middle of a tracking camera's view.
    assert hits >= 0.7 and grey_corners == 0.0, (hits, grey_corners)


def test_ctrl_c_ends_a_looping_play(tmp_path: Path) -> None:
    import signal

    path = write(tmp_path / "drive", "ros1", drive()[:5])
    bus = Bus(tmp_path, "zenoh")
    try:
        play = bus.robotmodel("bag", "play", str(path), "--loop", "--clock")
        play.wait_line("Playing", timeout=60, stream="err")
        assert play.stop(signal.SIGINT, timeout=10) == 0
    finally:
        bus.reap()
    assert any("Playback finished" in line for line in play.err), play.err


def test_delay_sleeps_before_each_pass(tmp_path: Path) -> None:
    path = write(tmp_path / "drive", "mcap", drive()[:3])  # /tf at 0 and 0.05 s of recording
    stop = threading.Event()
    arrivals: list[float] = []

    def on_tf(_m: Any) -> None:
        arrivals.append(time.monotonic())
        if len(arrivals) >= 4:
            stop.set()

    with Node("sub", backend="inprocess", domain_id=153) as node, Recording(path) as rec:
        node.create_subscription("tf2_msgs/msg/TFMessage", "/tf", on_tf, 100)
        player = Player(rec, node, PlayOptions(loop=True, topics=("/tf",), delay_ns=400_000_000))
        start = time.monotonic()
        player.play(stop)
    # Each pass (0.05 s of recording at rate 1) waits 0.4 s first: a gap of >= 0.4 s before each pass's first message.
    assert arrivals[0] - start >= 0.4
    assert arrivals[2] - arrivals[1] >= 0.4
    assert arrivals[1] - arrivals[0] < 0.4


def test_remap_renames_what_is_played(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = write(tmp_path / "drive", "mcap", drive()[:6])  # /tf_static and 5 /tf
    bus = Bus(tmp_path, "zenoh")
    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "RMW_IMPLEMENTATION"):
        monkeypatch.setenv(key, bus.env[key])
    got: dict[str, list[Any]] = {"/tf": [], "/replayed/tf": [], "/tf_static": []}
    try:
        with Node("sub") as node:
            for topic, items in got.items():
                node.create_subscription("tf2_msgs/msg/TFMessage", topic, items.append, QOS_TF_STATIC_LISTENER)
            # The delay gives the player's session time to meet this subscriber, as rosbag play's -d is for.
            play = bus.robotmodel("bag", "play", str(path), "--remap", "/tf:=/replayed/tf", "-d", "1", "-r", "5")
            play.wait_line("Playback finished", timeout=60, stream="err")
            assert play.popen.wait(30) == 0
    finally:
        bus.reap()
    assert any(line.endswith("[rosbag2_player]: Sleep 1000000000 ns") for line in play.err), play.err
    assert got["/tf"] == []
    assert [m.transforms[0].transform.translation.x for m in got["/replayed/tf"]] == pytest.approx(
        [0.05 * k for k in range(5)])
    assert len(got["/tf_static"]) == 1  # not named by the rule: played under its own name


@pytest.mark.parametrize(("words", "needle"), [
    (["--remap", "/tf"], "--remap '/tf': "),
    (["-d", "0"], "argument -d/--delay: invalid positive_float value: '0'"),
])
def test_bad_remap_or_delay_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str], words: list[str],
                                        needle: str) -> None:
    path = write(tmp_path / "drive", "mcap", drive()[:3])
    with pytest.raises(SystemExit) if words[0] == "-d" else contextlib.nullcontext():
        assert main(["bag", "play", str(path), *words]) != 0
    lines = capsys.readouterr().err.strip().splitlines()
    # One line naming the problem (argparse's usage before its own error, as ros2 bag's)
    assert needle in lines[-1] and (words[0] == "-d" or len(lines) == 1), lines


def test_remap_and_delay_words() -> None:
    from robotmodel.cli.bag_cmd import play_options
    from robotmodel.cli.main import build_parser

    args = build_parser().parse_args(["bag", "play", "F", "-m", "/tf:=/a", "b:=c", "--delay", "0.25"])
    assert play_options(args) == PlayOptions(remaps=("/tf:=/a", "b:=c"), delay_ns=250_000_000)
