"""robotmodel's tf buffer against the real tf2 C++ BufferCore (Debian's ROS 1 ``tf2_py``), same run, same data.

The peer is tf2's C++ through its Python binding, what a rospy user calls, in a child process
under /usr/bin/python3 (Debian's ROS 1; another interpreter than the project's); ours runs in
this process. This script is both sides: ``--peer`` makes it the tf2_py side, which reads the
data (a JSON line) from its stdin and then measures one round each time it reads ``round``.
Rounds alternate between the two processes (the other one idles meanwhile), so both see the
same load on a machine shared with other jobs; each figure is the median CPU time per call
(process time: what the code itself costs, far steadier than the wall clock under load).

- Lookup on a 5-deep chain (map -> odom -> base -> torso -> arm -> tool), every link sampled
  at 100 Hz and interpolated (query times between samples, in random order: no answer or
  search position is reused). Message out on both sides: ``Buffer.lookup_transform`` (a
  TransformStamped) vs ``tf2_py.BufferCore.lookup_transform_core`` (a geometry_msgs
  TransformStamped). Also our core ``lookup_ns`` (a pose tuple) vs the same peer call.
  Goals (issue 23): lookup_transform <= 1.0x, core <= 0.7x.
- ``set_transform`` at steady state: 100 frames at 1 kHz into buffers whose 10 s windows are
  already full (every insert prunes), one TransformStamped per frame whose stamp and transform
  are replaced before each call, on both sides. Goal: <= 1.0x.
- Agreement: the poses both give for the lookup queries (largest difference, translation in m,
  quaternion components up to sign).
- The message out alone, no goal: ours (six dataclass objects) against genpy's
  TransformStamped built as tf2_py's C++ builds it (the class called, then each field set
  through the attribute protocol). Both lookups build a message; genpy's costs ~2.6 us of
  tf2_py's ~6 us, ours ~0.6-0.9 us of our ~10-11 us.
- ``--costs``: the CPU cost, in this interpreter and run, of one float operation, one libm
  call, one 14-double read from an array and one RLock hold: the blocks of a pure-Python lookup.

Why the lookup goals are out of pure Python's reach: one interpolated link is ~32 float
operations (the SLERP's dot product and weights, the translation's blend), 4 libm calls (acos,
3 sin) and one 14-double read; each of the four compositions is 61 float operations (the
rotated translation and the quaternion product), and the canonical quaternion ~15 more: ~420
float operations, 20 libm calls and 5 reads a lookup. With CPython 3.11's ~9.5 ns a float
operation at a low load (16-20 ns at the loads of these runs, see ``--costs``) that is ~4 us of
arithmetic at best, before the bracket search, the plan and the lock (~1 us together); the
goal for the core lookup, 0.7x tf2_py's ~5.6-6 us, is ~4 us in all. What was left to take has
been taken (the walk planned once per pair, links inlined with no tuple or call per link, one
bracket search for links stamped alike, no SLERP at a sample's own stamp), so what is measured
is ~9-10.5 us for ``lookup_ns`` at loads of 9-12 (1.2-1.6x, the ratio moving with the load).

A compiled kernel (issue 23, item 5: only a dependency with wheels, nothing compiled on the
user's machine), measured on this data in a scratch script, not added: PyGLM 2.8.3
(manylinux wheels; ``glm.slerp``/``glm.mix`` and products of ``dquat``/``dvec3``, ~40-230 ns a
call) does the five links' arithmetic in 2.5-2.9 us when every sample is kept as glm objects
(152 bytes a sample as a (dquat, dvec3) pair: the goal is <= 80, ours is 64) and in 5.5-7.3 us
when they are built from the stored rows at each lookup (four constructors a link, ~125-150 ns
each), against 8.6-10.1 us for our whole ``lookup_ns`` in the same runs; glm also lerps instead
of SLERPing near-equal rotations, which tf2 does not. NumPy and Pinocchio cost ~0.5-1 us a
call, for ~30 small operations a lookup. numba compiles on the user's machine (LLVM, at the
first call), which item 5 rules out, and its ahead-of-time mode would put a compiled module in
this package. So no dependency gives a single lookup under ~4 us within the storage goal.

Run: python benchmarks/bench_tf2_peer.py [--quick] [--rounds N] [--costs]   (needs Debian's python3-tf2-py)
"""

