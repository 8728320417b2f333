"""Running a plan: every process started, watched, and stopped together.

As roslaunch: each start and each death is reported on one line; a node marked
``required`` that exits brings the whole launch down; when every process has exited the
launch ends. SIGINT or SIGTERM stop everything: SIGINT to each process, SIGTERM to those
still running after a grace period, SIGKILL last, and every process is reaped. On Linux
the children also get SIGTERM if the supervisor itself dies without cleaning up.
"""

from __future__ import annotations

import contextlib
import ctypes
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Sequence

from robotmodel.launch._model import ProcessSpec
from robotmodel.signals import stop_on_signals

__all__ = ["run_processes"]

_SIGINT_GRACE = 10.0
_SIGTERM_GRACE = 3.0
_POLL = 0.1


def _die_with_parent() -> None:
    # Runs in the child between fork and exec: ask the kernel for SIGTERM when the parent dies.
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


def _argv(spec: ProcessSpec) -> list[str]:
    return [sys.executable, "-m", "robotmodel.cli.main", *spec.argv]


def run_processes(specs: Sequence[ProcessSpec], *, log: Callable[[str], None] | None = None,
                  stop: threading.Event | None = None) -> int:
    """Start ``specs``, wait until a signal, a required exit or all exits; returns the exit code.

    The code is 0 after a stop signal or clean exits, 1 when a process failed on its own.
    Installs SIGINT/SIGTERM handlers (main thread only) unless ``stop`` is given.
    """
    say = log or (lambda text: print(text, file=sys.stderr, flush=True))
    if stop is None:
        stop = stop_on_signals()
    running: dict[int, tuple[str, subprocess.Popen[bytes]]] = {}
    failed = False
    try:
        for index, spec in enumerate(specs, start=1):
            if stop.is_set():
                break
            label = f"{spec.name.lstrip('/') or spec.kind}-{index}"
            # The launcher runs no threads of its own, so preexec_fn is safe here.
            preexec = _die_with_parent if sys.platform == "linux" else None
            popen = subprocess.Popen(_argv(spec), stdin=subprocess.DEVNULL, preexec_fn=preexec)  # noqa: PLW1509
            running[index] = (label, popen)
            say(f"process[{label}]: started with pid [{popen.pid}]")
        required = {i for i, spec in enumerate(specs, start=1) if spec.required}
        while running and not stop.wait(_POLL):
            for index, (label, popen) in list(running.items()):
                code = popen.poll()
                if code is None:
                    continue
                del running[index]
                if code == 0:
                    say(f"[{label}] process has finished cleanly")
                else:
                    failed = True
                    say(f"[{label}] process has died [pid {popen.pid}, exit code {code}]")
                if index in required:
                    say(f"[{label}] required process has exited, shutting down")
                    stop.set()
    finally:
        _stop_all([p for _, p in running.values()])
    return 1 if failed else 0


def _stop_all(procs: list[subprocess.Popen[bytes]]) -> None:
    for sig, grace in ((signal.SIGINT, _SIGINT_GRACE), (signal.SIGTERM, _SIGTERM_GRACE)):
        alive = [p for p in procs if p.poll() is None]
        for p in alive:
            with contextlib.suppress(ProcessLookupError):
                p.send_signal(sig)
        deadline = time.monotonic() + grace
        while any(p.poll() is None for p in alive) and time.monotonic() < deadline:
            time.sleep(0.05)
    for p in procs:
        if p.poll() is None:
            p.kill()
        p.wait()
