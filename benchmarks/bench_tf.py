"""TF buffer speed and memory at steady state, against pytransform3d measured in the same run.

- Steady-state single inserts: 100 frames at 1 kHz into a buffer whose cache window
  (10 s, then 60 s) is already full, so every insert also prunes. Raw ``insert`` and the
  message adapter ``set_transform``. Target >= 300k/s, flat in the window length.
- Bulk inserts: ``insert_many`` of whole per-frame arrays. Target >= 5M samples/s.
- Bytes per stored sample at steady state (10 s window, 100 frames at 1 kHz). Target <= 80.
- Lookups over a 5-deep chain whose links all interpolate between 100 Hz samples:
  single-lookup median (``lookup_transform``, message out; and the core ``lookup_ns``) vs
  pytransform3d's TemporalTransformManager. Targets <= 10 us, >= 200x.
- Vectorized lookups (``lookup_transforms`` over 200k stamps). Target >= 2M lookups/s.
- ``lookup_transforms`` with a single stamp vs one scalar lookup (should be no slower).

Run: python benchmarks/bench_tf.py [--quick]
It also runs against an older checkout (PYTHONPATH=/path/to/old python benchmarks/bench_tf.py):
the buffer's missing entry points are then reported as n/a, and the old cache is pre-filled
through its own lists (equivalent to in-order inserts, only faster to set up).
"""

from __future__ import annotations

import gc
import itertools
import os
import statistics
import sys
import time
import tracemalloc
from collections.abc import Callable
from typing import Any

import numpy as np
from pytransform3d.transform_manager import NumpyTimeseriesTransform, TemporalTransformManager

from robotmodel.tf import Buffer, Duration, Time, make_transform

SEC = 1_000_000_000
MS = 1_000_000
CHAIN = ["map", "odom", "base", "torso", "arm", "tool"]
FRAMES = [f"f{i}" for i in range(100)]
QUICK = "--quick" in sys.argv


class Clock:
    """Wall and process CPU time of a block; on a shared machine CPU time shows the code's own cost."""

    def __enter__(self) -> Clock:
        self.wall, self.cpu = time.perf_counter(), time.process_time()
        return self

    def __exit__(self, *exc: object) -> None:
        self.wall, self.cpu = time.perf_counter() - self.wall, time.process_time() - self.cpu


def median_per_call(fn: Callable[[], object], n: int, repeats: int = 7) -> tuple[float, float]:
    """Median (wall, CPU) seconds per call over ``repeats`` runs of ``n`` calls."""
    walls, cpus = [], []
    for _ in range(repeats):
        with Clock() as c:
            for _ in range(n):
                fn()
        walls.append(c.wall / n)
        cpus.append(c.cpu / n)
    return statistics.median(walls), statistics.median(cpus)