from __future__ import annotations

import itertools
import json
import math
import os
import random
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

SEC = 1_000_000_000
MS = 1_000_000
CHAIN = ["map", "odom", "base", "torso", "arm", "tool"]
FRAMES = [f"f{i}" for i in range(100)]
PEER_PYTHON = "/usr/bin/python3"
QUICK = "--quick" in sys.argv


def cpu_per_call(fn: Callable[[], object], n: int, repeats: int) -> float:
    """Median CPU seconds per call over ``repeats`` runs of ``n`` calls."""
    cpus = []
    for _ in range(repeats):
        t0 = time.process_time()
        for _ in range(n):
            fn()
        cpus.append((time.process_time() - t0) / n)
    return statistics.median(cpus)


def steady_costs(set_transform: Callable[[Any, str], object], msgs: dict[str, Any], stamps: list[Any],
                 transforms: list[Any]) -> list[float]:
    """CPU seconds per set_transform at each step: every frame's message re-stamped and given the step's transform.

    Both sides run this (the peer under Debian's Python with rospy's messages, ours with robotmodel's).
    """
    per_step = []
    for st, tr in zip(stamps, transforms, strict=False):
        s0 = time.process_time()
        for f in FRAMES:
            m = msgs[f]
            m.header.stamp = st
            m.transform = tr
            set_transform(m, "bench")
        per_step.append((time.process_time() - s0) / len(FRAMES))
    return per_step


def poses_of(lookup: Callable[[Any], Any], times: list[Any]) -> list[list[float]]:
    """Each looked-up TransformStamped's translation and rotation, for the agreement check (both sides)."""
    poses = []
    for t in times:
        r = lookup(t).transform
        poses.append([r.translation.x, r.translation.y, r.translation.z,
                      r.rotation.x, r.rotation.y, r.rotation.z, r.rotation.w])
    return poses


