"""A clone with nothing beside it: the corpus tests skip with one line saying why, nothing fails."""

from __future__ import annotations

import os
import subprocess
import sys

from conftest import REPO


def test_corpus_tests_skip_when_the_corpus_is_absent() -> None:
    env = dict(os.environ, ROBOTMODEL_CORPUS=str(REPO / "no-such-corpus"))
    files = ["tests/test_corpus.py", "tests/check/test_corpus_parity.py", "tests/xacro/test_expand.py"]
    only_corpus = "golden or byte_identical or output_file or must_fail or manifest or entry or negative or round_trip"
    result = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-rs", *files,
                             "-k", only_corpus], capture_output=True, text=True, cwd=REPO, env=env, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
    skips = [line for line in result.stdout.splitlines() if line.startswith("SKIPPED")]
    assert len(skips) >= 5 and "failed" not in result.stdout
    assert all(line.endswith("(set ROBOTMODEL_CORPUS to run these tests)") for line in skips), skips

