"""The viewer in a real browser: headless Chromium over the DevTools protocol.

Each test starts ``robotmodel view`` as a process (own port), loads its page, waits
(condition + deadline) until the scene is drawn, and checks the PNG: robot-coloured
pixels where our FK says the visuals are, background in the corners, a different image
after a joint moves. PNGs are kept under the test's tmp_path.
"""

from __future__ import annotations

import re
import signal
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import BUNDLED, ERD_ROBOTS
from livebus import Bus
from viewerhelpers import HIDE_HELPERS, MESH_COUNT, READY, grey_points, loopback_only, png_pixels, robot_fraction

from robotmodel.model import load
from robotmodel.viewer import Browser

# No skip without Chromium: CI installs it, and a missing browser must show as a failure.

PANDA = ERD_ROBOTS / "panda_description" / "urdf" / "panda.urdf"
TALOS = ERD_ROBOTS / "talos_data" / "robots" / "talos_reduced.urdf"
DIFFBOT = BUNDLED / "diffbot.urdf.xacro"

# (file, extra CLI args, joint to move, slider step to move it to)
ROBOTS = {
    # The wheels are round: their frames make a wheel turn visible.
    "diffbot": (DIFFBOT, ["--frames", "left_wheel,right_wheel"], "left_wheel_joint", 9000),
    "panda": (PANDA, [], "panda_joint2", 8500),
    "talos": (TALOS, [], "arm_left_4_joint", 1000),
}


def _visual_count(path: Path) -> int:
    return sum(len(link.visuals) for link in load(path).links)


def _shot(browser: Browser, out: Path) -> bytes:
    browser.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    png = browser.screenshot()
    out.write_bytes(png)
    return png


