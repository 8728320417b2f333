"""A TransformListener absorbing a /tf flood on one ROS 1 master: robotmodel's vs rospy's tf2_ros, same run.

Debian's roscore on a free port (private ROS_HOME). For each side in turn, a listener process
(this script with ``--listen IMPL``: rospy's ``tf2_ros.Buffer`` + ``TransformListener`` under
/usr/bin/python3, or robotmodel's ``Buffer`` + ``TransformListener`` on its ROS 1 wire under
the project's Python) is flooded by the same publisher in this process: robotmodel's ROS 1
publisher, keep-all, N TFMessages of 10 transforms (world -> f0..f9, stamps 0.1 ms apart),
sent as fast as it can, then one ``done`` transform. The listener counts its own process CPU
time from the first flood transform in its buffer to ``done`` (polling every 5 ms), and
reports how many samples of f0 its buffer holds (all N: nothing dropped).

Figure: transforms per CPU-second of the listener process. Goal (issue 23): robotmodel >= 2x rospy.
CPU time, not wall clock: the machine is shared with other jobs.

Run: python benchmarks/bench_tf_listener.py [--quick]   (needs Debian's ROS 1: roscore, python3-tf2-ros)
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import _harness

QUICK = "--quick" in sys.argv
MESSAGES = 2_000 if QUICK else 10_000
PER_MESSAGE = 10
BASE_NS = 1_000_000_000_000


def listen(impl: str) -> int:
    """The listener side: print ``ready``, then one JSON line once ``done`` is in the buffer."""
    if impl == "rospy":
        import rospy
        import tf2_ros

        rospy.init_node("bench_listener", disable_signals=True)
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        zero = rospy.Time(0)

        def has(frame: str) -> bool:
            return bool(buffer.can_transform("world", frame, zero))

        def samples() -> int:
            import yaml

            info = yaml.safe_load(buffer.all_frames_as_yaml())["f0"]
            count: float = info["rate"] * info["buffer_length"]
            return round(count)
    else:
        from robotmodel.bus import Node
        from robotmodel.tf import Buffer, Time
        from robotmodel.tf_ros import TransformListener

        node = Node("bench_listener", backend="ros1")
        buffer = Buffer()
        TransformListener(buffer, node)
        zero = Time()

        def has(frame: str) -> bool:
            return bool(buffer.can_transform("world", frame, zero))

        def samples() -> int:
            return len(buffer._caches[buffer._ids["f0"]])  # type: ignore[arg-type]
    print("ready", flush=True)
    while not has("f0"):
        time.sleep(0.005)
    cpu0 = time.process_time()
    while not has("done"):
        time.sleep(0.005)
    cpu = time.process_time() - cpu0
    print(json.dumps({"cpu_s": cpu, "f0_samples": samples()}), flush=True)
    sys.stdin.read()
    return 0


def flood(env: dict[str, str], impl: str) -> dict[str, Any]:
    from robotmodel.bus import History, Node, QoS
    from robotmodel.msgs import TFMessage, make_transform

    python = "/usr/bin/python3" if impl == "rospy" else sys.executable
    proc = subprocess.Popen([python, str(Path(__file__).resolve()), "--listen", impl], env=env,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                            start_new_session=True)
    assert proc.stdout is not None
    try:
        if proc.stdout.readline().strip() != "ready":
            raise RuntimeError(f"the {impl} listener did not start")
        msgs = []
        for k in range(MESSAGES):
            ns = BASE_NS + k * 100_000
            msgs.append(TFMessage(transforms=[make_transform("world", f"f{j}", (0.001 * k, 0.0, 0.1 * j),
                                                             (0.0, 0.0, 0.0, 1.0), ns) for j in range(PER_MESSAGE)]))
        done = TFMessage(transforms=[make_transform("world", "done", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0),
                                                    BASE_NS + MESSAGES * 100_000)])
        with Node(f"bench_flood_{impl}", backend="ros1") as node:
            pub = node.create_publisher(TFMessage, "/tf", QoS(0, history=History.KEEP_ALL))
            deadline = time.monotonic() + 60
            while not pub.matched():
                if time.monotonic() > deadline:
                    raise RuntimeError(f"the {impl} listener did not subscribe to /tf")
                time.sleep(0.01)
            time.sleep(0.5)  # the connection's header exchange is done on both sides
            for msg in msgs:
                pub.publish(msg)
            pub.publish(done)
            result: dict[str, Any] = json.loads(proc.stdout.readline())
        return result
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(10)


def main() -> int:
    with _harness.private_roscore() as env:
        os.environ.update({k: env[k] for k in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_HOME")})
        runs: dict[str, list[dict[str, Any]]] = {"rospy": [], "robotmodel": []}
        for impl in ("rospy", "robotmodel", "rospy", "robotmodel"):
            runs[impl].append(flood(env, impl))
    total = MESSAGES * PER_MESSAGE
    print(f"/tf flood on one ROS 1 master: {MESSAGES:,} TFMessages of {PER_MESSAGE} transforms; listener process "
          "CPU time (the machine is shared with other jobs: CPU time, not wall clock); two runs each, alternating")
    rates = {}
    for impl, got in runs.items():
        rates[impl] = [total / r["cpu_s"] for r in got]
        kept = ", ".join(str(r["f0_samples"]) for r in got)
        print(f"{impl:12} {' '.join(f'{x / 1e3:,.0f}k' for x in rates[impl])} transforms per CPU-second "
              f"(f0 samples kept: {kept} of {MESSAGES:,})")
    ratio = max(rates["robotmodel"]) / max(rates["rospy"])
    print(f"robotmodel / rospy: {ratio:.2f}x (best of each; goal >= 2x); load average {os.getloadavg()[0]:.1f} "
          f"on {os.cpu_count()} CPUs")
    return 0


if __name__ == "__main__":
    if "--listen" in sys.argv:
        sys.exit(listen(sys.argv[sys.argv.index("--listen") + 1]))
    sys.exit(main())
