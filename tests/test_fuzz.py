"""Seeded mutation fuzzing: no URDF, however broken, gets a traceback or a hang.

Seeds are the bundled robots (expanded once with xacro) and a few example-robot-data
URDFs. Each mutant (elements deleted or duplicated, attributes set to NaN, inf, huge,
tiny, empty, whitespace-padded or non-ASCII values, parent and child swapped, names
collided, mimics pointed anywhere, axes zeroed or shrunk) goes through every library
entry point: it is either rejected with a :class:`RobotModelError` or gives a model
whose kinematics, publishing, lint, reports and URDF round trip all work. A sample goes
through the command line (``check-urdf`` and ``fk``): exit 0, or a non-zero exit with
exactly one line on stderr. Every mutant has a time budget (``PER_MUTANT_S``), so a
hang fails instead of stalling the suite; the whole file runs in well under a minute.

The long-chain case: ``fk`` on a 3,000-joint chain of mixed joint types, with mimic
chains, peaks below ``LONG_CHAIN_RSS_BOUND`` resident memory.
"""

from __future__ import annotations

import contextlib
import functools
import json
import random
import signal
import subprocess
import sys
import textwrap
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path
from types import FrameType

import numpy as np
import robotmodel.robots
from conftest import ERD_ROBOTS

from robotmodel.check import lint, to_graphviz, tree_report
from robotmodel.errors import RobotModelError
from robotmodel.kinematics import (
    KinematicModel,
    KinematicState,
    batch_link_matrices,
    joint_transforms,
    static_transforms,
)
from robotmodel.model import parse_urdf, to_urdf
from robotmodel.xacro import expand

MUTANTS = 300
CLI_SAMPLE = 8
PER_MUTANT_S = 5.0
LONG_CHAIN_RSS_BOUND = 160 * 2**20

ERD_SEEDS = [
    "panda_description/urdf/panda.urdf",
    "ur_description/urdf/ur5_robot.urdf",
    "double_pendulum_description/urdf/double_pendulum.urdf",
    "z1_description/urdf/z1.urdf",
]

VALUES = [
    "nan", "inf", "-inf", "1e400", "1e-320", "1e308", "-1e308", "", " ", "\t1\n", "1 ", " 1", "\u00e9",
    "\u00a0", "0x10", "1_0", "-0", "1" * 400, "0 0", "1 2 3 4", "0 0 0", "1e-300 0 0", "a\tb", "x\ny",
    "\u4e2d\u6587", "\U0001f916", "package://", "file:///dev/null", "/" * 300, "m" * 300 + ".stl",
]
JOINT_TYPES = ["revolute", "continuous", "prismatic", "fixed", "floating", "planar", "hinge", ""]


@functools.cache
def _seeds() -> list[tuple[str, str]]:
    seeds = [(name, expand(robotmodel.robots.path(name))) for name in robotmodel.robots.names()]
    seeds += [(path, (ERD_ROBOTS / path).read_text(encoding="utf-8")) for path in ERD_SEEDS]
    return seeds


def _mutate(root: ET.Element, rng: random.Random) -> None:
    elements = list(root.iter())
    joints = root.findall("joint")
    names = [e.get("name", "") for e in root.findall("link")] + [j.get("name", "") for j in joints]
    op = rng.randrange(9)
    target = rng.choice(elements)
    if op == 0 and target is not root:
        parent = next(p for p in root.iter() if target in list(p))
        parent.remove(target)
    elif op == 1 and target is not root:
        parent = next(p for p in root.iter() if target in list(p))
        parent.append(ET.fromstring(ET.tostring(target)))
    elif op in (2, 3) and target.attrib:
        key = rng.choice(sorted(target.attrib))
        target.set(key, rng.choice(VALUES) if op == 2 else rng.choice([*names, *VALUES]))
    elif op == 4 and target.attrib:
        del target.attrib[rng.choice(sorted(target.attrib))]
    elif op == 5 and joints:
        joint = rng.choice(joints)
        parent, child = joint.find("parent"), joint.find("child")
        if parent is not None and child is not None:
            p, c = parent.get("link", ""), child.get("link", "")
            parent.set("link", c)
            child.set("link", p)
    elif op == 6 and joints:
        joint = rng.choice(joints)
        for old in joint.findall("mimic"):
            joint.remove(old)
        ET.SubElement(joint, "mimic", joint=rng.choice(joints).get("name", ""),
                      multiplier=rng.choice(["1", "-2", "nan", "1e308"]))
    elif op == 7 and joints:
        rng.choice(joints).set("type", rng.choice(JOINT_TYPES))
    elif op == 8 and joints:
        joint = rng.choice(joints)
        for old in joint.findall("axis"):
            joint.remove(old)
        ET.SubElement(joint, "axis", xyz=rng.choice(["0 0 0", "1e-300 0 0", "1e-320 1e-320 0", "1e300 1e300 0",
                                                     "0 0 1 0", "nan 0 1", " 0 0 1"]))


