"""Running a plan: its processes under one :class:`robotmodel.process.Supervisor`, reported as roslaunch does."""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable, Sequence

from robotmodel.launch._model import ProcessSpec
from robotmodel.process import Supervisor
from robotmodel.signals import stop_on_signals

__all__ = ["run_processes"]


def run_processes(specs: Sequence[ProcessSpec], *, log: Callable[[str], None] | None = None,
                  stop: threading.Event | None = None) -> int:
    """Start ``specs``, wait until a signal, a required exit or all exits; stop and reap them all.

    Each start and death is reported on one line (to ``log``, default stderr). Returns 0
    after a stop signal or clean exits, 1 when a process failed on its own. Installs
    SIGINT/SIGTERM handlers (main thread only) unless ``stop`` is given.
    """
    say = log or (lambda text: print(text, file=sys.stderr, flush=True))
    if stop is None:
        stop = stop_on_signals()
    supervisor = Supervisor(say=say)
    failed = False
    try:
        for index, spec in enumerate(specs, start=1):
            if stop.is_set():
                break
            label = f"{spec.name.lstrip('/') or spec.kind}-{index}"
            child = supervisor.command(label, *spec.argv, required=spec.required)
            say(f"process[{label}]: started with pid [{child.pid}]")
        failed = supervisor.watch(stop)
    finally:
        supervisor.stop_all()
    return 1 if failed else 0
