"""The running demo: output folder, children on a private bus, live lines, files, the offline answer."""

from __future__ import annotations

import argparse
import re
import signal
import sys
import threading
import time
from datetime import datetime
from pathlib import Path

from robotmodel.cli._demo_children import Child, Children, private_bus_env
from robotmodel.cli.demo_cmd import MAP_TO_ODOM, ROBOT, TOPICS, VIEWER_CAMERA

from robotmodel.errors import RobotModelError
from robotmodel.signals import stop_on_signals

__all__ = ["Demo"]

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


class Demo:
    """One run of ``robotmodel demo``."""

    def __init__(self, args: argparse.Namespace) -> None:
        if not args.duration > 0:
            raise RobotModelError("--duration must be greater than 0")
        if not args.time_scale > 0:
            raise RobotModelError("--time-scale must be greater than 0")
        self.args = args
        self.out = _out_dir(args.output)
        self.env = private_bus_env()
        self.children = Children(self.env, self.out / "logs")
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
            self._run_until(started + self.args.duration)
        finally:
            self.echo.end()
            self.elapsed = time.monotonic() - started
            # view_frames and the screenshot end by themselves; stopped half-way, they did not fail.
            cut = {c.name for c in self.children.started if c.name in _TASKS and c.popen.poll() is None}
            codes = self.children.stop_all(last=("record",))
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
        scale = ["--time-scale", f"{self.args.time_scale:g}"]
        c = self.children
        mcap = self.out / "demo.mcap"
        record = c.robotmodel("record", "-o", str(mcap), *TOPICS)
        self._ready(record, r"Recording to", "record")
        self.files.append(("recording (MCAP)", mcap))
        x, y, z = MAP_TO_ODOM
        c.robotmodel("static_transform_publisher", "--x", x, "--y", y, "--z", z, "--frame-id", "map",
                     "--child-frame-id", "odom")
        c.robotmodel("robot_state_publisher", robot)
        c.robotmodel("joint_state_publisher", robot, "--source-list", "/wheel_states")
        sim = c.example("sensor_simulator", "--joint-states-topic", "/wheel_states", *scale)
        self._ready(sim, r"integrating", "sensor_simulator")
        c.example("robot_controller", *scale)
        c.robotmodel("tf2_echo", "map", "base_footprint", "1", on_line=self.echo)
        # The viewer drives the robot as rviz would: joints from /joint_states (the wheels turn),
        # placed by /tf from odom, the camera riding along behind base_link. No frame triads:
        # their labels crowd the picture and slow a headless screenshot down.
        view = c.robotmodel("view", robot, "--follow", "--tf", "--fixed-frame", "odom", "--frames", "none",
                            "--track", "base_link", f"--camera={VIEWER_CAMERA}")
        found = self._ready(view, r"^(http://127\.0\.0\.1:\d+/\S*)", "view")
        self.url = found.group(1)
        print(f"viewer: {self.url}", flush=True)
        if not self.args.no_browser:
            import webbrowser

            webbrowser.open(self.url, new=2)

    def _ready(self, child: Child, pattern: str, what: str) -> re.Match[str]:
        deadline = time.monotonic() + _READY_S
        found = None
        while found is None and time.monotonic() < deadline and child.popen.poll() is None:
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
        frames_at = min(2.0, self.args.duration / 4)
        shot_at = self.args.duration / 2
        start = end - self.args.duration
        frames_child: Child | None = None
        shot: Child | None = None
        while not self.stop.wait(0.1):
            now = time.monotonic()
            if frames_child is None and now - start >= frames_at:
                wait = f"{max(1.0, min(3.0, self.args.duration / 3)):g}"
                frames_child = self.children.robotmodel("view_frames", "--wait-time", wait,
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
        while child.popen.poll() is None and time.monotonic() < deadline and not self.stop.wait(0.1):
            pass

    def _start_screenshot(self) -> Child | None:
        from robotmodel.viewer import find_chromium

        if self.url is None:
            return None
        if find_chromium() is None:
            self.notes.append("no screenshot: no Chromium found (install Debian's chromium)")
            return None
        return self.children.start("screenshot", [sys.executable, "-m", "robotmodel.cli._demo_shot", self.url,
                                                  str(self.out / "viewer.png")])

    def _offline(self) -> None:
        import subprocess

        mcap = self.out / "demo.mcap"
        if not mcap.exists():
            return
        at = f"+{round(min(self.args.duration, self.elapsed) / 2, 1):g}"  # half-way through what ran
        argv = [sys.executable, "-m", "robotmodel.cli.main", "tf2-echo", "--bag", str(mcap), "map",
                "base_footprint", "--time", at, "--no-progress"]
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
