"""`robotmodel xacro` takes every option of xacro 2.1.1's command, with xacro's meaning."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
TOP = f"""<robot name="r" {XACRO_NS}>
  <xacro:property name="w" value="2"/>
  <xacro:include filename="sub/inc.xacro" bogus="1"/>
  <xacro:property name="cfg" value="${{xacro.load_yaml('sub/c.yaml')}}"/>
  <xacro:arg name="a" default="0"/>
  <link name="a${{w}}${{v}}${{cfg.k}}_$(arg a)"/>
</robot>
"""


def _tree(root: Path) -> Path:
    (root / "sub").mkdir(parents=True)
    (root / "sub" / "inc.xacro").write_text(f'<robot {XACRO_NS}><xacro:property name="v" value="3"/></robot>')
    (root / "sub" / "c.yaml").write_text("k: 5\n")
    (root / "top.xacro").write_text(TOP)
    return root / "top.xacro"


def _ours(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "xacro", *args], capture_output=True,
                          text=True, cwd=cwd, check=False)


def _xacro(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    xacro_bin = shutil.which("xacro")
    assert xacro_bin, "the xacro package's console script is missing"
    return subprocess.run([xacro_bin, *args], capture_output=True, text=True, cwd=cwd, check=False)


def _no_addresses(text: str) -> str:
    return re.sub(r" at 0x[0-9a-f]+", " at 0x…", text)


@pytest.mark.parametrize(
    "flags",
    [[], ["-q"], ["-v"], ["-vv"], ["--verbosity", "3"], ["--verbosity=4"], ["-q", "-v"], ["-i"], ["--inorder"]],
    ids=lambda f: " ".join(f) or "default",
)
def test_verbosity_and_inorder_as_xacro(tmp_path: Path, flags: list[str]) -> None:
    _tree(tmp_path)
    ref = _xacro(*flags, "top.xacro", cwd=tmp_path)
    ours = _ours(*flags, "top.xacro", cwd=tmp_path)
    assert ref.returncode == 0, ref.stderr
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout == ref.stdout
    assert _no_addresses(ours.stderr) == _no_addresses(ref.stderr)


def test_deps_prints_the_included_files_as_xacro(tmp_path: Path) -> None:
    _tree(tmp_path)
    ref = _xacro("--deps", "top.xacro", cwd=tmp_path)
    ours = _ours("--deps", "top.xacro", cwd=tmp_path)
    assert ours.returncode == 0, ours.stderr
    assert not ours.stdout.endswith("\n")  # as xacro: no trailing newline
    assert sorted(ours.stdout.split(" ")) == sorted(ref.stdout.split(" ")) == ["sub/c.yaml", "sub/inc.xacro"]
    out = tmp_path / "deps.txt"
    assert _ours("--deps", "-o", str(out), "top.xacro", cwd=tmp_path).returncode == 0
    assert out.read_text() == ours.stdout


def test_root_dir(tmp_path: Path) -> None:
    top = _tree(tmp_path / "pkg")
    # xacro's --root-dir applies to the top file and includes, not to load_yaml.
    lines = [line for line in TOP.splitlines(keepends=True) if "load_yaml" not in line]
    top.write_text("".join(lines).replace("${cfg.k}", ""))
    ref = _xacro("--root-dir", "pkg", "top.xacro", cwd=tmp_path)
    ours = _ours("--root-dir", "pkg", "top.xacro", cwd=tmp_path)
    assert ref.returncode == 0, ref.stderr
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout == ref.stdout


@pytest.mark.parametrize(
    "order",
    [
        ["-o", "{out}", "top.xacro", "a:=1"],
        ["top.xacro", "-o", "{out}", "a:=1"],
        ["top.xacro", "a:=1", "-o", "{out}"],
        ["a:=1", "top.xacro", "-o", "{out}"],
        ["a:=1", "-o", "{out}", "top.xacro"],
        ["-o{out}", "a:=1", "top.xacro"],
    ],
    ids=" ".join,
)
def test_output_and_mappings_in_any_position(tmp_path: Path, order: list[str]) -> None:
    _tree(tmp_path)
    out = tmp_path / "out" / "r.urdf"
    words = [w.format(out=out) for w in order]
    ref = _xacro(*words, cwd=tmp_path)
    assert ref.returncode == 0, ref.stderr
    expected = out.read_text()
    out.unlink()
    ours = _ours(*words, cwd=tmp_path)
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout == ""
    assert out.read_text() == expected
    assert '<link name="a235_1"/>' in expected


@pytest.mark.parametrize("flag", ["--xacro-ns", "--check-order", "--legacy", "--just-deps"])
def test_options_xacro_2_1_1_lacks_are_refused_with_the_xacro_usage(tmp_path: Path, flag: str) -> None:
    # xacro 2.1.1 itself refuses these ROS 1 era options ("no such option"), exit 2.
    _tree(tmp_path)
    assert _xacro(flag, "top.xacro", cwd=tmp_path).returncode == 2
    ours = _ours(flag, "top.xacro", cwd=tmp_path)
    assert ours.returncode == 2 and ours.stdout == ""
    assert ours.stderr.startswith("usage: robotmodel xacro ")
    assert ours.stderr.splitlines()[-1] == f"robotmodel xacro: error: unrecognized arguments: {flag}"


def test_stdin(tmp_path: Path) -> None:
    _tree(tmp_path)
    ours = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "xacro", "-", "a:=7"], input=TOP,
                          capture_output=True, text=True, cwd=tmp_path, check=False)
    assert ours.returncode == 0, ours.stderr
    ref = _xacro("top.xacro", "a:=7", cwd=tmp_path).stdout
    # Same document; the banner names "-" where xacro names the file.
    assert ours.stdout == ref.replace("from " + "top.xacro".ljust(30), "from " + "-".ljust(30))