def frame_poses(n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    poses = np.empty((n, 7))
    poses[:, :3] = np.cumsum(rng.uniform(-0.01, 0.01, (n, 3)), axis=0)
    angle = np.cumsum(rng.uniform(0.0, 0.01, n))
    poses[:, 3:] = np.column_stack([np.zeros(n), np.zeros(n), np.sin(angle / 2), np.cos(angle / 2)])
    poses[1::2, 3:] *= -1.0  # both signs of each rotation, as publishers send them
    return poses


def prefill(buf: Any, window_s: int, fresh: bool = False) -> int:
    """Fill every frame's window (1 kHz); returns the next stamp. Uses insert_many when it exists.

    ``fresh``: on an older buffer, give each frame its own Python objects, as real inserts do
    (needed to measure memory; sharing them is faster for the speed runs).
    """
    n = window_s * 1000 + 1
    stamps = np.arange(1, n + 1, dtype=np.int64) * MS
    poses = frame_poses(n, 0)
    if hasattr(buf, "insert_many"):
        for f in FRAMES:
            buf.insert_many("world", f, stamps, poses, "bench")
        return int(stamps[-1]) + MS
    # Older buffer: one real insert creates each cache, then its lists are filled in order.
    rows = [tuple(map(float, p)) for p in poses]
    stamp_list = [int(s) for s in stamps]
    for f in FRAMES:
        if fresh:
            rows = [tuple(map(float, p)) for p in poses]
            stamp_list = [int(s) for s in stamps]
        buf.set_transform(make_transform("world", f, poses[0, :3], poses[0, 3:], int(stamps[0])), "bench")
        cache = buf._caches[buf._ids[f]]
        cache.stamps[:] = stamp_list
        cache.data[:] = rows
        cache.parents[:] = [cache.parents[0]] * n
        cache.version += 1
    return int(stamps[-1]) + MS


Rate = tuple[float, float]  # (wall, CPU) per second


def _rate(count: int, c: Clock) -> Rate:
    return count / c.wall, count / c.cpu


def steady_inserts(window_s: int) -> tuple[Rate | None, Rate]:
    buf = Buffer(cache_time=Duration(seconds=window_s))
    stamp = prefill(buf, window_s)
    steps = 300 if QUICK else 1000
    poses = frame_poses(steps, 1)
    rows = [tuple(map(float, p)) for p in poses]
    raw = None
    gc.collect()
    if hasattr(buf, "insert"):
        insert = buf.insert
        with Clock() as c:
            for k in range(steps):
                s = stamp + k * MS
                pose = rows[k]
                for f in FRAMES:
                    insert("world", f, s, pose, "bench")
        raw = _rate(steps * len(FRAMES), c)
        stamp += steps * MS
    msgs = {f: make_transform("world", f, poses[0, :3], poses[0, 3:], 0) for f in FRAMES}
    stamps = [Time(nanoseconds=stamp + k * MS).to_msg() for k in range(steps)]
    # The same moving poses as the raw inserts (rotations of every sign, not only w > 0.5).
    transforms = [make_transform("world", "x", p[:3], p[3:], 0).transform for p in poses]
    set_transform = buf.set_transform
    with Clock() as c:
        for k in range(steps):
            st, tr = stamps[k], transforms[k]
            for f in FRAMES:
                m = msgs[f]
                m.header.stamp = st
                m.transform = tr
                set_transform(m, "bench")
    return raw, _rate(steps * len(FRAMES), c)


def bulk_inserts() -> Rate | None:
    buf = Buffer(cache_time=Duration(seconds=10))
    if not hasattr(buf, "insert_many"):
        return None
    n = 10_000
    stamps = np.arange(1, n + 1, dtype=np.int64) * MS
    poses = frame_poses(n, 2)
    with Clock() as c:
        for f in FRAMES:
            buf.insert_many("world", f, stamps, poses, "bench")
    return _rate(n * len(FRAMES), c)


def bytes_per_sample() -> float:
    gc.collect()
    tracemalloc.start()
    base = tracemalloc.get_traced_memory()[0]
    buf = Buffer(cache_time=Duration(seconds=10))
    stamp = prefill(buf, 10, fresh=True)
    msg = make_transform("world", "f0", (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 0)
    for k in range(200):  # a little steady-state traffic: prune and append
        msg.header.stamp = Time(nanoseconds=stamp + k * MS).to_msg()
        for f in FRAMES:
            msg.child_frame_id = f
            buf.set_transform(msg, "bench")
    gc.collect()
    used = tracemalloc.get_traced_memory()[0] - base
    tracemalloc.stop()
    stored = sum(len(c) for c in buf._caches if c is not None)
    return used / stored


def chain_buffer(samples: int) -> tuple[Any, TemporalTransformManager, np.ndarray]:
    rng = np.random.default_rng(0)
    stamps = np.arange(1, samples + 1) * (SEC // 100)  # 100 Hz
    buf = Buffer()
    tm = TemporalTransformManager()
    for parent, child in itertools.pairwise(CHAIN):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = np.cumsum(rng.uniform(0.0, 0.05, samples))
        quat = np.hstack([np.sin(angle / 2)[:, None] * axis, np.cos(angle / 2)[:, None]])
        xyz = np.cumsum(rng.uniform(-0.01, 0.01, (samples, 3)), axis=0)
        for k, s in enumerate(stamps):
            buf.set_transform(make_transform(parent, child, xyz[k], quat[k], int(s)), "bench")
        pqs = np.hstack([xyz, quat[:, [3, 0, 1, 2]]])  # pytransform3d wants (x y z qw qx qy qz)
        tm.add_transform(child, parent, NumpyTimeseriesTransform(stamps / SEC, pqs))
    return buf, tm, stamps


def lookups() -> dict[str, Any]:
    buf, tm, stamps = chain_buffer(500)
    # Many different query times between samples, in random order: every link interpolates,
    # no answer or search position is reused.
    order = np.random.default_rng(5).permutation(np.arange(100, 400))
    queries = [int(stamps[k] + SEC // 300) for k in order]
    times = [Time(nanoseconds=q) for q in queries]
    cycle_t, cycle_q = itertools.cycle(times), itertools.cycle(queries)
    ours = median_per_call(lambda: buf.lookup_transform("map", "tool", next(cycle_t)), 20000)
    core = median_per_call(lambda: buf.lookup_ns("map", "tool", next(cycle_q)), 20000)
    theirs = median_per_call(lambda: tm.get_transform_at_time("tool", "map", next(cycle_q) / SEC), 100, 5)
    exact = int(stamps[250])
    assert np.allclose(buf.lookup_ns("map", "tool", exact)[0][:3],
                       tm.get_transform_at_time("tool", "map", exact / SEC)[:3, 3], atol=1e-9)
    one = median_per_call(lambda: buf.lookup_transforms("map", "tool", [next(cycle_q)]), 20000)
    n = 200_000
    many = np.random.default_rng(2).integers(int(stamps[1]), int(stamps[-2]), n)
    buf.lookup_transforms("map", "tool", many[:10])
    rates = []
    for _ in range(3):
        with Clock() as c:
            buf.lookup_transforms("map", "tool", many)
        rates.append(_rate(n, c))
    vector = (statistics.median(r[0] for r in rates), statistics.median(r[1] for r in rates))
    return {"ours": ours, "core": core, "theirs": theirs, "one": one, "vector": vector}


def fmt(rate: Rate | None) -> str:
    return "n/a" if rate is None else f"{rate[0] / 1e3:,.0f}k/s (CPU time {rate[1] / 1e3:,.0f}k/s)"


def us(t: tuple[float, float]) -> str:
    return f"{t[0] * 1e6:.2f} us (CPU {t[1] * 1e6:.2f})"


if __name__ == "__main__":
    look = lookups()
    ours, core, theirs = look["ours"], look["core"], look["theirs"]
    print(f"lookup, 5-deep interpolated chain: lookup_transform {us(ours)} median, core lookup_ns {us(core)} | "
          f"pytransform3d {theirs[0] * 1e6:.0f} us -> {theirs[0] / ours[0]:.0f}x "
          f"(CPU {theirs[1] / ours[1]:.0f}x; core {theirs[1] / core[1]:.0f}x) (targets <=10 us, >=200x)")
    print(f"lookup_transforms with one stamp: {us(look['one'])} vs lookup_transform {us(ours)} "
          "(target: no slower)")
    vec = look["vector"]
    print(f"vectorized lookups: {vec[0] / 1e6:.2f}M lookups/s (CPU time {vec[1] / 1e6:.2f}M/s) over the same chain "
          "(target >=2M/s)")
    for window in (10, 60):
        raw, msg = steady_inserts(window)
        print(f"steady-state inserts, {window} s window full (100 frames at 1 kHz): insert {fmt(raw)}, "
              f"set_transform {fmt(msg)} (target >=300k/s, flat in the window)")
    bulk = bulk_inserts()
    bulk_text = "n/a" if bulk is None else f"{bulk[0] / 1e6:.1f}M samples/s (CPU time {bulk[1] / 1e6:.1f}M/s)"
    print(f"bulk inserts (insert_many, 100 frames x 10k samples): {bulk_text} (target >=5M/s)")
    print(f"memory at steady state (10 s window, 100 frames at 1 kHz): {bytes_per_sample():.0f} bytes per "
          "stored sample (target <=80; tf2's C++ list node ~112)")
    print(f"load average during the run: {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
