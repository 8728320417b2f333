"""A non-editable install: the wheel carries the models under robotmodel/robots and no top-level cli/urdf."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

from conftest import REPO


def test_wheel_layout(tmp_path: Path) -> None:
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w",
                    str(tmp_path), str(REPO)], check=True, capture_output=True)
    wheel = next(tmp_path.glob("robotmodel-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    tops = {n.split("/")[0] for n in names}
    assert tops == {"robotmodel", f"{wheel.name.split('-')[0]}-{wheel.name.split('-')[1]}.dist-info"}
    for model in ("arm.urdf.xacro", "diffbot.urdf.xacro", "skid_steer.urdf.xacro", "inertia_macros.xacro"):
        assert f"robotmodel/robots/{model}" in names
    assert "robotmodel/cli/main.py" in names
    entry = next(n for n in names if n.endswith("entry_points.txt"))
    text = zipfile.ZipFile(wheel).read(entry).decode()
    assert "robotmodel = robotmodel.cli.main:main" in text and "\nxacro" not in text
