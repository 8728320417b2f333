"""Real processes for the live TF tests: own bus per test, line waits with deadlines, always reaped."""

from __future__ import annotations

import fcntl
import os
import random
import re
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TypeVar

import pytest

HERE = Path(__file__).resolve().parent
CHILDREN = HERE / "tf_ros" / "tf_children.py"
# Where domain leases are taken: one lock file per ROS domain id, shared by every test process
# on the machine (pytest-xdist workers, a second run), so no two live tests share a domain.
_LEASES = Path(tempfile.gettempdir()) / "robotmodel-test-domains"


class DomainLease:
    """A ROS domain id (1..200: clear of 0, the default a developer may be using) no other live test holds.

    The lease is an exclusive lock on the domain's file, kept until :meth:`release` or until
    this process ends (the kernel drops it then, so a killed run leaks nothing). DDS keeps
    domains apart by id alone, so two tests on one domain would see each other's nodes.
    """

    def __init__(self) -> None:
        _LEASES.mkdir(exist_ok=True)
        for domain in random.sample(range(1, 201), 200):
            fd = os.open(_LEASES / f"{domain}.lock", os.O_RDWR | os.O_CREAT, 0o666)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                os.close(fd)
                continue
            self.domain_id, self._fd = domain, fd
            return
        raise RuntimeError("every test ROS domain id (1..200) is leased")

    def release(self) -> None:
        """Give the domain back (harmless twice)."""
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1


#: The RMW_IMPLEMENTATION that puts a robotmodel process on each wire a live test names.
RMW_OF_WIRE = {"zenoh": "rmw_zenoh_cpp", "dds": "rmw_cyclonedds_cpp"}


def set_wire(env: dict[str, str], wire: str) -> dict[str, str]:
    """Put ``env`` on ``wire`` ("zenoh" or "dds") by RMW_IMPLEMENTATION, as a user's shell would; returns it.

    A live test names its wire: robotmodel's own default (DDS unless the shell says otherwise)
    must not decide it. DDS discovery stays on loopback (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST)
    whatever the developer's shell widened, and without a ROS 1 setup's variables.
    """
    env["RMW_IMPLEMENTATION"] = RMW_OF_WIRE[wire]
    for key in ("ROS_VERSION", "ROS_MASTER_URI", "ROS_STATIC_PEERS", "ROS_LOCALHOST_ONLY"):
        env.pop(key, None)
    env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    return env


