"""ROS command-line forms in every command taking xacro arguments: name:=value anywhere, '-' for stdin,
and errors that show the subcommand's usage."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ERD_ROBOTS

XACRO = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
         '<xacro:arg name="p" default="a_"/><link name="$(arg p)base"/><link name="$(arg p)arm"/>'
         '<joint name="j" type="prismatic"><parent link="$(arg p)base"/><child link="$(arg p)arm"/>'
         '<origin xyz="1 2 3"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
         "</joint></robot>")
PANDA = ERD_ROBOTS / "panda_description/urdf/panda.urdf"


def _run(*args: str, cwd: Path, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], capture_output=True, text=True,
                          cwd=cwd, input=stdin, check=False)


def _robot(tmp_path: Path) -> Path:
    path = tmp_path / "r.urdf.xacro"
    path.write_text(XACRO)
    return path


@pytest.mark.parametrize(
    "words",
    [
        ["check-urdf", "p:=b_", "r.urdf.xacro"],
        ["check-urdf", "r.urdf.xacro", "--package-path", ".", "p:=b_"],
        ["check_urdf", "--format", "text", "p:=b_", "r.urdf.xacro"],
        ["fk", "p:=b_", "r.urdf.xacro", "--joint", "j=0.5"],
        ["fk", "r.urdf.xacro", "--joint", "j=0.5", "p:=b_", "--format", "text"],
        ["fk", "--joint", "j=0.5", "r.urdf.xacro", "_ignored:=x", "p:=b_"],
    ],
    ids=" ".join,
)
def test_mappings_anywhere(tmp_path: Path, words: list[str]) -> None:
    _robot(tmp_path)
    result = _run(*words, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "b_arm" in result.stdout and "a_arm" not in result.stdout
    if words[0] == "fk":
        assert "b_arm:\n  Translation: [1.000000, 2.000000, 3.500000]" in result.stdout


def test_graphviz_output_and_mappings_anywhere(tmp_path: Path) -> None:
    _robot(tmp_path)
    env_free = ["urdf-to-graphviz", "p:=b_", "r.urdf.xacro", "tree", "p:=c_"]  # the last value wins, as xacro
    result = _run(*env_free, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("Created file tree.gv\n")
    assert '"c_arm"' in (tmp_path / "tree.gv").read_text()


@pytest.mark.parametrize("command", ["xacro", "check-urdf", "fk", "urdf-to-graphviz"])
def test_errors_show_the_subcommand_usage(tmp_path: Path, command: str) -> None:
    _robot(tmp_path)
    for words in (["r.urdf.xacro", "--no-such-flag", "p:=b_"], ["r.urdf.xacro", "a:=b:=c"], []):
        result = _run(command, *words, cwd=tmp_path)
        assert result.returncode == 2, (words, result.stderr)
        assert result.stdout == ""
        assert result.stderr.startswith(f"usage: robotmodel {command} [name:=value ...] "), result.stderr
        assert result.stderr.splitlines()[-1].startswith(f"robotmodel {command}: error: ")
    assert not list(tmp_path.glob("*.gv"))


def test_commands_without_xacro_arguments_refuse_mappings(tmp_path: Path) -> None:
    result = _run("demo", "a:=1", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.startswith("usage: robotmodel demo ")
    assert result.stderr.splitlines()[-1] == "robotmodel demo: error: unrecognized arguments: a:=1"


def test_stdin_in_fk(tmp_path: Path) -> None:
    by_file = _run("fk", str(PANDA), "--format", "json", cwd=tmp_path)
    by_stdin = _run("fk", "-", "--format", "json", cwd=tmp_path, stdin=PANDA.read_text())
    assert by_stdin.returncode == 0, by_stdin.stderr
    assert json.loads(by_stdin.stdout) == json.loads(by_file.stdout)
    xacro_stdin = _run("fk", "p:=s_", "-", "--link", "s_arm", cwd=tmp_path, stdin=XACRO)
    assert xacro_stdin.returncode == 0, xacro_stdin.stderr
    assert "s_arm:" in xacro_stdin.stdout
    empty = _run("fk", "-", cwd=tmp_path, stdin="")
    assert empty.returncode == 1 and empty.stdout == ""
    assert empty.stderr == "robotmodel fk: error: <stdin>: empty document or not XML\n"


def test_stdin_in_urdf_to_graphviz(tmp_path: Path) -> None:
    (tmp_path / "file").mkdir()
    (tmp_path / "stdin").mkdir()
    assert _run("urdf-to-graphviz", str(PANDA), "x", cwd=tmp_path / "file").returncode == 0
    result = _run("urdf-to-graphviz", "-", "x", cwd=tmp_path / "stdin", stdin=PANDA.read_text())
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "stdin" / "x.gv").read_text() == (tmp_path / "file" / "x.gv").read_text()
