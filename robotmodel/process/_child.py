"""The demo's child processes: one private bus, every line logged, all of them reaped on exit.

Each child gets the demo's environment: its own rendezvous port and ``ROS_DOMAIN_ID``, and
no zenoh configuration from the user's shell, so the demo neither joins nor disturbs
another system. On Linux a child is also killed when the demo itself dies, so not even
a ``kill -9`` of the demo leaves one running (children are started from the main thread:
the kernel sends the signal when the thread that started a child ends).
"""

from __future__ import annotations

import os
import random
import re
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path

__all__ = ["Child", "Children", "private_bus_env"]

# Sets PR_SET_PDEATHSIG (1) to SIGKILL, exits if the demo is already gone, then becomes the
# child proper: the setting survives exec. (A preexec_fn would do the same in the forked
# child, but is unsafe while the demo's reader threads run.) SIGKILL, not SIGTERM: this is
# the path for a demo that could not clean up, and a child busy shutting down its bus
# session when all its peers vanish at once may not act on a SIGTERM; the recording keeps
# every chunk flushed so far either way.
_LAUNCHER = (
    "import ctypes, os, signal, sys\n"
    "ctypes.CDLL(None).prctl(1, signal.SIGKILL)\n"
    "if os.getppid() != int(sys.argv[1]): sys.exit(1)\n"
    "os.execv(sys.argv[2], sys.argv[2:])\n"
)


def private_bus_env() -> dict[str, str]:
    """The current environment with a free loopback rendezvous port, a random domain and no zenoh config."""
    env = dict(os.environ)
    for key in ("ZENOH_SESSION_CONFIG_URI", "ZENOH_ROUTER_CONFIG_URI", "ZENOH_CONFIG_OVERRIDE"):
        env.pop(key, None)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        env["ROBOTMODEL_ZENOH_PORT"] = str(s.getsockname()[1])
    # Clear of 0, the domain a developer's own ROS 2 system is most likely on.
    env["ROS_DOMAIN_ID"] = str(random.randint(120, 200))
    env["PYTHONUNBUFFERED"] = "1"
    return env


def _launch(argv: list[str]) -> list[str]:
    """``argv`` behind the launcher on Linux; elsewhere the demo's own cleanup must do."""
    if sys.platform != "linux":
        return argv
    return [sys.executable, "-c", _LAUNCHER, str(os.getpid()), *argv]


class Child:
    """One process; its stdout and stderr lines go to a log file and are kept for :meth:`wait_line`."""

    def __init__(self, name: str, argv: list[str], env: dict[str, str], log: Path,
                 on_line: Callable[[str], None] | None = None) -> None:
        self.name = name
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self._on_line = on_line
        self._log = log.open("w", encoding="utf-8")
        # A session of its own: Ctrl-C in the terminal reaches the demo, which stops the
        # children in order (the recorder last, so it keeps everything up to the end).
        self.popen = subprocess.Popen(_launch(argv), env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, text=True, bufsize=1, start_new_session=True)
        self._reader = threading.Thread(target=self._read, name=f"demo-{name}", daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.popen.stdout is not None
        for raw in self.popen.stdout:
            line = raw.rstrip("\n")
            self._log.write(raw)
            self._log.flush()
            with self._cond:
                self.lines.append(line)
                self._cond.notify_all()
            if self._on_line is not None:
                self._on_line(line)

    def wait_line(self, pattern: str, timeout: float) -> re.Match[str] | None:
        """The first line matching ``pattern``, waiting up to ``timeout`` seconds (None if not seen)."""
        rx = re.compile(pattern)
        deadline = time.monotonic() + timeout
        seen = 0
        with self._cond:
            while True:
                for line in self.lines[seen:]:
                    found = rx.search(line)
                    if found:
                        return found
                seen = len(self.lines)
                left = deadline - time.monotonic()
                if left <= 0 or self.popen.poll() is not None:
                    return None
                self._cond.wait(min(left, 0.2))

    def stop(self, timeout: float = 10.0) -> int:
        """SIGINT (a ROS tool's clean stop), then SIGKILL after ``timeout``; returns the exit code."""
        if self.popen.poll() is None:
            self.popen.send_signal(signal.SIGINT)
        try:
            code = self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            self.popen.kill()
            code = self.popen.wait()
        self._reader.join(5)
        self._log.close()
        return code


class Children:
    """The demo's processes, stopped in reverse start order with ``last`` ones at the very end."""

    def __init__(self, env: dict[str, str], logs: Path) -> None:
        self.env = env
        self.logs = logs
        self.started: list[Child] = []

    def start(self, name: str, argv: list[str], on_line: Callable[[str], None] | None = None) -> Child:
        """Start ``argv`` as child ``name`` (its output in ``logs/NAME.log``)."""
        child = Child(name, argv, self.env, self.logs / f"{name}.log", on_line)
        self.started.append(child)
        return child

    def robotmodel(self, command: str, *args: str, on_line: Callable[[str], None] | None = None) -> Child:
        """``robotmodel COMMAND ARGS`` run by this interpreter (the child is named after COMMAND)."""
        return self.start(command, [sys.executable, "-m", "robotmodel.cli.main", command, *args], on_line)

    def example(self, name: str, *args: str) -> Child:
        """``python -m robotmodel.examples.NAME ARGS``."""
        return self.start(name, [sys.executable, "-m", f"robotmodel.examples.{name}", *args])

    def stop_all(self, last: tuple[str, ...] = ()) -> dict[str, int]:
        """Stop every child (those named in ``last`` after the others); their exit codes by name."""
        order = [c for c in reversed(self.started) if c.name not in last]
        order += [c for c in self.started if c.name in last]
        codes: dict[str, int] = {}
        # Signal the first group together, so the whole stop takes one child's time, not the sum.
        first = [c for c in order if c.name not in last]
        for child in first:
            if child.popen.poll() is None:
                child.popen.send_signal(signal.SIGINT)
        for child in order:
            codes[child.name] = child.stop()
        return codes
