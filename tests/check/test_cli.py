"""The check-urdf and urdf-to-graphviz subcommands, run in-process through robotmodel's main()."""

from __future__ import annotations

import io
import json
import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import CHECK_URDF_BIN, ERD_ROBOTS, URDF_TO_GRAPHVIZ_BIN, urdfdom_env
from robotmodel.cli.main import main

PANDA = ERD_ROBOTS / "panda_description/urdf/panda.urdf"
XACRO = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
         '<xacro:arg name="p" default="a_"/><link name="$(arg p)base"/><link name="$(arg p)arm">'
         '<inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>'
         '</link><joint name="j" type="continuous"><parent link="$(arg p)base"/><child link="$(arg p)arm"/>'
         "</joint></robot>")


def _urdfdom_check(path: Path) -> str:
    return subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True,
                          env=urdfdom_env(), check=True).stdout


def test_alias_and_warnings_after_tree(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "r.urdf.xacro"
    path.write_text(XACRO)
    assert main(["check_urdf", str(path), "p:=b_"]) == 0
    out, err = capsys.readouterr()
    expanded = tmp_path / "expanded.urdf"
    expanded.write_text(XACRO.replace("$(arg p)", "b_"))
    assert out == _urdfdom_check(expanded)
    assert "warning: [mass-not-positive] link [b_arm]" in err
    assert main(["check-urdf", "--strict", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert "error: [mass-not-positive] link [a_arm]" in err


def test_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "r.urdf.xacro"
    path.write_text(XACRO)
    assert main(["check-urdf", "--format", "json", str(path)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is True
    assert (report["robot"], report["root"], report["links"], report["joints"]) == ("r", "a_base", 2, 1)
    assert report["tree"] == [{"depth": 1, "joint": "j", "type": "continuous", "parent": "a_base",
                               "child": "a_arm"}]
    assert [f["code"] for f in report["findings"]] == ["mass-not-positive"]
    path.write_text("<robot/>")
    assert main(["check-urdf", "--format", "json", str(path)]) == 1
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is False and "No name given for the robot." in report["error"]


def test_stdin(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr("sys.stdin", io.StringIO(PANDA.read_text()))
    assert main(["check-urdf", "-"]) == 0
    assert capsys.readouterr().out == _urdfdom_check(PANDA)
    monkeypatch.setattr("sys.stdin", io.StringIO(""))
    assert main(["check-urdf", "-"]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "empty document" in err


def test_error_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "bad.urdf"
    path.write_text('<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
                    '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>')
    assert main(["check-urdf", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err == (f"robotmodel check-urdf: error: {path}: Failed to find root link: "
                   "Two root links found: [a] and [c]\n")
    assert main(["check-urdf", str(tmp_path / "missing.urdf")]) == 1
    assert "no such file" in capsys.readouterr().err


def _reference_gv(path: Path, tmp_path: Path) -> str:
    ref_dir = tmp_path / "ref"
    ref_dir.mkdir()
    env = urdfdom_env()
    env["PATH"] = "/nonexistent"
    subprocess.run([str(URDF_TO_GRAPHVIZ_BIN), str(path)], capture_output=True, env=env, cwd=ref_dir,
                   check=True)
    return (ref_dir / "panda.gv").read_text()


@pytest.mark.skipif(shutil.which("dot") is None, reason="graphviz's dot is not installed")
def test_graphviz_writes_gv_and_pdf(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                    capsys: pytest.CaptureFixture[str]) -> None:
    expected = _reference_gv(PANDA, tmp_path)
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    assert main(["urdf_to_graphviz", str(PANDA)]) == 0
    assert capsys.readouterr().out == "Created file panda.gv\nCreated file panda.pdf\n"
    assert (work / "panda.gv").read_text() == expected
    assert (work / "panda.pdf").read_bytes().startswith(b"%PDF")
    assert main(["urdf-to-graphviz", str(PANDA), "out/tree"]) == 0
    assert (work / "out/tree.gv").read_text() == expected
    assert (work / "out/tree.pdf").is_file()
    assert sorted(p.name for p in work.rglob("*")) == ["out", "panda.gv", "panda.pdf", "tree.gv", "tree.pdf"]


def test_graphviz_without_dot_says_so(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                      capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PATH", "/nonexistent")
    assert main(["urdf-to-graphviz", str(PANDA)]) == 0
    out, err = capsys.readouterr()
    assert out == "Created file panda.gv\n"
    assert "panda.pdf was not created" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["panda.gv"]


def test_graphviz_invalid_robot_writes_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "in" / "bad.urdf"
    bad.parent.mkdir()
    bad.write_text('<robot name="r"/>')
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    monkeypatch.chdir(out_dir)
    assert main(["urdf-to-graphviz", str(bad)]) == 1
    assert "No link elements found" in capsys.readouterr().err
    assert list(out_dir.iterdir()) == []


@pytest.mark.parametrize("kind", ["empty.urdf", "blank.urdf.xacro", "/dev/null", "pipe"])
def test_empty_input_says_what_urdfdom_says(tmp_path: Path, kind: str) -> None:
    """An empty document (a file, blanks only, /dev/null, a shell's <(...) pipe) is named as urdfdom names it."""
    import os
    import sys
    import threading

    if kind == "/dev/null":
        path = Path(kind)
    elif kind == "pipe":
        path = tmp_path / "fifo"
        os.mkfifo(path)
        threading.Thread(target=lambda: path.open("wb").close(), daemon=True).start()  # the writer: nothing
    else:
        path = tmp_path / kind
        path.write_text("" if kind.startswith("empty") else " \n\t\n")
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "check_urdf", str(path)],
                          capture_output=True, text=True, timeout=60, check=False)
    assert proc.returncode == 1 and proc.stdout == ""
    assert proc.stderr == (f"robotmodel check_urdf: error: {path}: empty file: no XML document "
                           "(XML_ERROR_EMPTY_DOCUMENT)\n")
    if kind != "pipe":  # urdfdom's own verdict on the same input
        ref = subprocess.run([str(CHECK_URDF_BIN), str(path)], capture_output=True, text=True, env=urdfdom_env(),
                             check=False)
        assert ref.returncode != 0 and "XML_ERROR_EMPTY_DOCUMENT" in ref.stderr


def test_a_pipe_holding_a_robot_is_checked(tmp_path: Path) -> None:
    import os
    import sys
    import threading

    path = tmp_path / "fifo"
    os.mkfifo(path)
    threading.Thread(target=lambda: path.write_bytes(PANDA.read_bytes()), daemon=True).start()
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "check_urdf", str(path)],
                          capture_output=True, text=True, timeout=60, check=False)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == _urdfdom_check(PANDA)
