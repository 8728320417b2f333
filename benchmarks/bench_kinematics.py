"""Kinematics speed against peers measured in the same run on this machine.

- robot_state_publisher cycle (one joint state -> every joint's T_parent_child, translation +
  quaternion) for Panda and Talos, against yourdfpy (update_cfg + get_transform per joint)
  and against raw Pinocchio (framesForwardKinematics + every link pose copied to NumPy).
- Batch FK throughput for Panda (all link poses) against a Pinocchio Python loop.
- Long serial chains: our single-configuration FK (time, peak traced memory) against
  Pinocchio's createData + framesForwardKinematics where its nv³ Data still fits.

Targets: >=30x yourdfpy, <=1.5x the raw-Pinocchio floor, batch >=1M configs/s and >=10x the loop.
Run: python benchmarks/bench_kinematics.py
"""

from __future__ import annotations

import statistics
import sysconfig
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pinocchio as pin
import yourdfpy

from robotmodel.kinematics import (
    PINOCCHIO_DATA_LIMIT,
    KinematicModel,
    KinematicState,
    batch_link_matrices,
    batch_link_poses,
    joint_transforms,
)
from robotmodel.model import parse_urdf

ROBOTS = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix" / "share" / "example-robot-data" / "robots"
PANDA = ROBOTS / "panda_description" / "urdf" / "panda.urdf"
TALOS = ROBOTS / "talos_data" / "robots" / "talos_full_v2.urdf"


def per_call(fn: Callable[[], object], min_time: float = 0.3) -> float:
    """Median seconds per call over several timed batches."""
    fn()
    n = 1
    while True:
        start = time.perf_counter()
        for _ in range(n):
            fn()
        if time.perf_counter() - start > 0.05:
            break
        n *= 2
    samples: list[float] = []
    deadline = time.perf_counter() + min_time
    while time.perf_counter() < deadline or len(samples) < 5:
        start = time.perf_counter()
        for _ in range(n):
            fn()
        samples.append((time.perf_counter() - start) / n)
    return statistics.median(samples)


def rsp_cycle(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    model = KinematicModel(parse_urdf(text))
    rng = np.random.default_rng(0)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    values = dict(zip(model.variables, rng.uniform(lo, hi).tolist(), strict=True))

    ours = per_call(lambda: joint_transforms(model, values))

    yd = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False,
                            load_collision_meshes=False)
    cfg = {n: values[n] for n in yd.actuated_joint_names if n in values}
    pairs = [(j.child, j.parent) for j in yd.robot.joints if j.type != "fixed"]

    def yourdfpy_cycle() -> None:
        yd.update_cfg(cfg)
        for child, parent in pairs:
            yd.get_transform(child, parent)

    theirs = per_call(yourdfpy_cycle, min_time=1.0)

    pm = pin.buildModelFromXML(text)
    data = pm.createData()
    q = pin.neutral(pm)
    frames = [f for f in range(pm.nframes) if pm.frames[f].type == pin.BODY]

    def raw_pinocchio() -> None:
        pin.framesForwardKinematics(pm, data, q)
        for f in frames:
            data.oMf[f].homogeneous  # noqa: B018 - the extraction is what is measured

    floor = per_call(raw_pinocchio)
    print(f"RSP cycle {path.stem:14s} ({len(values)} joints): ours {ours * 1e6:8.1f} us | "
          f"yourdfpy {theirs * 1e6:9.1f} us -> {theirs / ours:6.1f}x faster (target >=30x) | "
          f"raw Pinocchio+extract {floor * 1e6:7.1f} us -> ours/floor {ours / floor:4.2f} (target <=1.5)")


def batch_fk() -> None:
    text = PANDA.read_text(encoding="utf-8")
    model = KinematicModel(parse_urdf(text))
    rng = np.random.default_rng(1)
    n = 100_000
    configs = rng.uniform(np.maximum(model.lower, -np.pi), np.minimum(model.upper, np.pi), (n, model.nv))
    ours = per_call(lambda: batch_link_poses(model, configs), min_time=1.0) / n
    as_matrices = per_call(lambda: batch_link_matrices(model, configs), min_time=1.0) / n

    pm = pin.buildModelFromXML(text)
    data = pm.createData()
    frames = [pm.getFrameId(name, pin.BODY) for name in model.link_names]
    qs = [model.pin_configuration(c) for c in configs[:2000]]

    def loop() -> None:
        for q in qs:
            pin.framesForwardKinematics(pm, data, q)
            np.stack([data.oMf[f].homogeneous for f in frames])

    theirs = per_call(loop) / len(qs)
    print(f"batch FK panda ({len(model.link_names)} links): ours {1 / ours:12,.0f} configs/s (target >=1M) | "
          f"Pinocchio loop {1 / theirs:10,.0f} configs/s -> {theirs / ours:5.1f}x (target >=10x) | "
          f"as N x L x 4 x 4 matrices {1 / as_matrices:12,.0f} configs/s")


def chain_urdf(n: int) -> str:
    """A serial chain of ``n`` revolute joints."""
    links = "".join(f'<link name="l{i}"/>' for i in range(n + 1))
    joints = "".join(
        f'<joint name="j{i}" type="revolute"><parent link="l{i}"/><child link="l{i + 1}"/>'
        '<origin xyz="0 0 0.1" rpy="0.1 0 0"/><axis xyz="0 0 1"/>'
        '<limit effort="1" velocity="1" lower="-3" upper="3"/></joint>' for i in range(n))
    return f'<robot name="chain">{links}{joints}</robot>'


def _chain_line(n: int) -> str:
    import tracemalloc

    model = KinematicModel(parse_urdf(chain_urdf(n)))
    q = np.full(n, 0.1)
    tracemalloc.start()
    state = KinematicState(model)
    state.update(q).link_matrices()
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    ours = per_call(lambda: state.update(q).link_matrices(), min_time=0.3)
    line = f"chain of {n:4d} joints: ours {ours * 1e3:7.2f} ms, {peak / 2**20:5.1f} MiB traced"
    if model.pinocchio_data_bytes > PINOCCHIO_DATA_LIMIT:
        return line + (f" | Pinocchio Data would be ~{model.pinocchio_data_bytes / 2**20:,.0f} MiB: refused "
                       f"(limit {PINOCCHIO_DATA_LIMIT / 2**20:.0f} MiB)")
    pm = model.pin_model
    start = time.perf_counter()
    data = pm.createData()
    created = time.perf_counter() - start
    config = model.pin_configuration(q)
    frames = [pm.getFrameId(name, pin.BODY) for name in model.link_names]

    def pinocchio_fk() -> None:
        pin.framesForwardKinematics(pm, data, config)
        np.stack([data.oMf[f].homogeneous for f in frames])

    theirs = per_call(pinocchio_fk, min_time=0.3)
    return line + (f" | Pinocchio createData {created * 1e3:7.1f} ms (Data ~{model.pinocchio_data_bytes / 2**20:,.0f}"
                   f" MiB), FK+extract {theirs * 1e3:6.2f} ms -> ours/theirs {ours / theirs:4.2f}")


def long_chains() -> None:
    for n in (100, 150, 500, 3000):
        print(_chain_line(n))


if __name__ == "__main__":
    rsp_cycle(PANDA)
    rsp_cycle(TALOS)
    batch_fk()
    long_chains()