def mutants(n: int, seed: int = 14) -> Iterator[tuple[str, str]]:
    """``n`` mutated URDF texts, each labelled with its seed robot and index."""
    rng = random.Random(seed)
    seeds = _seeds()
    for i in range(n):
        label, text = seeds[i % len(seeds)]
        root = ET.fromstring(text)
        for _ in range(rng.randint(1, 3)):
            _mutate(root, rng)
        yield f"{i}:{label}", ET.tostring(root, encoding="unicode")


@contextlib.contextmanager
def _deadline(seconds: float, label: str) -> Iterator[None]:
    def expired(signum: int, frame: FrameType | None) -> None:
        raise TimeoutError(f"mutant {label} took more than {seconds} s")

    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _exercise(text: str) -> None:
    desc = parse_urdf(text)
    assert parse_urdf(to_urdf(desc)) == desc
    tree_report(desc)
    to_graphviz(desc)
    lint(desc, base_dir=Path.cwd())
    model = KinematicModel(desc)
    state = KinematicState(model)
    state.link_matrices()
    rng = np.random.default_rng(0)
    lo = np.where(np.isfinite(model.lower), model.lower, -np.pi)
    hi = np.where(np.isfinite(model.upper), model.upper, np.pi)
    qs = rng.uniform(np.minimum(lo, hi), np.maximum(lo, hi), (3, model.nv))
    batch = batch_link_matrices(model, qs)
    for k, q in enumerate(qs):
        np.testing.assert_allclose(state.update(q, clamp=True).link_matrices(), batch[k], rtol=1e-9, atol=1e-9)
    joint_transforms(model, dict(zip(model.variables, qs[0], strict=True)))
    static_transforms(model)
    if model.pinocchio_data_bytes < 2**24 and model.link_names:
        state.jacobian(model.link_names[-1])


def test_library_survives_every_mutant() -> None:
    outcomes = {"accepted": 0, "rejected": 0}
    for label, text in mutants(MUTANTS):
        with _deadline(PER_MUTANT_S, label):
            try:
                _exercise(text)
            except RobotModelError as exc:
                assert str(exc), label
                outcomes["rejected"] += 1
            else:
                outcomes["accepted"] += 1
    # The mutations must exercise both sides, or the fuzzing proves little.
    assert outcomes["accepted"] > MUTANTS // 10 and outcomes["rejected"] > MUTANTS // 10, outcomes


def _cli(args: list[str]) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], capture_output=True,
                          text=True, timeout=60, check=False)


def _clean(result: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in result.stderr, result.stderr
    if result.returncode != 0:
        assert result.stdout == ""
        assert result.stderr.count("\n") == 1, result.stderr


def test_command_line_on_a_sample_of_mutants(tmp_path: Path) -> None:
    every = MUTANTS // CLI_SAMPLE
    for i, (label, text) in enumerate(mutants(MUTANTS)):
        if i % every:
            continue
        path = tmp_path / f"m{i}.urdf"
        path.write_text(text, encoding="utf-8")
        for command in (["check-urdf", str(path)], ["fk", str(path), "--clamp"]):
            result = _cli(command)
            assert result.returncode in (0, 1), (label, command, result.stderr)
            _clean(result)


def _mixed_chain(n: int, seed: int = 3) -> str:
    rng = random.Random(seed)
    parts = [f'<link name="l{i}"/>' for i in range(n + 1)]
    for i in range(n):
        jtype = rng.choice(["revolute", "continuous", "prismatic", "fixed"])
        mimic = f'<mimic joint="j{i - 1}" multiplier="0.5"/>' if i and rng.random() < 0.3 else ""
        parts.append(
            f'<joint name="j{i}" type="{jtype}"><parent link="l{i}"/><child link="l{i + 1}"/>'
            f'<origin xyz="0 0 0.05" rpy="{rng.uniform(-1, 1)!r} 0 0"/><axis xyz="0 1 1"/>'
            f'<limit effort="1" velocity="1" lower="-1" upper="1"/>{mimic}</joint>')
    return f'<robot name="mixed">{"".join(parts)}</robot>'


def _peak_rss(argv: list[str]) -> tuple[int, int, str]:
    """Peak RSS (bytes), exit code and stderr of ``argv``, run as the only child of a fresh interpreter."""
    probe = textwrap.dedent("""
        import json, resource, subprocess, sys
        cap = lambda: resource.setrlimit(resource.RLIMIT_AS, (6 * 2**30, 6 * 2**30))
        r = subprocess.run(sys.argv[1:], capture_output=True, text=True, preexec_fn=cap)
        print(json.dumps([resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024, r.returncode,
                          r.stderr[-2000:]]))
    """)
    out = subprocess.run([sys.executable, "-c", probe, *argv], capture_output=True, text=True, check=True,
                         timeout=300)
    peak, code, stderr = json.loads(out.stdout)
    return int(peak), int(code), str(stderr)


def test_long_mixed_chain_stays_under_the_memory_bound(tmp_path: Path) -> None:
    path = tmp_path / "mixed.urdf"
    path.write_text(_mixed_chain(3000), encoding="utf-8")
    peak, code, stderr = _peak_rss([sys.executable, "-m", "robotmodel.cli.main", "fk", str(path),
                                    "--link", "l3000"])
    assert code == 0, stderr
    assert peak < LONG_CHAIN_RSS_BOUND, f"peak RSS {peak / 2**20:.0f} MiB"
