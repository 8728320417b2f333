"""The running demo: output folder, children on a private bus, live lines, files, the offline answer."""

from __future__ import annotations

import os
import random
import re
import signal
import socket
import sys
import threading
import time
from collections.abc import Callable
from datetime import datetime
from pathlib import Path

from robotmodel.errors import RobotModelError
from robotmodel.process import Child, Supervisor, command_argv
from robotmodel.signals import stop_on_signals

__all__ = ["Demo", "private_bus_env"]

ROBOT = "diffbot.urdf.xacro"
#: The recorded topics: TF, the robot, and the odometry example's own.
TOPICS = ("/tf", "/tf_static", "/joint_states", "/robot_description", "/odom", "/cmd_vel")
#: map → odom, as a localization node would publish it.
MAP_TO_ODOM = ("1.0", "0.5", "0.0")
#: The viewer's camera, in odom, before it follows base_link with this offset: above, behind and to
#: the right of the robot as it sets off along x, close enough for the robot to fill the picture.
VIEWER_CAMERA = "-0.6,-0.45,0.4:0,0,0"

_ECHO_EVERY_S = 5.0  # how often the live tf2_echo line is printed when stdout is not a terminal
_READY_S = 60.0
_TASKS = ("view_frames", "screenshot")


def _out_dir(text: str | None) -> Path:
    path = Path(text) if text else Path(f"robotmodel-demo-{datetime.now():%Y%m%d-%H%M%S}")
    if path.exists() and (not path.is_dir() or any(path.iterdir())):
        raise RobotModelError(f"{path} already exists and is not an empty folder (not overwritten)")
    path.mkdir(parents=True, exist_ok=True)
    (path / "logs").mkdir()
    return path


class _EchoLine:
    """Folds tf2_echo's blocks into one line: the time, the translation and the yaw."""

    def __init__(self) -> None:
        self.tty = sys.stdout.isatty()
        self._lock = threading.Lock()
        self._stamp = ""
        self._translation = ""
        self._last_print = 0.0
        self.latest = ""

    def __call__(self, line: str) -> None:
        if line.startswith("At time "):
            self._stamp = line[len("At time "):]
        elif line.startswith("- Translation: "):
            self._translation = line[len("- Translation: "):]
        elif line.startswith("- Rotation: in RPY (degree) ") and self._translation:
            yaw = line.rsplit(",", 1)[-1].strip(" ]")
            text = f"tf2_echo map base_footprint: at {self._stamp}: translation {self._translation}, yaw {yaw} deg"
            self._show(text)

    def _show(self, text: str) -> None:
        with self._lock:
            self.latest = text
            now = time.monotonic()
            if self.tty:
                sys.stdout.write("\r\033[K" + text)
                sys.stdout.flush()
            elif now - self._last_print >= _ECHO_EVERY_S:
                self._last_print = now
                print(text, flush=True)

    def end(self) -> None:
        """Finish the live line on a terminal."""
        if self.tty and self.latest:
            print(flush=True)


def private_bus_env() -> dict[str, str]:
    """The current environment with a free loopback rendezvous port, a random domain and no zenoh config.

    The demo neither joins nor disturbs another system on this machine.
    """
    env = dict(os.environ)
    # The private bus is zenoh whatever the shell sourced: a ROS 1 setup (ROS_VERSION=1 and
    # ROS_MASTER_URI) or another RMW would otherwise move the children onto the user's system.
    for key in ("ZENOH_SESSION_CONFIG_URI", "ZENOH_ROUTER_CONFIG_URI", "ZENOH_CONFIG_OVERRIDE", "ROS_VERSION",
                "ROS_MASTER_URI"):
        env.pop(key, None)
    env["RMW_IMPLEMENTATION"] = "rmw_zenoh_cpp"
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        env["ROBOTMODEL_ZENOH_PORT"] = str(s.getsockname()[1])
    # Clear of 0, the domain a developer's own ROS 2 system is most likely on.
    env["ROS_DOMAIN_ID"] = str(random.randint(120, 200))
    env["PYTHONUNBUFFERED"] = "1"
    return env


