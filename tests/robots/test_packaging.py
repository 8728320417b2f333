"""A non-editable install carries the bundled models inside robotmodel/robots and no stray top-level packages."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_wheel_holds_models_under_robotmodel_robots(tmp_path: Path) -> None:
    subprocess.run([sys.executable, "-m", "pip", "wheel", str(REPO), "-w", str(tmp_path), "--no-deps",
                    "--no-build-isolation", "-q"], check=True, capture_output=True, cwd=tmp_path)
    (wheel,) = tmp_path.glob("robotmodel-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    bundled = {n.removeprefix("robotmodel/robots/") for n in names if n.startswith("robotmodel/robots/")}
    on_disk = {p.name for p in (REPO / "urdf").iterdir() if p.suffix in {".xacro", ".urdf", ".py"}}
    assert on_disk <= bundled, sorted(on_disk - bundled)
    top = {n.split("/")[0] for n in names if "/" in n and not n.split("/")[0].endswith((".dist-info", ".data"))}
    assert top == {"robotmodel"}, top
    assert not any(n in {"cli.py", "urdf.py"} for n in names)
