"""``robotmodel urdf-to-graphviz`` (alias ``urdf_to_graphviz``): the robot's tree as a graph."""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

from robotmodel.cli._common import add_model_arguments, split_mappings, write_atomic

from robotmodel.check import to_graphviz
from robotmodel.errors import RobotModelError
from robotmodel.model import load


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
    parser.set_defaults(func=run)
    # urdfdom's form is `urdf_to_graphviz FILE [OUTPUT]`: OUTPUT arrives as the first
    # word of the name:=value list (see run); say so in the usage line.
    for action in parser._actions:
        if action.dest == "mappings":
            action.metavar = "[OUTPUT] name:=value"
            action.help = "output base name (default: the robot's name), then xacro arguments"


def run(args: argparse.Namespace) -> int:
    """Write the .gv, then the .pdf when graphviz's ``dot`` is installed."""
    # urdfdom takes OUTPUT as the optional second positional word; keep that form.
    words = list(args.mappings)
    output = None
    if words and ":=" not in words[0]:
        output = words.pop(0)
    desc = load(args.file, split_mappings(words), package_paths=args.package_path, untrusted=args.untrusted)
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