@pytest.mark.parametrize("name", list(ROBOTS))
def test_live_page_draws_the_robot_and_a_joint_moves_it(name: str, bus: Bus, tmp_path: Path) -> None:
    path, extra, joint, step = ROBOTS[name]
    proc = bus.robotmodel("view", str(path), "--port", "0", *extra)
    url = proc.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
    try:
        listening = loopback_only(proc.popen.pid)
        assert listening and all(a.startswith("127.0.0.1:") for a in listening), listening
        with Browser(width=1280, height=800, timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.wait_for(f"{MESH_COUNT} >= {_visual_count(path)}", timeout=30)
            browser.evaluate(HIDE_HELPERS)
            before = _shot(browser, tmp_path / f"{name}-before.png")
            desc = load(path)
            on_robot, corners = robot_fraction(browser, before, grey_points(desc, {}))
            assert on_robot >= 0.7, f"only {on_robot:.0%} of the visuals' centres are drawn robot-coloured"
            assert corners == 0.0, "the background is robot-coloured: the check would prove nothing"
            # Move the slider as a user would: set it and fire its input event.
            browser.evaluate(f"""(() => {{ const s = document.getElementById("joint-{joint}");
                s.value = {step}; s.dispatchEvent(new Event("input")); return true; }})()""")
            browser.wait_for("window.robotmodel.latencies.length >= 1", timeout=20)
            after = _shot(browser, tmp_path / f"{name}-after.png")
            changed = np.any(png_pixels(before) != png_pixels(after), axis=-1).mean()
            assert changed > 0.001, f"moving {joint} changed only {changed:.4%} of the pixels"
            value = float(browser.evaluate(f"window.robotmodel.positions['{joint}']"))
            assert value != 0.0
            # joint_state_publisher_gui's buttons: Center puts every slider on its zero, Randomize
            # anywhere in its range (both through the 0..10000 slider steps).
            joints = browser.evaluate("window.robotmodel.config.joints")
            browser.evaluate("document.getElementById('center').click()")
            centred = browser.evaluate("window.robotmodel.positions")
            for j in joints:
                assert abs(centred[j["name"]] - j["zero"]) <= (j["max"] - j["min"]) / 10000 + 1e-12, j
            browser.evaluate("document.getElementById('randomize').click()")
            randomized = browser.evaluate("window.robotmodel.positions")
            assert all(j["min"] <= randomized[j["name"]] <= j["max"] for j in joints)
            assert randomized != centred
    finally:
        code = proc.stop(signal.SIGINT)
    assert code == 0, proc.err[-20:]
    assert not any("Traceback" in line for line in proc.err), proc.err


def test_static_html_of_panda_renders_offline(tmp_path: Path) -> None:
    from subprocess import run

    out = tmp_path / "panda.html"
    result = run([sys.executable, "-m", "robotmodel.cli.main", "view", str(PANDA), "--static-html", str(out),
                  "--joint", "panda_joint4=-1.2"], capture_output=True, text=True, timeout=300, check=False)
    assert result.returncode == 0, result.stderr
    html = out.read_text()
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", html), "the page loads something remotely"
    with Browser(width=1280, height=800, timeout=60) as browser:
        browser.call("Network.enable")
        browser.call("Network.emulateNetworkConditions", {"offline": True, "latency": 0, "downloadThroughput": -1,
                                                          "uploadThroughput": -1})
        browser.navigate(out.as_uri())
        browser.wait_for(READY, timeout=60)
        assert browser.evaluate(MESH_COUNT) >= _visual_count(PANDA)
        browser.evaluate(HIDE_HELPERS)
        png = _shot(browser, tmp_path / "panda-static.png")
        requested = [e["params"]["request"]["url"] for e in browser.events
                     if e["method"] == "Network.requestWillBeSent"]
        on_robot, corners = robot_fraction(browser, png, grey_points(load(PANDA), {"panda_joint4": -1.2}))
    assert all(u.startswith(("file:", "data:", "blob:")) for u in requested), requested
    assert on_robot >= 0.7 and corners == 0.0, (on_robot, corners)


def test_slider_publishes_joint_states_seen_by_another_process(bus: Bus, tmp_path: Path) -> None:
    gui = bus.robotmodel("joint-state-publisher-gui", str(PANDA), "--port", "0")
    url = gui.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
    listener = bus.start(sys.executable, "-c", _SUBSCRIBER)
    listener.wait_line("^subscribed$", timeout=60)
    try:
        listener.wait_line(r"^panda_joint2 0\.0+$", timeout=30)  # the default, before any slider moves
        listening = loopback_only(gui.popen.pid)
        assert listening and all(a.startswith("127.0.0.1:") for a in listening), listening
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.evaluate("""(() => { const s = document.getElementById("joint-panda_joint2");
                s.value = 7500; s.dispatchEvent(new Event("input")); return true; })()""")
            shown = float(browser.evaluate("window.robotmodel.positions['panda_joint2']"))
            # The page sends the move over its websocket asynchronously: the browser stays open until
            # the other process has it (closing it at once lost the message under a loaded machine).
            match = listener.wait_line(r"^panda_joint2 (0\.[1-9]\d*)$", timeout=30)
        # joint_state_publisher_gui's mapping: min + (max - min) * step / 10000.
        expected = -1.7628 + (1.7628 + 1.7628) * 0.75
        assert shown == pytest.approx(expected)
        assert float(match.group(1)) == pytest.approx(expected, abs=1e-9)
    finally:
        listener.stop(signal.SIGTERM)
        code = gui.stop(signal.SIGINT)
    assert code == 0, gui.err[-20:]


_SUBSCRIBER = """
from robotmodel.bus import Node
from robotmodel.msgs import JointState
from robotmodel.signals import stop_on_signals
stop = stop_on_signals()  # an Event set from a handler would miss a SIGTERM landing on a zenoh thread
def on_state(msg):
    for name, value in zip(msg.name, msg.position):
        if name == "panda_joint2":
            print(name, repr(float(value)), flush=True)
with Node("listener") as node:
    node.create_subscription(JointState, "joint_states", on_state, 10)
    print("subscribed", flush=True)
    stop.wait()
"""


def test_follow_and_tf_with_the_robot_from_robot_description(bus: Bus) -> None:
    """rviz's setup: no FILE (the robot from /robot_description), joints from /joint_states, frames from /tf."""
    arm = str(BUNDLED / "arm.urdf.xacro")
    bus.robotmodel("robot-state-publisher", arm)
    bus.robotmodel("joint-state-publisher", arm, "--zeros", "arm_shoulder_joint=0.5", "arm_elbow_joint=-0.7")
    view = bus.robotmodel("view", "--follow", "--tf", "--fixed-frame", "arm_upper_link", "--port", "0")
    url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
    try:
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.wait_for("Math.abs(window.robotmodel.positions.arm_elbow_joint + 0.7) < 1e-9", timeout=30)
            assert browser.evaluate(MESH_COUNT) >= _visual_count(BUNDLED / "arm.urdf.xacro")
            drawn = browser.wait_for("""(() => { const n = viewer.scene_tree.find(["tf", "gripper_palm_link"]);
                return n.object.matrix.elements[15] === 1 && n.object.position.lengthSq() > 0
                    && Array.from(n.object.matrix.elements); })()""", timeout=30)
            placed = browser.wait_for("""(() => { const m = viewer.scene_tree.find(["robot"]).object.matrix;
                return m.elements[14] !== 0 && Array.from(m.elements); })()""", timeout=30)
    finally:
        code = view.stop(signal.SIGINT)
    assert code == 0, view.err[-20:]
    from robotmodel.kinematics import KinematicModel, KinematicState

    desc = load(BUNDLED / "arm.urdf.xacro")
    state = KinematicState(KinematicModel(desc)).update({"arm_shoulder_joint": 0.5, "arm_elbow_joint": -0.7})
    # Drawn from the fixed frame asked for: T_arm_upper_link_gripper_palm_link.
    expected = np.linalg.inv(state.link_matrix("arm_upper_link")) @ state.link_matrix("gripper_palm_link")
    np.testing.assert_allclose(np.asarray(drawn).reshape(4, 4).T, expected, atol=1e-5)
    # The robot is drawn from the same fixed frame: its root where arm_upper_link sees it.
    root_in_fixed = np.linalg.inv(state.link_matrix("arm_upper_link")) @ state.link_matrix(desc.root)
    np.testing.assert_allclose(np.asarray(placed).reshape(4, 4).T, root_in_fixed, atol=1e-5)


def test_screenshot_command_writes_a_png_of_the_robot(tmp_path: Path) -> None:
    from subprocess import run

    out = tmp_path / "diffbot.png"
    result = run([sys.executable, "-m", "robotmodel.cli.main", "view", str(DIFFBOT), "--screenshot", str(out),
                  "--size", "640x480"], capture_output=True, text=True, timeout=300, check=False)
    assert result.returncode == 0, result.stderr
    rgb = png_pixels(out.read_bytes())
    assert rgb.shape == (480, 640, 3)
    # The robot (white, grey, black) fills part of the middle; meshcat's sky is never grey,
    # and its grid lines alone make well under 1% of it (0.3% measured with an empty robot).
    from viewerhelpers import is_robot_grey

    middle = rgb[120:360, 160:480]
    assert 0.05 < is_robot_grey(middle).mean() < 0.9
    assert list(tmp_path.iterdir()) == [out]


_MOVING_ODOM = """
import math, time
from robotmodel.bus import Node
from robotmodel.signals import stop_on_signals
from robotmodel.tf import make_transform
from robotmodel.tf_ros import TransformBroadcaster
stop = stop_on_signals()  # an Event set from a handler would miss a SIGTERM landing on a zenoh thread
with Node("odometry") as node:
    broadcaster = TransformBroadcaster(node)
    print("broadcasting", flush=True)
    while not stop.wait(0.02):
        x = 0.2 * math.sin(time.monotonic())
        broadcaster.sendTransform(make_transform("odom", "base_footprint", (x, 0, 0), (0, 0, 0, 1),
                                                 stamp_ns=time.time_ns()))
"""


def test_a_streaming_tf_leaves_the_page_time_to_breathe(bus: Bus) -> None:
    """/tf at 50 Hz must not make the page draw on every batch (it once starved the page: a
    headless screenshot took ~1 min). Draws are throttled: at most 30 a second and never
    closer than a draw's own cost, so drawing takes at most about half the page's time."""
    diffbot = str(DIFFBOT)
    bus.robotmodel("robot-state-publisher", diffbot)
    bus.start(sys.executable, "-c", _MOVING_ODOM).wait_line("^broadcasting$", timeout=60)
    view = bus.robotmodel("view", diffbot, "--tf", "--fixed-frame", "odom", "--port", "0")
    url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
    try:
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            browser.wait_for("window.robotmodel.synced > 20", timeout=30)  # the stream is flowing
            elapsed, renders, batches, drawing = browser.evaluate("""new Promise(done => {
                const m = window.robotmodel, t0 = performance.now(), r0 = m.renders, s0 = m.synced,
                      d0 = m.renderMs;
                setTimeout(() => done([performance.now() - t0, m.renders - r0, m.synced - s0, m.renderMs - d0]),
                           2000); })""")
            browser.screenshot()  # answers while the stream goes on
    finally:
        code = view.stop(signal.SIGINT)
    assert code == 0
    assert batches > 0, "no /tf batches arrived while counting"
    assert renders <= elapsed / (1000 / 30) + 2, (elapsed, renders, batches)
    assert drawing <= 0.5 * elapsed + 100, (elapsed, drawing, renders)  # one draw's worth of slack


def test_frames_with_tf_picks_the_tf_frames_drawn(bus: Bus) -> None:
    """With --tf, --frames names the /tf frames drawn as triads (rviz's TF display), the robot still placed."""
    diffbot = str(DIFFBOT)
    bus.robotmodel("robot-state-publisher", diffbot)
    bus.start(sys.executable, "-c", _MOVING_ODOM).wait_line("^broadcasting$", timeout=60)
    view = bus.robotmodel("view", diffbot, "--tf", "--fixed-frame", "odom", "--frames", "base_footprint,base_link",
                          "--port", "0")
    url = view.wait_line(r"^http://127\.0\.0\.1:\d+/(?= \(|$)", timeout=120).group(0)
    try:
        with Browser(timeout=60) as browser:
            browser.navigate(url)
            browser.wait_for(READY, timeout=60)
            # odom and the sensors' frames are on /tf too, but not drawn (no wheels: no /joint_states).
            drawn = browser.wait_for("""(() => { const names = Object.keys(viewer.scene_tree.find(["tf"]).children);
                return names.length >= 2 && names.sort(); })()""", timeout=30)
            moved = browser.wait_for("""(() => { const m = viewer.scene_tree.find(["robot"]).object.matrix;
                return m.elements[12] !== 0; })()""", timeout=30)
    finally:
        code = view.stop(signal.SIGINT)
    assert code == 0, view.err[-20:]
    assert drawn == ["base_footprint", "base_link"]
    assert moved
