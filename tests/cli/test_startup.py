"""Lean start-up: `robotmodel --help` and every subcommand's parser load no heavy library; check-urdf on a
plain URDF loads neither Pinocchio nor xacro. Module sets, not timings (those are in benchmarks/)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from conftest import ERD_ROBOTS

# Heavy or runtime-only packages a parser never needs (numpy alone costs ~0.1 s to import).
HEAVY = {"pinocchio", "zenoh", "meshcat", "trimesh", "yourdfpy", "numpy", "xacro", "rosbags", "tornado", "yaml",
         "scipy"}


def _imported(code: str, cwd: Path) -> set[str]:
    """Top-level names of every module `python -X importtime` reports for ``code``, run in ``cwd``."""
    result = subprocess.run([sys.executable, "-X", "importtime", "-c", code], capture_output=True,
                            text=True, cwd=cwd, check=False)
    names = set()
    for line in result.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            names.add(line.rsplit("|", 1)[1].strip().split(".")[0])
    assert names, result.stderr
    return names


def test_help_imports_no_heavy_module(tmp_path: Path) -> None:
    code = "import robotmodel.cli.main as m\nm.build_parser()\ntry:\n    m.main(['--help'])\nexcept SystemExit:\n    pass"
    assert _imported(code, tmp_path) & HEAVY == set()


def test_every_subcommand_help_imports_no_heavy_module(tmp_path: Path) -> None:
    code = (
        "import sys, contextlib, io\n"
        "import robotmodel.cli.main as m\n"
        "parser = m.build_parser()\n"
        "names = [a for a in parser._subparsers._group_actions[0].choices]\n"
        "for name in names:\n"
        "    with contextlib.suppress(SystemExit), contextlib.redirect_stdout(io.StringIO()):\n"
        "        m.main([name, '--help'])\n"
        "print(len(names), file=sys.stderr)\n"
    )
    assert _imported(code, tmp_path) & HEAVY == set()


def test_check_urdf_on_a_plain_urdf_loads_neither_pinocchio_nor_xacro(tmp_path: Path) -> None:
    panda = ERD_ROBOTS / "panda_description/urdf/panda.urdf"
    code = f"import robotmodel.cli.main as m\nassert m.main(['check-urdf', {str(panda)!r}]) == 0"
    assert _imported(code, tmp_path) & (HEAVY - {"numpy"}) == set()
