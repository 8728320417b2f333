"""One child process of a supervisor: how it is started, its output, its stop.

Every child we start is a Python module of the installed package, run as
``python -P -c BOOT ...`` (:func:`module_argv`):

- ``-P`` (Python 3.11's safe path) keeps the current directory off ``sys.path``: from a
  clone's root, ``python -m robotmodel...`` would import the source folder ``robotmodel/``
  (without ``cli/`` and ``robots/``, which only the install maps into it) instead of the
  installed package. ``-P`` changes nothing else (unlike ``-I``, it keeps ``PYTHONPATH`` and
  ``PYTHONUNBUFFERED``).
- SIGINT is blocked while the child starts (the supervisor blocks it around the spawn, and
  the mask survives exec), and BOOT's first act is to make SIGINT kill the process outright
  (SIG_DFL) and unblock it: a Ctrl-C (or the supervisor's SIGINT) that lands while the child
  is still importing ends it quietly, as a roslaunch child ends, instead of printing a
  ``KeyboardInterrupt`` traceback; a command then installs its own clean-stop handlers
  (:func:`robotmodel.signals.stop_on_signals`).
- On Linux BOOT asks the kernel for a signal when the supervisor dies (PR_SET_PDEATHSIG),
  so not even a ``kill -9`` of the supervisor leaves a child running (children are started
  from the thread that lives as long as the supervisor: the kernel sends the signal when the
  thread that started a child ends), and exits if the supervisor is already gone.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any

__all__ = ["Child", "command_argv", "module_argv", "spawn"]

_BOOT = (
    "import os, signal, sys\n"
    "signal.signal(signal.SIGINT, signal.SIG_DFL)\n"
    "signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})\n"
    "if sys.platform == 'linux' and int(sys.argv[1]):\n"
    "    import ctypes\n"
    "    ctypes.CDLL(None).prctl(1, int(sys.argv[1]))\n"
    "    if os.getppid() != int(sys.argv[2]): sys.exit(1)\n"
    "import runpy\n"
    "module = sys.argv[3]\n"
    "del sys.argv[1:4]\n"
    "runpy.run_module(module, run_name='__main__', alter_sys=True)\n"
)

#: The module the ``robotmodel`` console script runs.
COMMAND_MODULE = "robotmodel.cli.main"


def module_argv(module: str, *args: str, orphan_signal: int = signal.SIGTERM) -> list[str]:
    """``python -m MODULE ARGS`` for a child of this process, loading the installed package whatever the cwd.

    ``orphan_signal`` is the signal the child gets if this process dies (Linux; 0: none).
    """
    return [sys.executable, "-P", "-c", _BOOT, str(int(orphan_signal)), str(os.getpid()), module, *args]


def command_argv(*words: str, orphan_signal: int = signal.SIGTERM) -> list[str]:
    """``robotmodel WORDS`` as a child of this process (see :func:`module_argv`)."""
    return module_argv(COMMAND_MODULE, *words, orphan_signal=orphan_signal)


@contextlib.contextmanager
def _sigint_blocked() -> Iterator[None]:
    # The calling thread's mask is what the child inherits; the process's other threads still take SIGINT.
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def spawn(argv: list[str], **popen: Any) -> subprocess.Popen[Any]:
    """``subprocess.Popen(argv, **popen)`` with SIGINT blocked in the child until its BOOT takes it.

    For an argv from :func:`module_argv`: a Ctrl-C that reaches the child while Python
    starts (before any code of ours could run) then waits for BOOT, which ends the child quietly.
    """
    with _sigint_blocked():
        return subprocess.Popen(argv, **popen)


class Child:
    """One process; with a ``log`` its stdout and stderr lines go there and are kept for :meth:`wait_line`.

    Without a log the child writes to this process's stdout and stderr (as roslaunch's
    children do). ``new_session`` puts it in a session of its own, out of reach of the
    terminal's Ctrl-C, so the supervisor alone decides when and in which order it stops.
    """

    def __init__(self, name: str, argv: list[str], *, env: Mapping[str, str] | None = None, log: Path | None = None,
                 on_line: Callable[[str], None] | None = None, new_session: bool = False) -> None:
        self.name = name
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self._on_line = on_line
        self._log = log.open("w", encoding="utf-8") if log is not None else None
        piped = subprocess.PIPE if log is not None else None
        self.popen = spawn(argv, env=None if env is None else dict(env), stdin=subprocess.DEVNULL, stdout=piped,
                           stderr=subprocess.STDOUT if piped else None, text=True, bufsize=1,
                           start_new_session=new_session)
        self._reader: threading.Thread | None = None
        if self._log is not None:
            self._reader = threading.Thread(target=self._read, name=f"child-{name}", daemon=True)
            self._reader.start()

    @property
    def pid(self) -> int:
        """The child's process id."""
        return self.popen.pid

    def poll(self) -> int | None:
        """The exit code once the child has ended (negative: killed by that signal), else None."""
        return self.popen.poll()

    def _read(self) -> None:
        assert self.popen.stdout is not None and self._log is not None
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
        """The first logged line matching ``pattern``, waiting up to ``timeout`` seconds (None if not seen)."""
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

    def signal(self, signum: int) -> None:
        """Send ``signum`` if the child is still running."""
        if self.popen.poll() is None:
            with contextlib.suppress(ProcessLookupError):
                self.popen.send_signal(signum)

    def reap(self) -> int:
        """Kill the child if it still runs, wait for it and its output; returns its exit code."""
        if self.popen.poll() is None:
            self.popen.kill()
        code = self.popen.wait()
        if self._reader is not None:
            self._reader.join(5)
        if self._log is not None:
            self._log.close()
        return code
