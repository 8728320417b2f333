"""``robotmodel demo`` as a user runs it: files left behind, the numbers it prints, nothing left running.

The recording is read back here with rosbags (not robotmodel's reader), and the offline
answer the demo prints is recomputed from its raw /tf and /tf_static messages. The recording is
then played back with ``bag play --clock`` (issue 22's must-show 3) into a sim-time tf2_echo,
view_frames and view, on the one demo run this file's first test makes (a demo run takes ~20 s here).
"""

from __future__ import annotations

import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from livebus import Bus, Proc
from procscan import assert_none_left
from robotmodel.robots import path as robot_path
from rosbags.highlevel import AnyReader
from viewerhelpers import HIDE_HELPERS, READY, grey_points, is_robot_grey, png_pixels, robot_fraction

from robotmodel.demo import VIEWER_CAMERA
from robotmodel.model import load
from robotmodel.viewer import Browser, camera_spec

DEMO = [sys.executable, "-m", "robotmodel.cli.main", "demo", "--no-browser"]


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONUNBUFFERED"] = "1"
    # The demo must pick its own bus whatever the caller's environment says.
    env["ROBOTMODEL_ZENOH_PORT"] = "7447"
    env["ROS_DOMAIN_ID"] = "0"
    return env


def _port(stdout: str) -> str:
    m = re.search(r"private bus \(port (\d+), ROS_DOMAIN_ID (\d+)\)", stdout)
    assert m, stdout
    assert m.group(1) != "7447" and m.group(2) != "0"
    return m.group(1)


def _read(mcap: Path) -> tuple[dict[str, int], list[tuple[int, str, str, tuple[float, ...], bool]]]:
    counts: dict[str, int] = {}
    transforms = []
    with AnyReader([mcap]) as reader:
        for conn, _t, raw in reader.messages():
            counts[conn.topic] = counts.get(conn.topic, 0) + 1
            if conn.topic in ("/tf", "/tf_static"):
                for t in reader.deserialize(raw, conn.msgtype).transforms:
                    stamp = t.header.stamp.sec * 10**9 + t.header.stamp.nanosec
                    tr, q = t.transform.translation, t.transform.rotation
                    transforms.append((stamp, t.header.frame_id, t.child_frame_id, (tr.x, tr.y, tr.z, q.z, q.w),
                                       conn.topic == "/tf_static"))
    return counts, transforms


def _expected_offline(transforms: list, at_ns: int) -> tuple[float, float, float]:
    """map -> base_footprint at ``at_ns``: the static map -> odom, then odom -> base_footprint interpolated."""
    static = [v for _s, p, c, v, is_static in transforms if (p, c) == ("map", "odom") and is_static]
    assert static, "no map -> odom on /tf_static"
    mx, my, _mz, mqz, mqw = static[-1]
    myaw = 2 * math.atan2(mqz, mqw)
    odom = sorted((s, v) for s, p, c, v, _ in transforms if (p, c) == ("odom", "base_footprint"))
    before = max((o for o in odom if o[0] <= at_ns), default=None)
    after = min((o for o in odom if o[0] >= at_ns), default=None)
    assert before is not None and after is not None
    f = 0.0 if after[0] == before[0] else (at_ns - before[0]) / (after[0] - before[0])
    x = before[1][0] + f * (after[1][0] - before[1][0])
    y = before[1][1] + f * (after[1][1] - before[1][1])
    yaw0, yaw1 = (2 * math.atan2(v[3], v[4]) for v in (before[1], after[1]))
    yaw = yaw0 + f * math.remainder(yaw1 - yaw0, 2 * math.pi)
    return (mx + math.cos(myaw) * x - math.sin(myaw) * y, my + math.sin(myaw) * x + math.cos(myaw) * y,
            math.remainder(myaw + yaw, 2 * math.pi))


