"""Real ROS 1 for tests/ros1: a private roscore per test (Debian 12's), rospy peers, robotmodel nodes.

Each test gets its own master port, ROS_HOME and ROS_HOSTNAME=127.0.0.1. Processes start in
their own process group, killed at the end; roslaunch starts rosmaster and rosout in sessions
of their own, so every process holding the test's ROS_HOME is killed as well. Skips with one line where Debian's ROS 1 is not installed.
"""

from __future__ import annotations

import contextlib
import os
import random
import re
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from robotmodel.errors import MasterError
from robotmodel.ros1 import MasterClient, Ros1Node

PEER = Path(__file__).resolve().parent / "ros1" / "rospy_peer.py"
RM_PEER = PEER.with_name("rm_peer.py")
SYSTEM_PYTHON = "/usr/bin/python3"


def _have_ros1() -> str | None:
    if shutil.which("roscore") is None:
        return "Debian's ROS 1 is absent (no roscore on PATH)"
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import rospy, std_msgs.msg, tf2_msgs.msg"],
                           capture_output=True, check=False)
    if probe.returncode != 0:
        return "Debian's ROS 1 is absent (/usr/bin/python3 cannot import rospy)"
    return None


MISSING = _have_ros1()


def free_port() -> int:
    """A loopback TCP port free right now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def master_port() -> int:
    """A free loopback port below the kernel's ephemeral range, for a roscore.

    Below that range no other process's ``bind(0)`` (a TCPROS server, a slave API, a test's
    free_port) can take it between this check and roscore's own bind.
    """
    low = int(Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split()[0])
    while True:
        port = random.randrange(10000, max(low, 10001))
        with socket.socket() as s:
            try:
                s.bind(("127.0.0.1", port))
            except OSError:
                continue
            return port


def wait_until(predicate: Callable[[], Any], timeout: float, what: str) -> Any:
    """Poll ``predicate`` until it returns something truthy; fail naming ``what`` at the deadline."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            pytest.fail(f"{what}: not within {timeout} s")
        time.sleep(0.05)


class GroupProc:
    """A child in its own process group whose output lines are collected as they arrive."""

    def __init__(self, argv: list[str], env: dict[str, str]) -> None:
        self.argv = argv
        self.popen = subprocess.Popen(argv, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, text=True, bufsize=1, start_new_session=True)
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.popen.stdout is not None
        for line in self.popen.stdout:
            with self._cond:
                self.lines.append(line.rstrip("\n"))
                self._cond.notify_all()

    def wait_line(self, pattern: str, timeout: float = 30.0) -> re.Match[str]:
        """The first output line matching ``pattern``; fails with the output at the deadline."""
        rx = re.compile(pattern)
        deadline = time.monotonic() + timeout
        with self._cond:
            while True:
                for line in self.lines:
                    if m := rx.search(line):
                        return m
                remaining = deadline - time.monotonic()
                if remaining <= 0 or (self.popen.poll() is not None and not self._reader.is_alive()):
                    pytest.fail(f"/{pattern}/ not printed within {timeout} s by {self.argv} "
                                f"(exit {self.popen.poll()}):\n" + "\n".join(self.lines[-40:]))
                self._cond.wait(min(remaining, 0.2))

    def count(self, pattern: str) -> int:
        """How many output lines so far match ``pattern``."""
        rx = re.compile(pattern)
        with self._cond:
            return sum(1 for line in self.lines if rx.search(line))

    def kill(self, sig: int = signal.SIGKILL) -> None:
        """Signal the whole process group and reap the child."""
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self.popen.pid, sig)
        try:
            self.popen.wait(15)
        except subprocess.TimeoutExpired:
            os.killpg(self.popen.pid, signal.SIGKILL)
            self.popen.wait()
        self._reader.join(5)


