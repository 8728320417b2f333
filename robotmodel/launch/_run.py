"""Running a launch file: the plan printed, then its processes under one :class:`robotmodel.process.Supervisor`."""

from __future__ import annotations

import shlex
import sys
import threading
from collections.abc import Callable, Mapping, Sequence

from robotmodel.launch._model import ProcessSpec
from robotmodel.process import Supervisor
from robotmodel.signals import stop_on_signals

__all__ = ["run_launch", "run_processes"]


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


def run_launch(target: str, file: str | None = None, mappings: Mapping[str, str] | None = None, *,
               package_paths: Sequence[str] = (), dry_run: bool = False, browser: bool = True,
               show_args: bool = False) -> int:
    """``roslaunch FILE`` (``file`` None: ``target`` is the file) or ``roslaunch PKG FILE``: plan, print, run.

    On the ROS 1 wire the file's parameters go to the parameter server first, as roslaunch
    puts them there, and the nodes read robot_description from it. Prints the notes and
    skipped nodes, then (unless ``dry_run``, which prints the command lines) runs the
    processes until SIGINT/SIGTERM, a required exit or all exits. A Python launch file
    (``*.py``) runs as ``ros2 launch`` runs it (:mod:`robotmodel.launch._pyload`), a
    ROS 2 YAML one (``*.yaml``) is read as its XML equivalent;
    ``show_args`` prints its arguments instead, as ``ros2 launch --show-args``. Bad input raises
    :class:`robotmodel.errors.LaunchError`. Returns the exit code.
    """
    import shutil
    import tempfile
    from pathlib import Path

    from robotmodel.errors import LaunchError
    from robotmodel.launch._files import load_launch_file
    from robotmodel.launch._find import find_launch_file
    from robotmodel.launch._kinds import build_plan
    from robotmodel.rcl import ros1_wire

    paths = [Path(p).resolve() for p in package_paths]
    if file is None:
        path = Path(target)
        if not path.is_file():
            raise LaunchError(f"{path}: no such launch file")
    else:
        path = find_launch_file(target, file, paths)
    if path.suffix == ".py":
        from robotmodel.launch._pyload import load_python_launch, show_arguments

        if show_args:
            print(show_arguments(path, paths), end="", flush=True)
            return 0
        launch = load_python_launch(path, dict(mappings or {}), paths)
    elif show_args:
        raise LaunchError(f"{path}: --show-args reads Python launch files (.launch.py)")
    elif path.name.endswith((".yaml", ".yml")):
        from robotmodel.launch._pysources import load_yaml_launch

        launch = load_yaml_launch(path, dict(mappings or {}), paths)
    else:
        launch = load_launch_file(path, dict(mappings or {}), paths)
    ros1 = ros1_wire()
    if ros1 and not dry_run:
        from robotmodel.launch._ros1params import set_on_server

        set_on_server(launch, paths)  # before any node starts, as roslaunch does
    workdir = Path(tempfile.mkdtemp(prefix="robotmodel-launch-"))
    try:
        plan = build_plan(launch, workdir, package_paths=paths, browser=browser, ros1=ros1)
        for note in plan.notes:
            print(f"note: {note}", file=sys.stderr)
        for line in plan.skipped:
            print(f"skipped: {line}", flush=True)
        if dry_run:
            for spec in plan.processes:
                print(f"{spec.name}: robotmodel {shlex.join(spec.argv)}")
            return 0
        if not plan.processes:
            print("nothing to start", file=sys.stderr)
            return 0
        return run_processes(plan.processes)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
