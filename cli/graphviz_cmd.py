"""``robotmodel urdf-to-graphviz`` (alias ``urdf_to_graphviz``): the robot's tree as a graph."""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

from robotmodel.cli._common import add_model_arguments, load_description, write_atomic

from robotmodel.errors import RobotModelError


def register(sub: Any) -> None:
    """Add the ``urdf-to-graphviz`` subcommand."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "urdf-to-graphviz", aliases=["urdf_to_graphviz"],
        help="write the link/joint tree as OUTPUT.gv and OUTPUT.pdf (urdfdom's layout)",
        description="Write $ROBOT_NAME.gv and .pdf in the current directory, or OUTPUT.gv and OUTPUT.pdf. "
        "The .gv is byte-identical to urdfdom's urdf_to_graphviz. Unlike urdfdom, the PDF is only "
        "reported as created when graphviz's dot actually made it.",
    )
    add_model_arguments(parser)
    # urdfdom's form: `urdf_to_graphviz FILE [OUTPUT]`.
    parser.add_argument("output", nargs="?", metavar="OUTPUT", help="output base name (default: the robot's name)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Write the .gv, then the .pdf when graphviz's ``dot`` is installed."""
    from robotmodel.check import to_graphviz

    desc, _ = load_description(args)
    base = args.output or desc.name
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
