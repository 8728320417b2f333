"""Ctrl-C in the terminal while the launched nodes are still importing: every process ends quietly.

A terminal's Ctrl-C reaches the whole foreground process group at once: the launcher and
each child (which the launcher then signals too). roslaunch's children die without a word;
ours must not print a ``KeyboardInterrupt`` traceback from the middle of their imports.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

from livebus import Bus
from procscan import assert_none_left


def _execd(pid: int) -> bool:
    try:
        return b"launch" not in Path(f"/proc/{pid}/cmdline").read_bytes()  # the launcher's, until exec
    except OSError:
        return True  # gone already


def test_ctrl_c_while_children_import_prints_no_traceback(tmp_path: Path, pkg) -> None:
    path = pkg.launch("three.launch", f"""
        <launch>
          <param name="robot_description" command="xacro {pkg.xacro}"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp"/>
          <node pkg="tf2_ros" type="static_transform_publisher" name="map_odom" args="1 2 0 0 0 0 map odom"/>
        </launch>
    """)
    bus = Bus(tmp_path, "zenoh")
    # A session of its own, so the test can send SIGINT to the whole group as a terminal does.
    proc = subprocess.Popen([sys.executable, "-m", "robotmodel.cli.main", "launch", str(path)], env=bus.env,
                            cwd=tmp_path, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    try:
        started = []
        assert proc.stderr is not None
        deadline = time.monotonic() + 60
        while len(started) < 3 and time.monotonic() < deadline:
            line = proc.stderr.readline()
            if not line:
                break
            if re.match(r"process\[[\w/-]+\]: started with pid \[\d+\]", line):
                started.append(line)
        assert len(started) == 3, started
        # Each child exec'd (its own command line): the interpreter is starting or importing, not serving yet.
        pids = [int(re.search(r"pid \[(\d+)\]", line).group(1)) for line in started]  # type: ignore[union-attr]
        while not all(_execd(pid) for pid in pids) and time.monotonic() < deadline:
            time.sleep(0.002)
        os.killpg(proc.pid, signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    text = out + err
    assert "Traceback" not in text and "KeyboardInterrupt" not in text, text
    assert proc.returncode == 0, text
    assert_none_left(bus.env["ROBOTMODEL_ZENOH_PORT"])
