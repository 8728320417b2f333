"""/tf between two ROS 1 nodes on one private roscore: robotmodel's ROS 1 wire next to rospy, same run.

Each pair is two processes on the same master (Debian's roscore on a free port, private
ROS_HOME): a subscriber, then a publisher of one-transform tf2_msgs/TFMessage on
/bench_tf (reliable keep-all, unbounded queue; subscriber with TCP_NODELAY).

- Latency: PINGS messages 2 ms apart; one-way = receive time - the send time in the stamp
  (one clock: same machine); p50 and p90.
- Throughput: N messages published as fast as the publisher can; the subscriber decodes
  each into a message object. Rate = N / (last receive - first send).
- CPU per message on each side (process time), steadier than wall clock under load.

Run: python benchmarks/bench_ros1.py [--quick]   (needs Debian's ROS 1: roscore, python3-rospy)
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
import xmlrpc.client
from pathlib import Path
from typing import Any

QUICK = "--quick" in sys.argv
PINGS = 300 if QUICK else 1_000
FLOOD = 5_000 if QUICK else 20_000
PEER = Path(__file__).resolve().with_name("ros1_peer.py")
PYTHONS = {"rospy": "/usr/bin/python3", "robotmodel": sys.executable}


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _start(argv: list[str], env: dict[str, str]) -> subprocess.Popen[str]:
    return subprocess.Popen(argv, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            text=True, start_new_session=True)


def _stop(proc: subprocess.Popen[Any]) -> None:
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait(10)


def _line(proc: subprocess.Popen[str], prefix: str) -> str:
    assert proc.stdout is not None
    for line in proc.stdout:
        if line.startswith(prefix):
            return line
    raise RuntimeError(f"{proc.args!r} ended without printing {prefix!r}")


def _master_up(uri: str) -> bool:
    try:
        answer: Any = xmlrpc.client.ServerProxy(uri).getSystemState("/bench")
    except OSError:
        return False
    code, _, (_, subs, _) = answer
    return bool(code == 1 and any(topic == "/rosout" for topic, _ in subs))


def run_pair(impl: str, env: dict[str, str]) -> dict[str, Any]:
    """One subscriber and one publisher of ``impl``; their merged result lines."""
    python = PYTHONS[impl]
    sub = _start([python, str(PEER), impl, "sub", str(FLOOD)], env)
    try:
        _line(sub, "ready")
        pub = _start([python, str(PEER), impl, "pub", str(PINGS), str(FLOOD)], env)
        try:
            result: dict[str, Any] = json.loads(_line(sub, "{"))
            result.update(json.loads(_line(pub, "{")))
        finally:
            _stop(pub)
    finally:
        _stop(sub)
    return result


def main() -> int:
    port = _free_port()
    uri = f"http://127.0.0.1:{port}"
    with tempfile.TemporaryDirectory() as home:
        env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOSTNAME="127.0.0.1", ROS_HOME=home, PYTHONUNBUFFERED="1")
        env.pop("ROS_IP", None)
        core = subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            deadline = time.monotonic() + 60
            while not _master_up(uri):
                if time.monotonic() > deadline:
                    raise RuntimeError("roscore did not come up")
                time.sleep(0.2)
            results = {impl: run_pair(impl, env) for impl in ("rospy", "robotmodel")}
        finally:
            os.killpg(core.pid, signal.SIGINT)
            try:
                core.wait(15)
            except subprocess.TimeoutExpired:
                os.killpg(core.pid, signal.SIGKILL)
                core.wait()
    ours, theirs = results["robotmodel"], results["rospy"]
    print(f"{FLOOD} flood messages, {PINGS} pings, one-transform TFMessage")
    print(f"{'':28}{'robotmodel':>14}{'rospy':>14}{'ratio':>10}")
    for key, label, better in (("rate", "throughput msgs/s", "higher"), ("p50_us", "latency p50 us", "lower"),
                               ("p90_us", "latency p90 us", "lower"),
                               ("sub_cpu_us_per_msg", "subscriber CPU us/msg", "lower"),
                               ("pub_cpu_us_per_msg", "publisher CPU us/msg", "lower")):
        a, b = float(ours[key]), float(theirs[key])
        print(f"{label:28}{a:14.1f}{b:14.1f}{a / b:10.2f}  ({better} is better)")
    print(f"received: robotmodel {ours['received']}/{FLOOD}, rospy {theirs['received']}/{FLOOD}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
