"""Every corpus entry point of MANIFEST.md: expansion, counts, and check_urdf output vs urdfdom."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, CORPUS, CORPUS_MISSING, urdfdom_env
from manifest import entries, negatives

from robotmodel.check import tree_report
from robotmodel.model import load, parse_urdf
from robotmodel.xacro import expand

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason=CORPUS_MISSING)  # every test here reads the corpus
ENTRIES = entries(CORPUS) if CORPUS.is_dir() else []
NEGATIVES = negatives(CORPUS) if CORPUS.is_dir() else []


def _urdfdom(urdf_text: str, tmp_path: Path) -> subprocess.CompletedProcess[str]:
    path = tmp_path / "robot.urdf"
    path.write_text(urdf_text, encoding="utf-8")
    return subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                          env=urdfdom_env(), check=False)


def test_manifest_is_read() -> None:
    assert len(ENTRIES) == 63
    assert sum(e.plain for e in ENTRIES) == 12
    assert len(NEGATIVES) == 5


@pytest.mark.parametrize("entry", ENTRIES, ids=[f"{e.number}-{Path(e.path).name}" for e in ENTRIES])
def test_entry_point(entry, tmp_path: Path) -> None:
    source = CORPUS / entry.path
    text = source.read_text(encoding="utf-8") if entry.plain else expand(source, entry.args)
    robot = ET.fromstring(text)
    assert robot.get("name") == entry.robot
    assert len(robot.findall("link")) == entry.links
    assert len(robot.findall("joint")) == entry.joints
    desc = load(source, entry.args)
    ours = tree_report(desc)
    assert ours.splitlines()[2] == entry.root_line
    reference = _urdfdom(text, tmp_path)
    assert reference.returncode == 0, reference.stderr
    assert ours == reference.stdout


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], capture_output=True,
                          text=True, check=False)


@pytest.mark.parametrize("case", NEGATIVES, ids=[f"{Path(n.path).name}-{n.args}" for n in NEGATIVES])
def test_negative_case(case, tmp_path: Path) -> None:
    words = [f"{k}:={v}" for k, v in case.args.items()]
    command = "xacro" if case.xacro_fails else "check-urdf"
    result = _cli(command, str(CORPUS / case.path), *words)
    assert result.returncode == 1
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    # The manifest records upstream's words; ours carry the same substance.
    expected = case.message.removeprefix("error: ").removeprefix("Error:   ")
    expected = expected.replace("<corpus>", str(CORPUS.resolve()))  # package lookup resolves symlinks
    assert expected[:100] in lines[0]
    if not case.xacro_fails:
        text = expand(CORPUS / case.path, case.args)
        with pytest.raises(Exception, match="Failed to"):
            parse_urdf(text)
        assert _urdfdom(text, tmp_path).returncode != 0
