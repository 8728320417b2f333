"""Memory of the TF tools after one 100k-transform /tf message, against their idle footprint.

Each tool runs as its own process on a private bus (own zenoh port, ROS domain and ROS_HOME;
the wire RMW_IMPLEMENTATION selects, DDS when unset):
``tf2_echo map tool``, ``view_frames`` (listening, measured before it writes its files) and
``view --tf`` (the browser viewer's server, with a bundled robot). Its resident set (VmRSS)
is read once it is subscribed and settled (idle), then this process publishes one TFMessage
of 100,000 transforms (world -> frame_NNNNNN, one sample each; ~9.6 MB of CDR, plus map ->
tool for tf2_echo to print) and the resident set is read again once it has settled (no
change over 3 s). Goal (issue 23): after <= 2x idle.

Also the buffer's own cost per frame with one sample, in this process: tracemalloc's count of
the bytes allocated by inserting 100,000 such frames (frame names, registry and caches). Measured
(CPython 3.11, by source line): 360 bytes a frame: the buffer's copy of the name (~61), the
name -> id dict entry with the id's int object (~66), the id -> name and id -> cache list slots
(16), the TimeCache object (120: 11 slots and the GC header), its row of a shared array (64:
stamp and 7 doubles, the array shared by 255 frames) and the stamp's int object (32).

What the tools keep after the message, besides that ~34 MiB: nothing of the message. The
listener decodes straight into records, the buffer keeps its own copies of names and stamps
(the decoded objects would pin the allocator's pages of the whole message), and once the wire
has let go of the 9.6 MB payload (the DDS wire after the batch it was taken in, zenoh 0.2 s
after its callback) glibc's free heap goes back to the system (malloc_trim: robotmodel/_heap.py). Without
that last step ~10-17 MiB more stayed mapped (tf2_echo 2.1-2.25x idle).

Run: python benchmarks/bench_tf_memory.py [--only tf2_echo|view_frames|view]
"""

from __future__ import annotations

import gc
import os
import random
import socket
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

N = 100_000
ROBOT = Path(__file__).resolve().parent.parent / "urdf" / "diffbot.urdf.xacro"


def rss_mib(pid: int) -> float:
    with Path(f"/proc/{pid}/status").open() as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    raise RuntimeError(f"no VmRSS for {pid}")


def settled(pid: int, quiet_s: float = 3.0, deadline_s: float = 120.0) -> float:
    """The resident set once it has stayed within 1 MiB for ``quiet_s`` seconds."""
    start = time.monotonic()
    last, since = rss_mib(pid), time.monotonic()
    while time.monotonic() - start < deadline_s:
        time.sleep(0.25)
        now = rss_mib(pid)
        if abs(now - last) > 1.0:
            last, since = now, time.monotonic()
        elif time.monotonic() - since >= quiet_s:
            return now
    return rss_mib(pid)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def per_frame_bytes() -> float:
    from robotmodel.tf import Buffer

    buf = Buffer()
    buf.insert("world", "x", 1, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), "a")
    gc.collect()
    tracemalloc.start()
    before = tracemalloc.get_traced_memory()[0]
    for k in range(N):
        buf.insert("world", f"frame_{k:06d}", 1_000_000_000 + k, (0.1 * k, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0),
                   "authority")
    gc.collect()
    used = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    return used / N


def big_message() -> object:
    from robotmodel.msgs import TFMessage, make_transform

    transforms = [make_transform("world", f"frame_{k:06d}", (0.001 * k, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0),
                                 1_000_000_000 + k) for k in range(N)]
    transforms.append(make_transform("map", "tool", (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0), 1_000_000_000))
    return TFMessage(transforms=transforms)


def measure(name: str, argv: list[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    from robotmodel.bus import QOS_TF, Node
    from robotmodel.msgs import TFMessage

    proc = subprocess.Popen([sys.executable, "-m", "robotmodel.cli.main", *argv], env=env, cwd=cwd,
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    try:
        msg = big_message()
        with Node("bench_tf_memory") as node:
            pub = node.create_publisher(TFMessage, "/tf", QOS_TF)
            deadline = time.monotonic() + 60
            while not pub.matched():
                if time.monotonic() > deadline or proc.poll() is not None:
                    raise RuntimeError(f"{name} did not subscribe to /tf")
                time.sleep(0.1)
            idle = settled(proc.pid)
            pub.publish(msg)  # type: ignore[arg-type]
            time.sleep(1.0)
            after = settled(proc.pid)
        if proc.poll() is not None:
            raise RuntimeError(f"{name} ended (status {proc.returncode}) before it was measured")
        return idle, after
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.wait(30)


def main() -> int:
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
    with tempfile.TemporaryDirectory() as home:
        env = dict(os.environ, ROBOTMODEL_ZENOH_PORT=str(free_port()), ROS_DOMAIN_ID=str(random.randint(201, 232)),
                   ROS_HOME=home, PYTHONUNBUFFERED="1")
        env.pop("ZENOH_SESSION_CONFIG_URI", None)
        os.environ.update({k: env[k] for k in ("ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "ROS_HOME")})
        tools = {
            "tf2_echo": ["tf2_echo", "map", "tool"],
            "view_frames": ["view_frames", "--wait-time", "600", "-o", str(Path(home) / "frames")],
            "view": ["view", "--tf", "--port", str(free_port()), str(ROBOT)],
        }
        print(f"one /tf message of {N:,} transforms (one sample per frame); VmRSS of each tool's process")
        for name, argv in tools.items():
            if only and name != only:
                continue
            idle, after = measure(name, argv, env, home)
            print(f"{name:12} idle {idle:6.1f} MiB, after the message {after:6.1f} MiB: {after / idle:.2f}x "
                  "(goal <= 2x)")
    print(f"buffer: {per_frame_bytes():.0f} bytes per frame with one sample (name, registry, cache object, "
          "sample row and stamp; tracemalloc over 100,000 frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
