"""Corpus entry points (MANIFEST.md): expanded through robotmodel.xacro, then our .gv must equal
urdf_to_graphviz's on that same expanded text, and the description must round-trip through to_urdf.
(check_urdf parity on the corpus is in tests/test_corpus.py.)"""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from conftest import CORPUS, CORPUS_MISSING, URDF_TO_GRAPHVIZ_BIN, urdfdom_env
from manifest import entries

from robotmodel.check import to_graphviz, tree_report
from robotmodel.model import load, parse_urdf, to_urdf

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason=CORPUS_MISSING)  # every test here reads the corpus
ENTRIES = entries(CORPUS) if CORPUS.is_dir() else []


@pytest.mark.parametrize("entry", ENTRIES, ids=[f"{e.number}-{Path(e.path).name}" for e in ENTRIES])
def test_graphviz_and_round_trip(entry, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    desc = load(CORPUS / entry.path, entry.args)
    assert tree_report(desc).splitlines()[2] == entry.root_line
    assert (len(desc.links), len(desc.joints)) == (entry.links, entry.joints)
    expanded = tmp_path / "expanded.urdf"
    expanded.write_text(desc.source_text, encoding="utf-8")
    env = urdfdom_env()
    env["PATH"] = "/nonexistent"  # the .gv only; urdfdom would otherwise also run dot
    subprocess.run([str(URDF_TO_GRAPHVIZ_BIN), str(expanded), "ref"], capture_output=True, env=env,
                   cwd=tmp_path, check=True)
    assert to_graphviz(desc) == (tmp_path / "ref.gv").read_text(encoding="utf-8")
    assert parse_urdf(to_urdf(desc)) == desc