# ---------------------------------------------------------------------------- data (stdlib only: both sides)
def make_data(quick: bool) -> dict[str, Any]:
    """The chain's samples, the lookup queries and the steady-state inserts' poses, as plain lists."""
    rng = random.Random(0)
    samples = 500
    stamps = [(k + 1) * (SEC // 100) for k in range(samples)]
    links = []
    for parent, child in itertools.pairwise(CHAIN):
        axis = [rng.gauss(0.0, 1.0) for _ in range(3)]
        norm = math.sqrt(sum(a * a for a in axis))
        axis = [a / norm for a in axis]
        angle, xyz = 0.0, [0.0, 0.0, 0.0]
        poses = []
        for _ in range(samples):
            angle += rng.uniform(0.0, 0.05)
            xyz = [v + rng.uniform(-0.01, 0.01) for v in xyz]
            s, c = math.sin(angle / 2), math.cos(angle / 2)
            poses.append([*xyz, axis[0] * s, axis[1] * s, axis[2] * s, c])
        links.append({"parent": parent, "child": child, "poses": poses})
    order = list(range(100, 400))
    rng.shuffle(order)
    queries = [stamps[k] + SEC // 300 for k in order]  # between two samples on every link

    def moving(n: int) -> list[list[float]]:
        out, angle, xyz = [], 0.0, [0.0, 0.0, 0.0]
        for k in range(n):
            angle += rng.uniform(0.0, 0.01)
            xyz = [v + rng.uniform(-0.01, 0.01) for v in xyz]
            sign = -1.0 if k % 2 else 1.0  # both signs of each rotation, as publishers send them
            out.append([*xyz, 0.0, 0.0, sign * math.sin(angle / 2), sign * math.cos(angle / 2)])
        return out

    window_s = 10
    return {"stamps": stamps, "links": links, "queries": queries, "window_s": window_s,
            "prefill": moving(window_s * 1000 + 1), "steady": moving(200 if quick else 500),
            "lookups": 5_000 if quick else 20_000}


# ---------------------------------------------------------------------------- tf2_py side (/usr/bin/python3)
def peer_main() -> int:
    import rospy
    import tf2_py
    from geometry_msgs.msg import Transform, TransformStamped

    data = json.loads(sys.stdin.readline())

    def message(parent: str, child: str, pose: list[float], ns: int) -> Any:
        t = TransformStamped()
        t.header.frame_id, t.child_frame_id = parent, child
        t.header.stamp = rospy.Time(ns // SEC, ns % SEC)
        t.transform = transform(pose)
        return t

    def transform(pose: list[float]) -> Any:
        tr = Transform()
        tr.translation.x, tr.translation.y, tr.translation.z = pose[:3]
        tr.rotation.x, tr.rotation.y, tr.rotation.z, tr.rotation.w = pose[3:]
        return tr

    chain = tf2_py.BufferCore(rospy.Duration(10))
    for link in data["links"]:
        for ns, pose in zip(data["stamps"], link["poses"], strict=True):
            chain.set_transform(message(link["parent"], link["child"], pose, ns), "bench")
    queries = data["queries"]
    times = [rospy.Time(q // SEC, q % SEC) for q in queries]

    window_s = data["window_s"]
    steady = tf2_py.BufferCore(rospy.Duration(window_s))
    prefill = [transform(p) for p in data["prefill"]]
    msgs = {f: message("world", f, data["prefill"][0], 0) for f in FRAMES}
    for k, tr in enumerate(prefill):
        stamp = rospy.Time((k + 1) * MS // SEC, (k + 1) * MS % SEC)
        for f in FRAMES:
            m = msgs[f]
            m.header.stamp, m.transform = stamp, tr
            steady.set_transform(m, "bench")
    next_ns = (len(prefill) + 1) * MS
    transforms = [transform(p) for p in data["steady"]]
    steps = len(transforms)
    print("ready", flush=True)

    for line in sys.stdin:
        if line.strip() != "round":
            break
        k = 0

        def lookup() -> Any:
            nonlocal k
            k += 1
            return chain.lookup_transform_core("map", "tool", times[k % len(times)])

        look = cpu_per_call(lookup, data["lookups"], 7)

        def build() -> Any:
            # What tf2_py's C++ does for the message out, in Python: the class called, then each
            # field set through the attribute protocol (PyObject_SetAttrString).
            t = TransformStamped()
            t.header.frame_id = "map"
            t.header.stamp = rospy.Time(1, 500)
            t.child_frame_id = "tool"
            tr, rot = t.transform.translation, t.transform.rotation
            tr.x, tr.y, tr.z = 0.1, 0.2, 0.3
            rot.x, rot.y, rot.z, rot.w = 0.0, 0.0, 0.0, 1.0
            return t

        message_cost = cpu_per_call(build, data["lookups"], 7)
        stamps = [rospy.Time((next_ns + j * MS) // SEC, (next_ns + j * MS) % SEC) for j in range(steps)]
        set_transform = steady.set_transform
        per_step = steady_costs(set_transform, msgs, stamps, transforms)
        next_ns += steps * MS
        poses = poses_of(lambda t: chain.lookup_transform_core("map", "tool", t), times[:50])
        print(json.dumps({"lookup": look, "message": message_cost, "set_transform": _median_of_blocks(per_step),
                          "poses": poses}),
              flush=True)
    return 0


def _median_of_blocks(per_step: list[float], block: int = 50) -> float:
    """Median over blocks of steps (one step's 100 inserts are too short to time alone)."""
    blocks = [sum(per_step[i:i + block]) / len(per_step[i:i + block]) for i in range(0, len(per_step), block)]
    return statistics.median(blocks)


# ---------------------------------------------------------------------------- our side (the project's Python)
class Ours:
    """robotmodel's Buffer with the same data and the same calls as the peer."""

    def __init__(self, data: dict[str, Any]) -> None:
        import numpy as np

        from robotmodel.tf import Buffer, Duration, Time, make_transform

        self.data = data
        self.chain = Buffer(cache_time=Duration(seconds=10))
        for link in data["links"]:
            for ns, pose in zip(data["stamps"], link["poses"], strict=True):
                self.chain.set_transform(make_transform(link["parent"], link["child"], pose[:3], pose[3:], ns),
                                         "bench")
        self.queries: list[int] = data["queries"]
        self.times = [Time(nanoseconds=q) for q in self.queries]
        window_s = data["window_s"]
        self.steady = Buffer(cache_time=Duration(seconds=window_s))
        # The same state as the peer's 10,001 set_transform per frame, filled in one step per frame.
        prefill = np.array(data["prefill"], dtype=np.float64)
        stamps = np.arange(1, prefill.shape[0] + 1, dtype=np.int64) * MS
        for f in FRAMES:
            self.steady.insert_many("world", f, stamps, prefill, "bench")
        self.next_ns = (prefill.shape[0] + 1) * MS
        self.msgs = {f: make_transform("world", f, data["prefill"][0][:3], data["prefill"][0][3:], 0)
                     for f in FRAMES}
        self.transforms = [make_transform("world", "x", p[:3], p[3:], 0).transform for p in data["steady"]]
        self._time = Time

    def round(self) -> dict[str, Any]:
        from robotmodel.msgs.builtin_interfaces import Time as StampMsg
        from robotmodel.tf._buffer import _message

        chain, times, queries, n = self.chain, self.times, self.queries, self.data["lookups"]
        k = 0

        def lookup() -> Any:
            nonlocal k
            k += 1
            return chain.lookup_transform("map", "tool", times[k % len(times)])

        def core() -> Any:
            nonlocal k
            k += 1
            return chain.lookup_ns("map", "tool", queries[k % len(queries)])

        look = cpu_per_call(lookup, n, 7)
        core_t = cpu_per_call(core, n, 7)
        pose, stamp = chain.lookup_ns("map", "tool", queries[0])
        message = cpu_per_call(lambda: _message(pose, stamp, "map", "tool"), n, 7)
        steps = len(self.transforms)
        stamps = [StampMsg(*divmod(self.next_ns + j * MS, SEC)) for j in range(steps)]
        set_transform, msgs, transforms = self.steady.set_transform, self.msgs, self.transforms
        per_step = steady_costs(set_transform, msgs, stamps, transforms)
        self.next_ns += steps * MS
        poses = poses_of(lambda t: chain.lookup_transform("map", "tool", t), times[:50])
        return {"lookup": look, "core": core_t, "message": message, "set_transform": _median_of_blocks(per_step),
                "poses": poses}


def op_costs() -> dict[str, float]:
    """CPU ns of the operations a pure-Python lookup is made of, in this interpreter (median of 7 runs)."""
    import struct
    import threading
    from array import array
    from math import sin

    row = array("q", [0]) * 16
    unpack14 = struct.Struct("14d").unpack_from
    lock = threading.RLock()
    a, b = 1.0000001, 0.9999999

    def empty(n: int) -> None:
        for _ in range(n):
            pass

    def floats(n: int) -> None:  # ten multiply-adds: 20 float operations a pass
        x = 0.5
        for _ in range(n):
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1
            x = x * a + b * 0.1

    def libm(n: int) -> None:
        for _ in range(n):
            sin(a)

    def unpack(n: int) -> None:
        for _ in range(n):
            unpack14(row, 0)

    def locked(n: int) -> None:
        for _ in range(n):
            with lock:
                pass

    def per(fn: Callable[[int], None], n: int = 200_000) -> float:
        runs = []
        for _ in range(7):
            t0 = time.process_time()
            fn(n)
            runs.append((time.process_time() - t0) / n * 1e9)
        return statistics.median(runs)

    loop = per(empty)
    return {"float operation": (per(floats) - loop) / 20, "libm call (math.sin)": per(libm) - loop,
            "14 doubles read (struct)": per(unpack) - loop, "RLock held and released": per(locked) - loop}


def _difference(a: list[list[float]], b: list[list[float]]) -> tuple[float, float]:
    dt = max(abs(x - y) for p, q in zip(a, b, strict=True) for x, y in zip(p[:3], q[:3], strict=True))
    dq = max(min(max(abs(x - y) for x, y in zip(p[3:], q[3:], strict=True)),
                 max(abs(x + y) for x, y in zip(p[3:], q[3:], strict=True))) for p, q in zip(a, b, strict=True))
    return dt, dq


def main() -> int:
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 5
    data = make_data(QUICK)
    peer = subprocess.Popen([PEER_PYTHON, str(Path(__file__).resolve()), "--peer"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True, env=dict(os.environ, PYTHONUNBUFFERED="1"))
    assert peer.stdin is not None and peer.stdout is not None
    try:
        peer.stdin.write(json.dumps(data) + "\n")
        peer.stdin.flush()
        ours = Ours(data)
        if peer.stdout.readline().strip() != "ready":
            raise RuntimeError("the tf2_py peer did not start (is Debian's python3-tf2-py installed?)")
        results: list[tuple[dict[str, Any], dict[str, Any]]] = []
        for _ in range(rounds):
            peer.stdin.write("round\n")
            peer.stdin.flush()
            theirs = json.loads(peer.stdout.readline())
            results.append((ours.round(), theirs))
        peer.stdin.close()
        peer.wait(30)
    finally:
        if peer.poll() is None:
            peer.kill()
            peer.wait()
    load = os.getloadavg()[0]
    print(f"robotmodel vs tf2's C++ BufferCore via Debian's ROS 1 tf2_py, {rounds} alternating rounds; "
          "CPU time medians per call (the machine is shared with other jobs: CPU time, not wall clock)")
    rows = (("lookup_transform, 5-deep interpolated chain (message out)", "lookup", "lookup", 1.0),
            ("core lookup_ns vs lookup_transform_core", "core", "lookup", 0.7),
            ("set_transform, steady state (100 frames at 1 kHz, 10 s window full)", "set_transform",
             "set_transform", 1.0),
            ("the message out alone (ours vs genpy's, built as tf2_py builds it)", "message", "message", None))
    print(f"{'':70}{'robotmodel':>12}{'tf2_py':>10}{'ratio':>8}  per round; goal")
    for label, mine, peer_key, goal in rows:
        a = statistics.median(o[mine] for o, _ in results)
        b = statistics.median(t[peer_key] for _, t in results)
        per_round = " ".join(f"{o[mine] / t[peer_key]:.2f}" for o, t in results)
        print(f"{label:70}{a * 1e6:10.2f}us{b * 1e6:8.2f}us{a / b:8.2f}  ({per_round})"
              + (f"; <= {goal}" if goal is not None else ""))
    dt, dq = _difference(results[-1][0]["poses"], results[-1][1]["poses"])
    print(f"agreement on {len(results[-1][0]['poses'])} lookups: translation {dt:.1e} m, quaternion {dq:.1e}")
    print(f"load average during the run: {load:.1f} on {os.cpu_count()} CPUs")
    if "--costs" in sys.argv:
        print("CPU cost of the pure-Python building blocks here: "
              + ", ".join(f"{name} {ns:.1f} ns" for name, ns in op_costs().items()))
    return 0


if __name__ == "__main__":
    sys.exit(peer_main() if "--peer" in sys.argv else main())