class Ros1World:
    """One test's private roscore and everything started against it."""

    def __init__(self, home: Path) -> None:
        home.mkdir(parents=True, exist_ok=True)
        self.home = home
        self.procs: list[GroupProc] = []
        self.nodes: list[Ros1Node] = []
        # Should the port be taken all the same (another test's roscore picked it), roscore
        # exits or never answers: after 30 s another port is tried.
        for _ in range(3):
            self.port = master_port()
            self.uri = f"http://127.0.0.1:{self.port}"
            self.env = dict(os.environ)
            self.env.update(ROS_MASTER_URI=self.uri, ROS_HOSTNAME="127.0.0.1", ROS_HOME=str(home),
                            ROS_LOG_DIR=str(home / "log"), PYTHONUNBUFFERED="1")
            for var in ("ROS_IP", "ROS_NAMESPACE"):
                self.env.pop(var, None)
            self.master = MasterClient(self.uri, "/pytest")
            self.roscore = self.start("roscore", "-p", str(self.port))
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline and self.roscore.popen.poll() is None:
                if self._master_up():
                    return
                time.sleep(0.1)
            if self._master_up():
                return
            self.reap()
            self.procs.clear()
        pytest.fail(f"roscore did not start on three ports; last output: {self.roscore.lines[-5:]}")

    def _master_up(self) -> bool:
        try:
            self.master.get_uri()
            # rosout registering its /rosout subscription is the last step of roscore's start
            _, subs, _ = self.master.get_system_state()
        except MasterError:
            return False
        return any(topic == "/rosout" for topic, _ in subs)

    def start(self, *argv: str) -> GroupProc:
        """Start ``argv`` in its own process group against this master."""
        proc = GroupProc(list(argv), self.env)
        self.procs.append(proc)
        return proc

    def rospy(self, *args: str) -> GroupProc:
        """A rospy peer (tests/ros1/rospy_peer.py) under Debian's Python."""
        return self.start(SYSTEM_PYTHON, str(PEER), *args)

    def robotmodel_peer(self, *args: str) -> GroupProc:
        """A robotmodel node in its own process (tests/ros1/rm_peer.py) under the project's Python."""
        return self.start(sys.executable, str(RM_PEER), *args)

    def tool(self, *argv: str, timeout: float = 60) -> str:
        """Run a real ROS 1 command line tool to its end; its stdout and stderr."""
        done = subprocess.run(list(argv), env=self.env, capture_output=True, text=True, timeout=timeout,
                              check=False, start_new_session=True)
        return done.stdout + done.stderr

    def node(self, name: str, **kwargs: Any) -> Ros1Node:
        """A robotmodel node on this master, closed at the end of the test."""
        node = Ros1Node(name, master_uri=self.uri, env=self.env, **kwargs)
        self.nodes.append(node)
        return node

    def registrations_of(self, node_name: str) -> list[str]:
        """Every registration (publisher, subscriber, service) the master holds for ``node_name``."""
        found = []
        for kind, entries in zip(("pub", "sub", "srv"), self.master.get_system_state(), strict=True):
            found += [f"{kind} {name}" for name, nodes in entries if node_name in nodes]
        return found

    def started_here(self) -> list[int]:
        """Pids of live processes started with this world's ROS_HOME (roslaunch puts rosmaster and rosout
        in sessions of their own, so roscore's process group does not hold them)."""
        needle = f"ROS_HOME={self.home}".encode()
        found = []
        for entry in Path("/proc").iterdir():
            if not entry.name.isdigit():
                continue
            try:
                environ = (entry / "environ").read_bytes()
                state = (entry / "stat").read_text().rsplit(")", 1)[1].split()[0]
            except (OSError, IndexError):
                continue
            if state != "Z" and needle in environ.split(b"\0"):
                found.append(int(entry.name))
        return found

    def kill_master(self) -> None:
        """SIGKILL roscore, rosmaster and rosout of this world."""
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self.roscore.popen.pid, signal.SIGKILL)
        for pid in self.started_here():
            with contextlib.suppress(OSError):
                cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
                if b"rosmaster" in cmdline or b"rosout" in cmdline:
                    os.kill(pid, signal.SIGKILL)
        wait_until(lambda: not any(b"rosmaster" in _cmdline(pid) or b"rosout" in _cmdline(pid)
                                   for pid in self.started_here()), 60, "the master's processes to end")
        self.roscore.kill()

    def restart_master(self) -> None:
        """A new roscore on the same port, after :meth:`kill_master` (its registrations and parameters are gone)."""
        self.roscore = self.start("roscore", "-p", str(self.port))
        wait_until(self._master_up, 60, f"the restarted roscore on {self.uri}")

    def reap(self) -> None:
        """Close our nodes, kill every process group and anything else left on this master, then reap."""
        for node in self.nodes:
            node.close()
        for proc in reversed(self.procs):
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.popen.pid, signal.SIGKILL)
        # before waiting for output to end: rosmaster and rosout hold roscore's stdout open
        for pid in self.started_here():
            with contextlib.suppress(OSError):
                os.kill(pid, signal.SIGKILL)
        for proc in self.procs:
            proc.kill()
        wait_until(lambda: not self.started_here(), 60, f"every process on {self.uri} to end")


def _cmdline(pid: int) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""



def system_python_md5(type_module: str, type_name: str) -> str:
    """The md5sum Debian's ROS 1 message class gives, read by its own Python."""
    code = f"from {type_module} import {type_name} as T; print(T._md5sum)"
    return subprocess.run([SYSTEM_PYTHON, "-c", code], capture_output=True, text=True, check=True).stdout.strip()