def test_demo_runs_headless_and_leaves_its_files(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "demo"
    done = subprocess.run([*DEMO, "--duration", "10", "--output", str(out)], env=_env(), cwd=tmp_path,
                          capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Traceback" not in done.stderr, done.stderr
    port = _port(done.stdout)
    assert_none_left(port)
    listing = done.stdout[done.stdout.index(f"files in {out.resolve()}/:"):]
    # The recording: every topic of the pipeline, readable by rosbags.
    mcap = out / "demo.mcap"
    assert "demo.mcap" in listing
    counts, transforms = _read(mcap)
    assert {"/tf", "/tf_static", "/joint_states", "/robot_description", "/odom", "/cmd_vel"} <= set(counts)
    assert counts["/odom"] > 50 and counts["/cmd_vel"] > 20
    # view_frames' diagram has the whole tree, with its broadcasters.
    gv = (out / "frames.gv").read_text()
    for parent, child in (("map", "odom"), ("odom", "base_footprint"), ("base_footprint", "base_link"),
                          ("base_link", "left_wheel"), ("base_link", "right_wheel")):
        assert f'"{parent}" -> "{child}"' in gv
    assert "Broadcaster: /sensor_simulator" in gv and "Broadcaster: /robot_state_publisher" in gv
    if shutil.which("dot"):
        assert (out / "frames.pdf").read_bytes().startswith(b"%PDF")
    if shutil.which("chromium"):
        png = (out / "viewer.png").read_bytes()
        assert png.startswith(b"\x89PNG\r\n\x1a\n")
        # The diffbot is drawn: its white body and black wheels, against meshcat's blue sky,
        # in the 3D view (the left three quarters; the slider panel is on the right).
        view = png_pixels(png)[:, : 3 * png_pixels(png).shape[1] // 4]
        assert is_robot_grey(view).mean() > 0.02
        assert "viewer.png" in listing
    # The live tf2_echo line came from the bus, and moved as the robot drove.
    live = re.findall(r"tf2_echo map base_footprint: at \S+: translation \[([-\d.]+), ([-\d.]+)", done.stdout)
    assert len(live) >= 2 and float(live[-1][0]) > float(live[0][0])
    # The offline answer: 5 s after the first recorded transform, recomputed from the raw messages.
    m = re.search(r"--time \+5\nAt time (\d+)\.(\d+)\n- Translation: \[([-\d.]+), ([-\d.]+), ([-\d.]+)\]\n"
                  r".*\n- Rotation: in RPY \(radian\) \[([-\d.]+), ([-\d.]+), ([-\d.]+)\]", done.stdout)
    assert m, done.stdout
    first = min(t[0] for t in transforms if not t[4])  # "+5": after the first /tf (dynamic) stamp
    # tf2_echo prints the integer nanosec after the dot, not zero-padded: 5.012 s prints "5.12000000".
    at_ns = int(m.group(1)) * 10**9 + int(m.group(2))
    assert abs(at_ns - (first + 5 * 10**9)) < 1000
    x, y, yaw = _expected_offline(transforms, at_ns)
    assert float(m.group(3)) == pytest.approx(x, abs=0.0006)
    assert float(m.group(4)) == pytest.approx(y, abs=0.0006)
    assert float(m.group(8)) == pytest.approx(yaw, abs=0.0006)
    _replay_with_clock(mcap, tmp_path, capsys)


def _replay_with_clock(mcap: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """``bag play --clock`` of the demo's recording: a tf2_echo with ``use_sim_time`` prints what ``tf2_echo --bag
    --time`` says for the same instants, a view_frames with it dates its tree inside the recording, and a
    ``view --tf`` with it draws the robot where the recorded drive ends (a screenshot)."""
    from recording.test_play import echo_blocks
    from robotmodel.cli.main import main

    with AnyReader([mcap]) as reader:
        start, end = reader.start_time, reader.end_time
    sim = ("--ros-args", "-p", "use_sim_time:=true")
    diffbot = robot_path("diffbot.urdf.xacro")
    bus = Bus(tmp_path, "dds")
    try:
        echo = bus.robotmodel("tf2_echo", "map", "base_footprint", *sim)
        view = bus.robotmodel("view", str(diffbot), "--tf", "--fixed-frame", "odom", "--track", "base_footprint",
                              "--port", "0", *sim)
        url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
        echo.wait_line("Waiting for transform", stream="err")
        play = bus.robotmodel("bag", "play", str(mcap), "--clock", "100", "-r", "4")
        play.wait_line("Playing", timeout=60, stream="err")
        frames = bus.robotmodel("view_frames", "--wait-time", "1.5", "-o", str(tmp_path / "replayed"), *sim)
        play.wait_line("Playback finished", timeout=60, stream="err")
        assert frames.popen.wait(60) == 0, frames.err[-5:]
        echo.stop()
        # The viewer, started before the replay with nothing on /tf, draws the robot where the recorded drive
        # ends (more than a metre from the origin): it followed the played /tf.
        _, transforms = _read(mcap)
        odom = max((s, v) for s, p, c, v, _ in transforms if (p, c) == ("odom", "base_footprint"))[1]
        final = _matrix(*odom)
        assert np.hypot(*final[:2, 3]) > 1.0
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.evaluate(HIDE_HELPERS)
            deadline = time.monotonic() + 30
            while not np.allclose(np.asarray(browser.evaluate(_PAGE_POSES)["root"]).reshape(4, 4).T, final,
                                  atol=1e-4):
                assert time.monotonic() < deadline, "the viewer never showed the drive's last pose"
                time.sleep(0.2)
            png = browser.screenshot()
            (tmp_path / "replay.png").write_bytes(png)  # kept for a look when this fails
            hits, grey_corners = robot_fraction(browser, png, grey_points(load(diffbot), {}))
    finally:
        bus.reap()
    assert hits >= 0.7 and grey_corners == 0.0, (hits, grey_corners)  # drawn there, in a tracking camera's view
    blocks = echo_blocks(echo.out)
    assert len(blocks) >= 3, echo.out
    capsys.readouterr()
    for stamp, live in blocks[:: max(1, len(blocks) // 4)]:
        assert start <= stamp <= end
        assert main(["tf2_echo", "map", "base_footprint", "--bag", str(mcap), "--time",
                     f"{stamp // 10**9}.{stamp % 10**9:09d}", "--no-progress"]) == 0
        assert echo_blocks(capsys.readouterr().out.splitlines()) == [(stamp, live)]
    recorded = re.search(r'"Recorded at time: ([\d.]+)"', (tmp_path / "replayed.gv").read_text())
    assert recorded and start / 1e9 <= float(recorded[1]) <= end / 1e9 + 0.1, recorded


def test_ctrl_c_stops_everything_and_keeps_the_recording(tmp_path: Path) -> None:
    out = tmp_path / "demo"
    proc = Proc([*DEMO, "--duration", "120", "--output", str(out)], _env(), tmp_path)
    try:
        header = proc.wait_line(r"private bus \(port (\d+)", timeout=60)
        proc.wait_line(r"^viewer: http://127\.0\.0\.1:\d+/", timeout=90)
        proc.wait_line(r"^tf2_echo map base_footprint", timeout=60)
        code = proc.stop(signal.SIGINT, timeout=60)
    finally:
        proc.kill()
    assert code == 0, "\n".join(proc.out + proc.err)
    assert_none_left(header.group(1))
    counts, _ = _read(out / "demo.mcap")
    assert counts.get("/odom", 0) > 0 and counts.get("/tf_static", 0) > 0
    assert any(line.startswith("files in ") for line in proc.out)


def test_bad_options_are_one_line_errors(tmp_path: Path) -> None:
    busy = tmp_path / "busy"
    busy.mkdir()
    (busy / "keep.txt").write_text("mine")
    for args, text in ((["--output", str(busy)], "already exists and is not an empty folder"),
                       (["--duration", "0", "--output", str(tmp_path / "x")], "--duration must be greater than 0")):
        done = subprocess.run([*DEMO, *args], env=_env(), capture_output=True, text=True, timeout=60, check=False)
        assert done.returncode == 1
        assert done.stderr.strip().count("\n") == 0 and text in done.stderr, done.stderr
    assert (busy / "keep.txt").read_text() == "mine" and sorted(p.name for p in busy.iterdir()) == ["keep.txt"]


def test_killing_the_demo_takes_its_children_down(tmp_path: Path) -> None:
    proc = Proc([*DEMO, "--duration", "120", "--output", str(tmp_path / "demo")], _env(), tmp_path)
    try:
        header = proc.wait_line(r"private bus \(port (\d+)", timeout=60)
        proc.wait_line(r"^viewer: http://127\.0\.0\.1:\d+/", timeout=90)
        proc.kill()  # SIGKILL: no cleanup in the demo itself
        # Each child was told by the kernel (parent-death signal) and stops on its own.
        assert_none_left(header.group(1), timeout=20)
    finally:
        proc.kill()


# The page's state: the robot's root (/robot) and base_link in the scene's frame (odom), and the
# camera (three.js's Y-up world, converted here: (x, y, z) -> (x, -z, y)).
_PAGE_POSES = """(() => { const find = p => viewer.scene_tree.find(p).object;
  const scene = viewer.scene; scene.updateMatrixWorld(true);
  const inScene = o => scene.matrixWorld.clone().invert().multiply(o.matrixWorld);
  const root = find(["robot"]), base = find(["robot", "base_footprint", "base_link"]);
  const c = viewer.camera.position, t = viewer.controls.target;
  return {root: Array.from(inScene(root).elements), base: Array.from(inScene(base).elements),
          camera: [c.x, -c.z, c.y], target: [t.x, -t.z, t.y]}; })()"""


def _matrix(x: float, y: float, z: float, qz: float, qw: float) -> np.ndarray:
    m = np.eye(4)
    yaw = 2 * math.atan2(qz, qw)
    m[:2, :2] = [[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]]
    m[:3, 3] = (x, y, z)
    return m


def test_viewer_drives_the_robot_to_where_tf_says_it_ended(tmp_path: Path) -> None:
    """The demo's viewer places the robot from /tf in odom (not at the origin) and its camera follows
    base_link: after the odometry pattern has ended, the page shows the robot at the recorded final
    odom -> base_footprint, base_link where the recorded static transform puts it, and the camera
    looking at base_link from the demo's offset."""
    out = tmp_path / "demo"
    proc = Proc([*DEMO, "--duration", "60", "--time-scale", "5", "--output", str(out)], _env(), tmp_path)
    try:
        header = proc.wait_line(r"private bus \(port (\d+)", timeout=60)
        url = proc.wait_line(r"^viewer: (http://127\.0\.0\.1:\d+/\S*)", timeout=90).group(1)
        log = out / "logs" / "robot_controller.log"
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            deadline = time.monotonic() + 60
            while "stopped" not in (log.read_text() if log.exists() else ""):
                assert time.monotonic() < deadline, "the odometry pattern did not end"
                time.sleep(0.2)
            # Stopped: the pose on /tf no longer changes, so the page settles on it.
            shown = browser.evaluate(_PAGE_POSES)
            deadline = time.monotonic() + 30
            while True:
                time.sleep(0.5)
                again = browser.evaluate(_PAGE_POSES)
                if again == shown:
                    break
                assert time.monotonic() < deadline, "the page never settled"
                shown = again
        code = proc.stop(signal.SIGINT, timeout=60)
    finally:
        proc.kill()
    assert code == 0, "\n".join(proc.out + proc.err)
    assert_none_left(header.group(1))
    _, transforms = _read(out / "demo.mcap")
    odom = max((s, v) for s, p, c, v, _ in transforms if (p, c) == ("odom", "base_footprint"))[1]
    offset = [v for _s, p, c, v, st in transforms if (p, c) == ("base_footprint", "base_link") and st][-1]
    t_odom_footprint = _matrix(*odom)
    t_odom_base = t_odom_footprint @ _matrix(*offset)
    root = np.asarray(shown["root"]).reshape(4, 4).T
    base = np.asarray(shown["base"]).reshape(4, 4).T
    assert np.hypot(*t_odom_footprint[:2, 3]) > 1.0, "the robot ended near the origin: nothing was shown"
    np.testing.assert_allclose(root, t_odom_footprint, atol=1e-4)
    np.testing.assert_allclose(base, t_odom_base, atol=1e-4)
    # The camera: its target on base_link, and the demo's offset from it kept.
    np.testing.assert_allclose(shown["target"], t_odom_base[:3, 3], atol=1e-4)
    position, target = camera_spec(VIEWER_CAMERA)
    np.testing.assert_allclose(np.subtract(shown["camera"], shown["target"]), np.subtract(position, target),
                               atol=1e-4)
