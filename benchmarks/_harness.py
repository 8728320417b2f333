"""What the benchmarks against real peers share: child processes, a private roscore, a pub/sub pair.

Each benchmark measures robotmodel and its peer (rospy, rclpy, the C++ tools) in one run;
this module starts and reaps their processes the same way for all of them.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import socket
import subprocess
import tempfile
import time
import xmlrpc.client
from collections.abc import Iterator
from typing import Any


def free_port() -> int:
    """A TCP port on 127.0.0.1 free at the time of the call."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def start(argv: list[str], env: dict[str, str], stderr: Any = subprocess.DEVNULL) -> subprocess.Popen[str]:
    """A child in its own session (so :func:`stop` takes its whole group), stdout piped as text."""
    return subprocess.Popen(argv, env=env, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=stderr,
                            text=True, start_new_session=True)


def stop(proc: subprocess.Popen[Any]) -> None:
    """Kill the child's process group (a benchmark's peers hold no state worth a clean exit) and reap it."""
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait(10)


def interrupt(proc: subprocess.Popen[Any], timeout: float) -> None:
    """Ctrl-C the child's process group (a clean exit: a master unregisters, a node its topics), SIGKILL if it hangs."""
    if proc.poll() is not None:
        return
    os.killpg(proc.pid, signal.SIGINT)
    try:
        proc.wait(timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def line(proc: subprocess.Popen[str], prefix: str) -> str:
    """The child's first stdout line starting with ``prefix``; RuntimeError if it ends first."""
    assert proc.stdout is not None
    for text in proc.stdout:
        if text.startswith(prefix):
            return text
    raise RuntimeError(f"{proc.args!r} ended without printing {prefix!r}")


def run_pair(sub_argv: list[str], pub_argv: list[str], env: dict[str, str],
             stderr: Any = subprocess.DEVNULL) -> dict[str, Any]:
    """A subscriber (ready once it prints ``ready``), then a publisher; their JSON result lines merged."""
    sub = start(sub_argv, env, stderr)
    try:
        line(sub, "ready")
        pub = start(pub_argv, env, stderr)
        try:
            result: dict[str, Any] = json.loads(line(sub, "{"))
            result.update(json.loads(line(pub, "{")))
        finally:
            stop(pub)
    finally:
        stop(sub)
    return result


def master_up(uri: str) -> bool:
    """Whether a ROS 1 master answers at ``uri`` with its /rosout registered (roscore fully up)."""
    try:
        answer: Any = xmlrpc.client.ServerProxy(uri).getSystemState("/bench")
    except OSError:
        return False
    code, _, (_, subs, _) = answer
    return bool(code == 1 and any(topic == "/rosout" for topic, _ in subs))


@contextlib.contextmanager
def private_roscore() -> Iterator[dict[str, str]]:
    """A real ``roscore`` on a free port with its own ROS_HOME; yields the environment that reaches it."""
    port = free_port()
    uri = f"http://127.0.0.1:{port}"
    with tempfile.TemporaryDirectory() as home:
        env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOSTNAME="127.0.0.1", ROS_HOME=home, PYTHONUNBUFFERED="1")
        env.pop("ROS_IP", None)
        core = subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            deadline = time.monotonic() + 60
            while not master_up(uri):
                if time.monotonic() > deadline:
                    raise RuntimeError("roscore did not come up")
                time.sleep(0.2)
            yield env
        finally:
            interrupt(core, 15)


def print_wire_table(ours: dict[str, Any], theirs: dict[str, Any], peer: str) -> None:
    """The throughput, latency and CPU rows of a wire benchmark: robotmodel, the peer, their ratio."""
    print(f"{'':28}{'robotmodel':>14}{peer:>14}{'ratio':>10}")
    for key, label, better in (("rate", "throughput msgs/s", "higher"), ("p50_us", "latency p50 us", "lower"),
                               ("p90_us", "latency p90 us", "lower"),
                               ("sub_cpu_us_per_msg", "subscriber CPU us/msg", "lower"),
                               ("pub_cpu_us_per_msg", "publisher CPU us/msg", "lower")):
        a, b = float(ours[key]), float(theirs[key])
        print(f"{label:28}{a:14.1f}{b:14.1f}{a / b:10.2f}  ({better} is better)")
