"""One supervisor for every group of processes we start: ``robotmodel launch``'s nodes and the demo's parts.

As roslaunch: each start and each death can be reported on one line (:meth:`Supervisor.watch`);
a child marked ``required`` that exits brings the whole group down; when every child has
exited the watch ends. Stopping (:meth:`Supervisor.stop_all`) sends SIGINT to every child,
SIGTERM to those still running after a grace period, SIGKILL last, and reaps them all;
children named ``last`` are stopped after the others (the demo's recorder, so it keeps
everything up to the end). See :mod:`robotmodel.process._child` for how each child starts:
the installed package whatever the current directory, quiet on an early SIGINT, and gone
when the supervisor dies.
"""

from __future__ import annotations

import signal
import sys
import threading
import time
from collections.abc import Callable, Collection, Mapping
from pathlib import Path

from robotmodel.process._child import Child, command_argv, module_argv

__all__ = ["Supervisor"]

_POLL = 0.1


class Supervisor:
    """Children started, watched and stopped together.

    ``env`` is every child's environment (None: this process's). With ``logs`` (a folder)
    each child's output goes to ``logs/NAME.log`` and the children run in sessions of their
    own (the terminal's Ctrl-C reaches only the supervisor, which stops them in order);
    without it they share this process's terminal and output, as roslaunch's children do.
    ``orphan_signal`` is what a child gets from the kernel if the supervisor dies (Linux).
    ``say`` receives the report lines (default: stderr).
    """

    def __init__(self, *, env: Mapping[str, str] | None = None, logs: Path | None = None,
                 orphan_signal: int = signal.SIGTERM, say: Callable[[str], None] | None = None,
                 sigint_grace: float = 10.0, sigterm_grace: float = 3.0) -> None:
        self.env = env
        self.logs = logs
        self.orphan_signal = orphan_signal
        self.say = say or (lambda text: print(text, file=sys.stderr, flush=True))
        self.sigint_grace = sigint_grace
        self.sigterm_grace = sigterm_grace
        self.started: list[Child] = []
        self.required: set[str] = set()
        self._reported: set[str] = set()

    def start(self, name: str, argv: list[str], *, on_line: Callable[[str], None] | None = None,
              required: bool = False) -> Child:
        """Start ``argv`` as child ``name`` (see :func:`robotmodel.process.module_argv` for a Python module)."""
        log = self.logs / f"{name}.log" if self.logs is not None else None
        child = Child(name, argv, env=self.env, log=log, on_line=on_line, new_session=self.logs is not None)
        self.started.append(child)
        if required:
            self.required.add(name)
        return child

    def module(self, name: str, module: str, *args: str, on_line: Callable[[str], None] | None = None,
               required: bool = False) -> Child:
        """``python -m MODULE ARGS`` as child ``name``, on the installed package."""
        return self.start(name, module_argv(module, *args, orphan_signal=self.orphan_signal), on_line=on_line,
                          required=required)

    def command(self, name: str, *words: str, on_line: Callable[[str], None] | None = None,
                required: bool = False) -> Child:
        """``robotmodel WORDS`` as child ``name``."""
        return self.start(name, command_argv(*words, orphan_signal=self.orphan_signal), on_line=on_line,
                          required=required)

    def watch(self, stop: threading.Event) -> bool:
        """Report deaths until ``stop`` is set, a required child exits (which sets it) or none is left.

        Returns whether a child failed on its own (a non-zero exit before the stop).
        """
        failed = False
        while not stop.wait(_POLL):
            running = 0
            for child in self.started:
                code = child.poll()
                if code is None:
                    running += 1
                    continue
                if child.name in self._reported:
                    continue
                self._reported.add(child.name)
                if code == 0:
                    self.say(f"[{child.name}] process has finished cleanly")
                else:
                    # Killed by a SIGINT (a terminal's Ctrl-C reaches the group): a stop, not a failure.
                    failed = failed or code != -signal.SIGINT
                    self.say(f"[{child.name}] process has died [pid {child.pid}, exit code {code}]")
                if child.name in self.required:
                    self.say(f"[{child.name}] required process has exited, shutting down")
                    stop.set()
            if not running:
                break
        return failed

    def stop_all(self, last: Collection[str] = ()) -> dict[str, int]:
        """Stop every child (those named in ``last`` after the others) and reap it; exit codes by name.

        Each group gets SIGINT together (a ROS tool's clean stop), SIGTERM after
        ``sigint_grace`` seconds, SIGKILL after ``sigterm_grace`` more.
        """
        first = [c for c in reversed(self.started) if c.name not in last]
        then = [c for c in self.started if c.name in last]
        for group in (first, then):
            for signum, grace in ((signal.SIGINT, self.sigint_grace), (signal.SIGTERM, self.sigterm_grace)):
                alive = [c for c in group if c.poll() is None]
                for child in alive:
                    child.signal(signum)
                deadline = time.monotonic() + grace
                while any(c.poll() is None for c in alive) and time.monotonic() < deadline:
                    time.sleep(0.05)
        return {child.name: child.reap() for child in [*first, *then]}
