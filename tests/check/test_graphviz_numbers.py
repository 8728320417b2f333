"""urdf_to_graphviz's number formatting and rpy round trip on awkward values, against the binary.

One synthetic robot with many joints whose origins hit the corners: gimbal lock (pitch near
±π/2), ±π yaw, negative zeros, tiny and huge translations, quat_xyzw origins (URDF 1.1).
"""

from __future__ import annotations

import math
import random
import subprocess
from pathlib import Path

from conftest import URDF_TO_GRAPHVIZ_BIN, urdfdom_env

from robotmodel.check import to_graphviz
from robotmodel.model import parse_urdf

SPECIAL = [0.0, -0.0, math.pi, -math.pi, math.pi / 2, -math.pi / 2, 1.5707963, -1.57079632679, 3.14159265359,
           -3.14159265359, 1e-7, -1e-7, 1e-5, 123456.789, 1e6, 1e-300, 0.5, 2.0]


def _origin(rng: random.Random, index: int) -> str:
    def pick() -> float:
        return rng.choice(SPECIAL) if rng.random() < 0.5 else rng.uniform(-4.0, 4.0)

    xyz = " ".join(repr(pick()) for _ in range(3))
    if index % 5 == 4:
        q = [rng.uniform(-1.0, 1.0) for _ in range(4)]
        if index % 10 == 9:
            q = [0.0, rng.choice([1.0, -1.0]), 0.0, rng.choice([1.0, 1e-9])]  # pitch ±π/2
        return f'<origin xyz="{xyz}" quat_xyzw="{" ".join(repr(v) for v in q)}"/>'
    return f'<origin xyz="{xyz}" rpy="{" ".join(repr(pick()) for _ in range(3))}"/>'


def test_awkward_origins_match_urdfdom(tmp_path: Path) -> None:
    rng = random.Random(20261122)
    parts = ['<robot name="numbers" version="1.1">', '<link name="l0"/>']
    for i in range(1, 301):
        parts.append(f'<link name="l{i}"/>')
        parent = rng.randrange(i)
        parts.append(f'<joint name="j{i:03d}" type="fixed">{_origin(rng, i)}'
                     f'<parent link="l{parent}"/><child link="l{i}"/></joint>')
    parts.append("</robot>")
    path = tmp_path / "numbers.urdf"
    path.write_text("\n".join(parts))
    env = urdfdom_env()
    env["PATH"] = "/nonexistent"
    subprocess.run([str(URDF_TO_GRAPHVIZ_BIN), str(path), "ref"], capture_output=True, env=env, cwd=tmp_path,
                   check=True)
    expected = (tmp_path / "ref.gv").read_text().splitlines()
    ours = to_graphviz(parse_urdf(path.read_text())).splitlines()
    assert len(ours) == len(expected)
    mismatches = [(a, b) for a, b in zip(ours, expected, strict=True) if a != b]
    assert mismatches == []
