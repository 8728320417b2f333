"""urdf_to_graphviz as a program: the robot's tree written as ``BASE.gv``, then ``BASE.pdf`` with graphviz's dot."""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

from robotmodel._atomic import write_atomic
from robotmodel.errors import RobotModelError

if TYPE_CHECKING:
    from robotmodel.model import RobotDescription

__all__ = ["run_urdf_to_graphviz"]


def run_urdf_to_graphviz(desc: RobotDescription, output: str | None = None) -> int:
    """Write ``OUTPUT.gv`` (default: the robot's name; urdfdom's exact text) and, when dot is installed, the PDF.

    Says ``Created file ...`` for each file actually made, as urdfdom does (the PDF only when
    dot made it); a dot failure raises RobotModelError. Returns the exit code (0).
    """
    from robotmodel.check._report import to_graphviz

    base = output or desc.name
    gv = Path(f"{base}.gv")
    write_atomic(gv, to_graphviz(desc))
    print(f"Created file {gv}")
    dot = shutil.which("dot")
    if dot is None:
        print(f"dot (graphviz) is not installed: {base}.pdf was not created", file=sys.stderr)
        return 0
    pdf = Path(f"{base}.pdf")
    with tempfile.TemporaryDirectory(dir=pdf.resolve().parent) as tmp:
        tmp_pdf = Path(tmp) / pdf.name
        result = subprocess.run([dot, "-Tpdf", str(gv), "-o", str(tmp_pdf)],
                                capture_output=True, text=True, check=False)
        if result.returncode != 0:
            raise RobotModelError(f"dot failed on {gv}: {result.stderr.strip()}")
        tmp_pdf.replace(pdf)
    print(f"Created file {pdf}")
    return 0