class Demo:
    """One run of ``robotmodel demo``: ``duration`` seconds, files into ``output`` (None: a fresh folder)."""

    def __init__(self, *, duration: float = 35.0, output: str | None = None, browser: bool = True,
                 time_scale: float = 1.0) -> None:
        if not duration > 0:
            raise RobotModelError("--duration must be greater than 0")
        if not time_scale > 0:
            raise RobotModelError("--time-scale must be greater than 0")
        self.duration, self.browser, self.time_scale = duration, browser, time_scale
        self.out = _out_dir(output)
        self.env = private_bus_env()
        # SIGKILL when the demo dies uncleanly: a child busy shutting down its bus session when all
        # its peers vanish at once may not act on a SIGTERM; the recording keeps every flushed chunk.
        self.children = Supervisor(env=self.env, logs=self.out / "logs", orphan_signal=signal.SIGKILL)
        self.stop = threading.Event()
        self.echo = _EchoLine()
        self.url: str | None = None
        self.files: list[tuple[str, Path]] = []
        self.notes: list[str] = []
        self.elapsed = 0.0

    def run(self) -> int:
        """Everything, in order; children are reaped whatever happens."""
        import robotmodel.robots

        robot = str(robotmodel.robots.path(ROBOT))
        old = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
        stop_on_signals(self.stop)
        print(f"robotmodel demo: the bundled {ROBOT} driven by the odometry example, on a private bus "
              f"(port {self.env['ROBOTMODEL_ZENOH_PORT']}, ROS_DOMAIN_ID {self.env['ROS_DOMAIN_ID']})", flush=True)
        print(f"files go to {self.out.resolve()}/", flush=True)
        started = time.monotonic()
        try:
            self._start(robot)
            # The run's length counts from a running pipeline: on a loaded machine starting it
            # can take seconds, which would otherwise leave the robot less time to drive.
            self._run_until(time.monotonic() + self.duration)
        finally:
            self.echo.end()
            self.elapsed = time.monotonic() - started
            # view_frames and the screenshot end by themselves; stopped half-way, they did not fail.
            cut = {c.name for c in self.children.started if c.name in _TASKS and c.poll() is None}
            codes = self.children.stop_all(last=("record", "router"))
            for signum, handler in old.items():
                signal.signal(signum, handler)
        failed = {n: c for n, c in codes.items() if c not in (0, -signal.SIGINT, 130) and n not in cut}
        for name, code in failed.items():
            self.notes.append(f"{name} exited with {code} (see logs/{name}.log)")
        self._collect(cut)
        self._offline()
        self._report()
        return 0 if not failed else 1

    def _start(self, robot: str) -> None:
        scale = ["--time-scale", f"{self.time_scale:g}"]
        c = self.children
        mcap = self.out / "demo.mcap"
        # The private bus's router is the demo's own child and ends with it; the first tool
        # would otherwise start one in the background that outlives the demo.
        self._ready(self._robotmodel("router"), r"Started Zenoh router", "router")
        record = self._robotmodel("record", "-o", str(mcap), *TOPICS)
        self._ready(record, r"Recording to", "record")
        self.files.append(("recording (MCAP)", mcap))
        x, y, z = MAP_TO_ODOM
        self._robotmodel("static_transform_publisher", "--x", x, "--y", y, "--z", z, "--frame-id", "map",
                     "--child-frame-id", "odom")
        self._robotmodel("robot_state_publisher", robot)
        self._robotmodel("joint_state_publisher", robot, "--source-list", "/wheel_states")
        sim = c.module("sensor_simulator", "robotmodel.examples.sensor_simulator", "--joint-states-topic",
                       "/wheel_states", *scale)
        self._ready(sim, r"integrating", "sensor_simulator")
        c.module("robot_controller", "robotmodel.examples.robot_controller", *scale)
        self._robotmodel("tf2_echo", "map", "base_footprint", "1", on_line=self.echo)
        # The viewer drives the robot as rviz would: joints from /joint_states (the wheels turn),
        # placed by /tf from odom, the camera riding along behind base_link. No frame triads:
        # their labels crowd the picture and slow a headless screenshot down.
        view = self._robotmodel("view", robot, "--follow", "--tf", "--fixed-frame", "odom", "--frames", "none",
                            "--track", "base_link", f"--camera={VIEWER_CAMERA}")
        found = self._ready(view, r"^(http://127\.0\.0\.1:\d+/\S*)", "view")
        self.url = found.group(1)
        print(f"viewer: {self.url}", flush=True)
        if self.browser:
            import webbrowser

            webbrowser.open(self.url, new=2)

    def _robotmodel(self, command: str, *args: str, on_line: Callable[[str], None] | None = None) -> Child:
        """``robotmodel COMMAND ARGS`` as a child named after COMMAND."""
        return self.children.command(command, command, *args, on_line=on_line)

    def _ready(self, child: Child, pattern: str, what: str) -> re.Match[str]:
        deadline = time.monotonic() + _READY_S
        found = None
        while found is None and time.monotonic() < deadline and child.poll() is None:
            if self.stop.is_set():
                raise KeyboardInterrupt
            found = child.wait_line(pattern, 0.2)
        if found is None:
            tail = " | ".join(child.lines[-3:])
            raise RobotModelError(f"{what} did not start (logs/{child.name}.log): {tail}")
        match: re.Match[str] = found
        return match

    def _run_until(self, end: float) -> None:
        # view_frames listens for a few seconds early on; the screenshot is started half-way,
        # with the robot under way, and may finish after the run (it is waited for then).
        frames_at = min(2.0, self.duration / 4)
        shot_at = self.duration / 2
        start = end - self.duration
        frames_child: Child | None = None
        shot: Child | None = None
        while not self.stop.wait(0.1):
            now = time.monotonic()
            if frames_child is None and now - start >= frames_at:
                wait = f"{max(1.0, min(3.0, self.duration / 3)):g}"
                frames_child = self._robotmodel("view_frames", "--wait-time", wait,
                                                        "-o", str(self.out / "frames"))
            if shot is None and now - start >= shot_at:
                shot = self._start_screenshot()
            if now >= end:
                break
        if shot is not None:
            self._wait(shot, 120.0)
        if frames_child is not None:
            self._wait(frames_child, 30.0)

    def _collect(self, cut: set[str]) -> None:
        """List the files the tasks left, and say why one is missing."""
        import shutil

        shot = self.out / "viewer.png"
        if shot.exists():
            self.files.append(("viewer screenshot", shot))
        elif "screenshot" in cut:
            self.notes.append("no screenshot: stopped before the page was drawn")
        else:
            lines = [c.lines[-1:] for c in self.children.started if c.name == "screenshot"]
            if lines:
                self.notes.append(f"no screenshot: {' '.join(lines[0]) or 'see logs/screenshot.log'}")
        for suffix, what in ((".gv", "frame tree (graphviz)"), (".pdf", "frame tree (PDF)")):
            path = self.out / f"frames{suffix}"
            if path.exists():
                self.files.append((what, path))
        if "view_frames" in cut:
            self.notes.append("no frame tree: stopped before view_frames finished listening")
        elif (self.out / "frames.gv").exists() and not (self.out / "frames.pdf").exists() and not shutil.which("dot"):
            self.notes.append("no frames.pdf: graphviz's dot is not installed")

    def _wait(self, child: Child, timeout: float) -> None:
        """Wait for a child that ends by itself, giving up early on Ctrl-C."""
        deadline = time.monotonic() + timeout
        while child.poll() is None and time.monotonic() < deadline and not self.stop.wait(0.1):
            pass

    def _start_screenshot(self) -> Child | None:
        from robotmodel.viewer import find_chromium

        if self.url is None:
            return None
        if find_chromium() is None:
            self.notes.append("no screenshot: no Chromium found (install Debian's chromium)")
            return None
        return self.children.module("screenshot", "robotmodel.demo._shot", self.url, str(self.out / "viewer.png"))

    def _offline(self) -> None:
        import subprocess

        mcap = self.out / "demo.mcap"
        if not mcap.exists():
            return
        at = f"+{round(min(self.duration, self.elapsed) / 2, 1):g}"  # half-way through what ran
        argv = command_argv("tf2-echo", "--bag", str(mcap), "map", "base_footprint", "--time", at, "--no-progress")
        print(f"\noffline, from the recording: where was base_footprint in map {at[1:]} s into it?", flush=True)
        print(f"$ robotmodel tf2-echo --bag {mcap} map base_footprint --time {at}", flush=True)
        done = subprocess.run(argv, env=self.env, capture_output=True, text=True, timeout=120, check=False)
        sys.stdout.write(done.stdout)
        if done.returncode != 0:
            self.notes.append(f"the offline query failed: {done.stderr.strip()}")

    def _report(self) -> None:
        print(f"\nfiles in {self.out.resolve()}/:", flush=True)
        for what, path in self.files:
            if path.exists():
                print(f"  {path.name:<16} {what}", flush=True)
        print(f"  {'logs/':<16} each process's output", flush=True)
        for note in self.notes:
            print(f"note: {note}", flush=True)
