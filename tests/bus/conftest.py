"""Fixtures for bus tests with real processes: a private port and domain, and reaped children."""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from livebus import DomainLease, set_wire

PEER = Path(__file__).with_name("peer.py")


def free_port() -> int:
    """A loopback port nobody listens on right now."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Proc:
    """A child process in its own process group, its stdout collected line by line."""

    def __init__(self, args: list[str], env: dict[str, str]) -> None:
        self.args = args
        self.popen = subprocess.Popen(
            args, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            text=True, start_new_session=True)
        self.lines: list[str] = []
        self.errors: list[str] = []
        self._cond = threading.Condition()
        threading.Thread(target=self._read, args=(self.popen.stdout, self.lines), daemon=True).start()
        threading.Thread(target=self._read, args=(self.popen.stderr, self.errors), daemon=True).start()

    def _read(self, stream: object, into: list[str]) -> None:
        for line in stream:  # type: ignore[attr-defined]
            with self._cond:
                into.append(line.rstrip("\n"))
                self._cond.notify_all()

    def wait_for(self, predicate: Callable[[list[str]], bool], timeout: float = 20.0,
                 stream: str = "stdout") -> bool:
        """Wait until ``predicate(lines)`` holds for the collected stdout (or stderr) lines."""
        lines = self.lines if stream == "stdout" else self.errors
        with self._cond:
            return self._cond.wait_for(lambda: predicate(lines), timeout)

    def wait_line(self, prefix: str, timeout: float = 20.0) -> str:
        """The first stdout line starting with ``prefix``; fails the test at the deadline."""
        found: list[str] = []

        def has(lines: list[str]) -> bool:
            found[:] = [ln for ln in lines if ln.startswith(prefix)][:1]
            return bool(found) or self.popen.poll() is not None

        self.wait_for(has, timeout)
        if not found:
            self.wait_for(lambda _: False, 0.2)  # let the readers catch the last output
            pytest.fail(f"no line '{prefix}...' from {self.args[-3:]} in {timeout} s; "
                        f"stdout={self.lines[-5:]} stderr={self.errors[-10:]}")
        return found[0]

    def kill(self) -> None:
        """SIGKILL the whole process group."""
        if self.popen.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.popen.pid, signal.SIGKILL)
        self.popen.wait(10)

    def terminate(self, timeout: float = 10.0) -> int:
        """SIGTERM the process (as a service manager stops it) and wait; kill at the deadline."""
        self.popen.send_signal(signal.SIGTERM)
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            return -9

    def stop(self, timeout: float = 10.0) -> int:
        """Close stdin (the peers' signal to finish) and wait; kill at the deadline."""
        try:
            if self.popen.stdin:
                self.popen.stdin.close()
        except BrokenPipeError:
            pass
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            return -9


class Procs:
    """Starts processes with the test's bus environment and reaps all of them."""

    def __init__(self, env: dict[str, str]) -> None:
        self.env = env
        self.started: list[Proc] = []

    @staticmethod
    def peer_args(*args: str) -> list[str]:
        return [sys.executable, str(PEER), *args]

    @staticmethod
    def cli_args(*args: str) -> list[str]:
        return [sys.executable, "-m", "robotmodel.cli.main", *args]

    def peer(self, *args: str) -> Proc:
        return self.run(self.peer_args(*args))

    def cli(self, *args: str) -> Proc:
        return self.run(self.cli_args(*args))

    def run(self, args: list[str], env: dict[str, str] | None = None) -> Proc:
        proc = Proc(args, self.env if env is None else env)
        self.started.append(proc)
        return proc

    def reap(self) -> None:
        for proc in self.started:
            proc.kill()


@pytest.fixture
def bus_wire() -> str:
    """The wire the processes of a test here speak (tests/bus/dds overrides it with "dds")."""
    return "zenoh"


@pytest.fixture
def bus_env(monkeypatch: pytest.MonkeyPatch, bus_wire: str) -> Iterator[dict[str, str]]:
    """An environment on ``bus_wire`` with a private rendezvous port and ROS domain, also set for this process."""
    lease = DomainLease()
    env = set_wire(dict(os.environ), bus_wire)
    env["ROBOTMODEL_ZENOH_PORT"] = str(free_port())
    env["ROS_DOMAIN_ID"] = str(lease.domain_id)
    env.pop("ZENOH_SESSION_CONFIG_URI", None)
    env.pop("ZENOH_CONFIG_OVERRIDE", None)
    env["PYTHONUNBUFFERED"] = "1"
    for key in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "RMW_IMPLEMENTATION", "ROS_AUTOMATIC_DISCOVERY_RANGE"):
        monkeypatch.setenv(key, env[key])
    for key in ("ROS_VERSION", "ROS_MASTER_URI", "ROS_STATIC_PEERS", "ROS_LOCALHOST_ONLY"):
        monkeypatch.delenv(key, raising=False)
    monkeypatch.delenv("ZENOH_SESSION_CONFIG_URI", raising=False)
    monkeypatch.delenv("ZENOH_CONFIG_OVERRIDE", raising=False)
    try:
        yield env
    finally:
        lease.release()


@pytest.fixture
def procs(bus_env: dict[str, str]) -> Iterator[Procs]:
    """Process starter; everything it started is killed at the end of the test."""
    p = Procs(bus_env)
    try:
        yield p
    finally:
        p.reap()


def deadline(seconds: float) -> Callable[[], bool]:
    """A callable that turns False once ``seconds`` have passed."""
    end = time.monotonic() + seconds
    return lambda: time.monotonic() < end


@pytest.fixture
def new_port() -> Callable[[], int]:
    """Gives loopback ports nobody listens on."""
    return free_port