def free_port() -> int:
    """A loopback TCP port free right now (the bus's rendezvous port for one test)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Proc:
    """A child process whose stdout and stderr lines are collected as they arrive."""

    def __init__(self, argv: list[str], env: dict[str, str], cwd: Path | None = None) -> None:
        self.argv = argv
        self.popen = subprocess.Popen(argv, env=env, cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      stderr=subprocess.PIPE, text=True, bufsize=1)
        self.out: list[str] = []
        self.err: list[str] = []
        self._cond = threading.Condition()
        self._readers = [threading.Thread(target=self._read, args=(self.popen.stdout, self.out), daemon=True),
                         threading.Thread(target=self._read, args=(self.popen.stderr, self.err), daemon=True)]
        for r in self._readers:
            r.start()

    def _read(self, stream: object, lines: list[str]) -> None:
        for line in stream:  # type: ignore[attr-defined]
            with self._cond:
                lines.append(line.rstrip("\n"))
                self._cond.notify_all()

    def wait_for(self, predicate: Callable[[], bool], timeout: float, what: str) -> None:
        """Wait until ``predicate()`` (called under the line lock) holds; fail with the output at the deadline."""
        deadline = time.monotonic() + timeout
        with self._cond:
            while not predicate():
                remaining = deadline - time.monotonic()
                if remaining <= 0 or (self.popen.poll() is not None and not predicate()):
                    # Let the readers drain what is left before reporting.
                    self._cond.wait(0.2)
                    if predicate():
                        return
                    pytest.fail(f"{what}: not seen within {timeout} s (exit {self.popen.poll()})\n"
                                f"argv: {self.argv}\nstdout:\n" + "\n".join(self.out[-60:]) +
                                "\nstderr:\n" + "\n".join(self.err[-60:]))
                self._cond.wait(min(remaining, 0.2))

    def wait_line(self, pattern: str, timeout: float = 20.0, stream: str = "out") -> re.Match[str]:
        """The first line of stdout (or ``stream="err"``) matching ``pattern``, waiting for it."""
        rx = re.compile(pattern)
        lines = self.out if stream == "out" else self.err
        found: list[re.Match[str]] = []

        def seen() -> bool:
            for line in lines:
                m = rx.search(line)
                if m:
                    found.append(m)
                    return True
            return False

        self.wait_for(seen, timeout, f"line /{pattern}/ on std{stream}")
        return found[0]

    def send(self, text: str) -> None:
        """Write to the child's stdin."""
        assert self.popen.stdin is not None
        self.popen.stdin.write(text)
        self.popen.stdin.flush()

    def stop(self, sig: int = signal.SIGTERM, timeout: float = 15.0) -> int:
        """Signal the child and reap it; returns its exit code."""
        if self.popen.poll() is None:
            self.popen.send_signal(sig)
        try:
            code = self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            self.popen.kill()
            code = self.popen.wait()
            pytest.fail(f"{self.argv} did not exit within {timeout} s of signal {sig}")
        for r in self._readers:
            r.join(5)
        return code

    def kill(self) -> None:
        """SIGKILL and reap."""
        if self.popen.poll() is None:
            self.popen.kill()
        self.popen.wait()
        for r in self._readers:
            r.join(5)


class Bus:
    """One test's bus (own rendezvous port and ROS_DOMAIN_ID, on ``wire``) and the processes started on it."""

    def __init__(self, cwd: Path, wire: str = "zenoh") -> None:
        self.cwd = cwd
        self.wire = wire
        self.env = set_wire(dict(os.environ), wire)
        self.env["ROBOTMODEL_ZENOH_PORT"] = str(free_port())
        self.lease = DomainLease()
        self.env["ROS_DOMAIN_ID"] = str(self.lease.domain_id)
        self.env["PYTHONUNBUFFERED"] = "1"
        self.env.pop("ZENOH_SESSION_CONFIG_URI", None)
        self.procs: list[Proc] = []

    def start(self, *argv: str) -> Proc:
        """Start a process with this bus's environment."""
        proc = Proc(list(argv), self.env, self.cwd)
        self.procs.append(proc)
        return proc

    def robotmodel(self, *args: str) -> Proc:
        """``robotmodel ARGS`` (through this interpreter)."""
        return self.start(sys.executable, "-m", "robotmodel.cli.main", *args)

    def child(self, *args: str) -> Proc:
        """A helper from tf_children.py."""
        return self.start(sys.executable, str(CHILDREN), *args)

    def reap(self) -> None:
        """Kill whatever is still running, then give the domain back."""
        for proc in self.procs:
            proc.kill()
        self.lease.release()


B = TypeVar("B", bound=Bus)


def joined(bus: B, monkeypatch: pytest.MonkeyPatch) -> Iterator[B]:
    """Yield ``bus`` with the test process on it too (its env set); every child is reaped after."""
    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "RMW_IMPLEMENTATION", "ROS_AUTOMATIC_DISCOVERY_RANGE"):
        monkeypatch.setenv(key, bus.env[key])
    monkeypatch.delenv("ZENOH_SESSION_CONFIG_URI", raising=False)
    try:
        yield bus
    finally:
        bus.reap()


@pytest.fixture
def bus(tmp_path: Path) -> Iterator[Bus]:
    """A fresh zenoh bus for one test; every process started on it is reaped afterwards."""
    b = Bus(tmp_path, "zenoh")
    try:
        yield b
    finally:
        b.reap()
