"""Many files in one ``check-urdf`` run (a process pool) against one run per file.

The many-file run's stdout is the single runs' stdouts in order, each finding line is the
single run's line naming its file, the exit code is the worst, and the summary counts what the
single runs reported.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import BUNDLED, CHECK_URDF_BIN, erd_urdfs, urdfdom_env
from robotmodel.cli.main import main

PREFIX = "robotmodel check-urdf: "


def _single(path: str, capsys: pytest.CaptureFixture[str], *extra: str) -> tuple[int, str, list[str]]:
    code = main(["check-urdf", path, *extra])
    out, err = capsys.readouterr()
    return code, out, err.splitlines()


def _named(line: str, path: str) -> str:
    """A single-file stderr line as a many-file run prints it (errors already name their file)."""
    body = line.removeprefix(PREFIX)
    return line if body.startswith("error: ") and path in body else f"{PREFIX}{path}: {body}"


def _expected_summary(results: list[tuple[int, str, list[str]]]) -> str:
    failed = sum(1 for code, _, _ in results if code != 0)
    errors = sum(1 for _, _, err in results for line in err if line.startswith(PREFIX + "error: "))
    warnings = sum(1 for _, _, err in results for line in err if line.startswith(PREFIX + "warning: "))
    n = len(results)
    return (f"{PREFIX}{n} file{'s' * (n != 1)} checked: {n - failed} passed, {failed} failed "
            f"({errors} error{'s' * (errors != 1)}, {warnings} warning{'s' * (warnings != 1)})")


def test_example_robot_data_many_equals_singles(capsys: pytest.CaptureFixture[str]) -> None:
    files = [str(p) for p in erd_urdfs()]
    singles = [_single(f, capsys) for f in files]
    code = main(["check-urdf", "--jobs", "2", *files])
    out, err = capsys.readouterr()
    assert out == "".join(s[1] for s in singles)
    assert err.splitlines() == [_named(line, f) for f, s in zip(files, singles, strict=True) for line in s[2]] + [
        _expected_summary(singles)]
    assert code == max(s[0] for s in singles) == 1
    # The single runs' stdout is urdfdom's: spot-check a passing file against check_urdf itself.
    first_ok = next(f for f, s in zip(files, singles, strict=True) if s[0] == 0)
    reference = subprocess.run([str(CHECK_URDF_BIN), first_ok], capture_output=True, text=True, env=urdfdom_env(),
                               check=True).stdout
    assert reference in out


def test_strict_and_mixed_outcomes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r"><link name="a"/><link name="b"/></robot>')
    files = [str(p) for p in sorted(BUNDLED.glob("*.urdf.xacro"))] + [str(bad), str(tmp_path / "missing.urdf")]
    files.append(str(erd_urdfs()[0]))
    for extra in ([], ["--strict"]):
        singles = [_single(f, capsys, *extra) for f in files]
        code = main(["check-urdf", *extra, *files])
        out, err = capsys.readouterr()
        assert code == 1 == max(s[0] for s in singles)
        assert out == "".join(s[1] for s in singles)
        assert err.splitlines()[-1] == _expected_summary(singles)
        assert sum(s[0] for s in singles) >= 2


def test_globs_and_process_runs(tmp_path: Path) -> None:
    """The installed command, as CI runs it: a recursive glob, exit codes, the summary on stderr only."""
    robots = tmp_path / "robots"
    (robots / "deep").mkdir(parents=True)
    for p in BUNDLED.glob("*.xacro"):
        (robots / "deep" / p.name).write_text(p.read_text())
    (robots / "plain.urdf").write_text('<robot name="p"><link name="only"/></robot>')
    run = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "check-urdf", "robots/**/*.urdf.xacro",
                          "robots/*.urdf"], cwd=tmp_path, capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stdout.count("robot name is: ") == 4
    assert run.stderr == f"{PREFIX}4 files checked: 4 passed, 0 failed (0 errors, 0 warnings)\n"
    (robots / "plain.urdf").write_text('<robot name="p"/>')
    run = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "check-urdf", "--format", "json",
                          "robots/**/*.urdf.xacro", "robots/*.urdf", "robots/none*.urdf"], cwd=tmp_path,
                         capture_output=True, text=True, check=False)
    assert run.returncode == 1
    report = json.loads(run.stdout)
    assert report["ok"] is False
    assert [(f["file"], f["ok"]) for f in report["files"]] == [
        ("robots/deep/arm.urdf.xacro", True), ("robots/deep/diffbot.urdf.xacro", True),
        ("robots/deep/skid_steer.urdf.xacro", True), ("robots/plain.urdf", False), ("robots/none*.urdf", False)]
    assert "No link elements found" in report["files"][3]["error"]
    assert "no such file" in report["files"][4]["error"]
    assert re.fullmatch(rf"{re.escape(PREFIX)}5 files checked: 3 passed, 2 failed \(2 errors, 0 warnings\)\n",
                        run.stderr)


def test_single_file_output_is_unchanged(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """One file: no summary line, stdout exactly urdfdom's, the error alone on stderr."""
    panda = str(erd_urdfs()[[p.name for p in erd_urdfs()].index("panda.urdf")])
    code, out, err = _single(panda, capsys)
    reference = subprocess.run([str(CHECK_URDF_BIN), panda], capture_output=True, text=True, env=urdfdom_env(),
                               check=True).stdout
    assert (code, out) == (0, reference)
    assert not any("checked:" in line for line in err)
