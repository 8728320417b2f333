"""robot_state_publisher's CPU per joint_states message: robotmodel's process vs the real C++ one (ROS 1, KDL).

One private roscore (Debian's). For Panda and Talos (``talos_full_v2``, example-robot-data),
each publisher in turn: Debian's C++ ``robot_state_publisher`` (robot_description on the
parameter server, ``~publish_frequency`` 1e6 so that no message is skipped) or ``robotmodel
robot-state-publisher FILE --publish-frequency 0`` (no cap) on robotmodel's ROS 1 wire. This
process publishes the same stream to both: N JointStates of every movable joint (values
moving, stamps 1 ms apart) at ~1 kHz, and reads /tf until the last stamp comes back. The
figure is the publisher process's CPU time (utime + stime from /proc) over the stream,
divided by N. The machine's load moves both figures (the C++ one falls as load rises: its
wake-ups then serve several messages), so each robot runs three rounds, the two publishers
side by side in ABBA order, and the median ratio is the result. Goal (issue 23):
robotmodel <= 1.0x the C++ one.

Run: python benchmarks/bench_rsp_ros1.py [--quick]   (needs Debian's ROS 1 and ros-robot-state-publisher)
"""

from __future__ import annotations

import math
import os
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import threading
import time
import xmlrpc.client
from pathlib import Path
from typing import Any

import _harness

QUICK = "--quick" in sys.argv
N = 500 if QUICK else 3_000
ROUNDS = 1 if QUICK else 3
ROBOTS = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix" / "share" / "example-robot-data" / "robots"
PANDA = ROBOTS / "panda_description" / "urdf" / "panda.urdf"
TALOS = ROBOTS / "talos_data" / "robots" / "talos_full_v2.urdf"
REAL_RSP = "/usr/lib/robot_state_publisher/robot_state_publisher"
TICK = os.sysconf("SC_CLK_TCK")


def cpu_s(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICK


def run(impl: str, urdf: Path, env: dict[str, str], uri: str) -> float:
    from robotmodel.bus import History, Node, QoS
    from robotmodel.model import load
    from robotmodel.msgs import JointState, TFMessage

    desc = load(urdf)
    moving = ("revolute", "continuous", "prismatic")
    joints = [j.name for j in desc.joints if j.type.value in moving and j.mimic is None]
    if impl == "c++":
        xmlrpc.client.ServerProxy(uri).setParam("/bench", "/robot_description", desc.source_text)
        argv = [REAL_RSP, "_publish_frequency:=1000000.0"]
    else:
        argv = [sys.executable, "-m", "robotmodel.cli.main", "robot-state-publisher", str(urdf),
                "--publish-frequency", "0"]
    log = tempfile.TemporaryFile("w+")  # noqa: SIM115 (read on failure, closed in finally)
    proc = subprocess.Popen(argv, env=dict(env, ROS_VERSION="1"), stdin=subprocess.DEVNULL, stdout=log, stderr=log,
                            start_new_session=True)
    last = threading.Event()
    final_ns = 0

    def on_tf(msg: Any) -> None:
        for t in msg.transforms:
            if t.header.stamp.sec * 1_000_000_000 + t.header.stamp.nanosec == final_ns:
                last.set()

    try:
        with Node(f"bench_rsp_{impl.replace('+', 'p')}", backend="ros1") as node:
            pub = node.create_publisher(JointState, "/joint_states", QoS(0, history=History.KEEP_ALL))
            node.create_subscription(TFMessage, "/tf", on_tf, QoS(0, history=History.KEEP_ALL))
            deadline = time.monotonic() + 60
            while not pub.matched():
                if time.monotonic() > deadline or proc.poll() is not None:
                    log.seek(0)
                    raise RuntimeError(f"the {impl} robot_state_publisher did not subscribe to /joint_states: "
                                       f"{log.read()[-2000:]}")
                time.sleep(0.05)
            time.sleep(1.0)
            base = time.time_ns() // 1_000_000 * 1_000_000
            msgs = []
            for k in range(N):
                msg = JointState()
                msg.header.stamp.sec, msg.header.stamp.nanosec = divmod(base + k * 1_000_000, 1_000_000_000)
                msg.name = list(joints)
                msg.position = [0.3 * math.sin(0.01 * k + j) for j in range(len(joints))]
                msgs.append(msg)
            final_ns = base + (N - 1) * 1_000_000
            cpu0 = cpu_s(proc.pid)
            start = time.monotonic()
            for k, msg in enumerate(msgs):
                pub.publish(msg)
                delay = start + (k + 1) * 0.001 - time.monotonic()
                if delay > 0:
                    time.sleep(delay)
            if not last.wait(60):
                raise RuntimeError(f"the {impl} robot_state_publisher never published the last stamp")
            return (cpu_s(proc.pid) - cpu0) / N
    finally:
        _harness.interrupt(proc, 10)
        log.close()
        if impl == "c++":  # its private parameter stays on the server and would reach robotmodel's node
            xmlrpc.client.ServerProxy(uri).deleteParam("/bench", "/robot_state_publisher/publish_frequency")


def main() -> int:
    with _harness.private_roscore() as env:
        os.environ.update({k: env[k] for k in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_HOME")})
        uri = env["ROS_MASTER_URI"]
        print(f"robot_state_publisher CPU per joint_states message ({N:,} messages at ~1 kHz, process "
              "utime+stime; the machine is shared with other jobs: CPU time, not wall clock)")
        for name, urdf in (("panda", PANDA), ("talos", TALOS)):
            ratios, theirs_all, ours_all = [], [], []
            for k in range(ROUNDS):
                # ABBA: the machine's load drifts; each round puts the two side by side, in turn first.
                if k % 2 == 0:
                    theirs = run("c++", urdf, env, uri)
                    ours = run("robotmodel", urdf, env, uri)
                else:
                    ours = run("robotmodel", urdf, env, uri)
                    theirs = run("c++", urdf, env, uri)
                ratios.append(ours / theirs)
                theirs_all.append(theirs)
                ours_all.append(ours)
                print(f"{name:6} round {k + 1}: C++ {theirs * 1e6:7.1f} us  robotmodel {ours * 1e6:7.1f} us  "
                      f"ratio {ours / theirs:5.2f}x  (load {os.getloadavg()[0]:.1f})", flush=True)
            print(f"{name:6} median: C++ {statistics.median(theirs_all) * 1e6:7.1f} us  robotmodel "
                  f"{statistics.median(ours_all) * 1e6:7.1f} us  ratio {statistics.median(ratios):5.2f}x "
                  f"(rounds {min(ratios):.2f}-{max(ratios):.2f}x; goal <= 1.0x)", flush=True)
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
