"""xacro expansion: golden outputs, parity with the xacro CLI, package resolution, hostile input."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import ERD_ROBOTS
from xmlcompare import xml_diff

from robotmodel.errors import PackageNotFoundError, UntrustedInputError, XacroError
from robotmodel.xacro import expand, expand_string, find_package, resolve_uri

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def _cli(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *args], capture_output=True,
                          text=True, cwd=cwd, check=False)


def test_pr2_matches_upstream_golden_file(corpus: Path) -> None:
    robots = corpus / "xacro" / "xacro" / "test" / "robots" / "pr2"
    ours = expand(robots / "pr2.urdf.xacro")
    golden = (robots / "pr2_1.11.4.xml").read_text(encoding="utf-8")
    assert xml_diff(ours, golden) is None


def test_hector_package_include_matches_shipped_urdf() -> None:
    robots = ERD_ROBOTS / "hector_description" / "robots"
    source = (robots / "quadrotor_base.xacro").read_text(encoding="utf-8")
    wrong = "package://example-robot-data/robots/hector_description/urdf/quadrotor_base.urdf.xacro"
    assert wrong in source  # the include xacro 2.1.1 cannot resolve by itself
    # example-robot-data 6.0.0 ships the included file under robots/, not urdf/: the
    # package:// lookup itself works (the error names the resolved path in the package).
    with pytest.raises(XacroError, match=str(ERD_ROBOTS / "hector_description" / "urdf")):
        expand(robots / "quadrotor_base.xacro")
    fixed = source.replace(wrong, wrong.replace("/urdf/", "/robots/"))
    ours = expand_string(fixed, base_dir=robots)
    shipped = (robots / "quadrotor_base.urdf").read_text(encoding="utf-8")
    # The shipped file came from ROS 1 xacro, which kept xmlns:xacro on <robot>.
    assert xml_diff(ours, shipped, ignore_attrs=("{http://www.ros.org/wiki/xacro}xacro",)) is None


@pytest.mark.parametrize(
    "relative",
    ["urdf_tutorial/urdf_tutorial/urdf/08-macroed.urdf.xacro", "xacro/xacro/test/A.xacro",
     "xacro/xacro/test/emoji.xacro"],
)
def test_cli_output_is_byte_identical_to_xacro(relative: str, corpus: Path) -> None:
    xacro_bin = shutil.which("xacro")
    assert xacro_bin, "the xacro package's console script is missing"
    # Same relative spelling on both sides: the banner quotes the input as given.
    reference = subprocess.run([xacro_bin, relative], capture_output=True, text=True, cwd=corpus, check=True)
    ours = _cli("xacro", relative, cwd=corpus)
    assert ours.returncode == 0, ours.stderr
    assert ours.stdout == reference.stdout


def test_cli_args_and_output_file(tmp_path: Path, corpus: Path) -> None:
    src = corpus / "xacro" / "xacro" / "test" / "test-xacro-cmake" / "test.xacro"
    out = tmp_path / "sub" / "out.urdf"
    result = _cli("xacro", str(src), "foo:=1", "bar:=2", "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert '<a bar="2" foo="1"/>' in out.read_text(encoding="utf-8")


def test_failed_expansion_leaves_no_output_file(tmp_path: Path, corpus: Path) -> None:
    out = tmp_path / "out.urdf"
    result = _cli("xacro", str(corpus / "xacro" / "xacro" / "test" / "broken.xacro"), "-o", str(out))
    assert result.returncode == 1
    assert "XML parsing error" in result.stderr and "broken.xacro" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not out.exists() and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("relative", "needle"),
    [
        ("xacro/xacro/test/broken.xacro", "XML parsing error: syntax error: line 1, column 0"),
        ("xacro/xacro/test/subdir/foo.xacro", "unknown macro name: xacro:foo"),
    ],
)
def test_upstream_fixtures_that_must_fail(relative: str, needle: str, corpus: Path) -> None:
    with pytest.raises(XacroError, match=needle):
        expand(corpus / relative)


def test_missing_input_file_is_a_clean_error() -> None:
    result = _cli("xacro", "does/not/exist.xacro")
    assert result.returncode == 1
    assert result.stderr.strip() == "robotmodel xacro: error: does/not/exist.xacro: input file does not exist"


def _package(root: Path, name: str) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    (root / "package.xml").write_text(f"<package><name>{name}</name></package>", encoding="utf-8")
    return root


def test_find_prefers_explicit_path_then_own_tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    own = _package(tmp_path / "repo" / "pkg_a", "pkg_a")
    other = _package(tmp_path / "elsewhere" / "pkg_a", "pkg_a")
    entry = own / "urdf" / "robot.xacro"
    entry.parent.mkdir()
    assert find_package("pkg_a", start=entry) == own
    assert find_package("pkg_a", start=entry, package_paths=[tmp_path / "elsewhere"]) == other


def test_find_uses_ros_package_path_ament_and_colcon(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    ros1 = _package(tmp_path / "ws1" / "src" / "deep" / "pkg_r", "pkg_r")
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(tmp_path / "ws1"))
    assert find_package("pkg_r") == ros1
    prefix = tmp_path / "prefix"
    (prefix / "share" / "ament_index" / "resource_index" / "packages").mkdir(parents=True)
    (prefix / "share" / "ament_index" / "resource_index" / "packages" / "pkg_m").write_text("")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    assert find_package("pkg_m") == prefix / "share" / "pkg_m"
    colcon = _package(tmp_path / "ws2" / "install" / "pkg_c" / "share" / "pkg_c", "pkg_c")
    monkeypatch.chdir(tmp_path / "ws2")
    assert find_package("pkg_c") == colcon


def test_unknown_package_names_package_and_places(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    pattern = r"package 'no_such_pkg' not found; searched: .*ROS_PACKAGE_PATH"
    with pytest.raises(PackageNotFoundError, match=pattern):
        find_package("no_such_pkg", start=tmp_path)
    pkg = _package(tmp_path / "repo" / "pkg_h", "pkg_h")
    (tmp_path / "repo" / ".git").mkdir()
    (pkg / "r.xacro").write_text(f'<robot {XACRO_NS} name="$(find pkg_h)"/>', encoding="utf-8")
    (tmp_path / "empty").mkdir()
    result = _cli("xacro", str(pkg / "r.xacro"), "--package-path", str(tmp_path / "empty"))
    assert result.returncode == 0, result.stderr  # explicit paths add to the search, they do not replace it
    assert f'name="{pkg}"' in result.stdout


def test_both_find_entry_points_and_package_uri(tmp_path: Path) -> None:
    (tmp_path / ".git").mkdir()  # a repository: its packages are searched beside the input
    pkg = _package(tmp_path / "pkg_x", "pkg_x")
    (pkg / "inc.xacro").write_text(
        f'<robot {XACRO_NS}><xacro:property name="v" value="7"/></robot>', encoding="utf-8")
    doc = (
        f'<robot {XACRO_NS} name="r">'
        '<xacro:include filename="package://pkg_x/inc.xacro"/>'
        '<link name="$(find pkg_x)"/><link name="${find(\'pkg_x\')}"/><link name="v${v}"/></robot>'
    )
    out = expand_string(doc, base_dir=tmp_path)
    assert out.count(f'name="{pkg}"') == 2 and 'name="v7"' in out
    assert resolve_uri("package://pkg_x/inc.xacro", base_dir=tmp_path) == pkg / "inc.xacro"


@pytest.mark.parametrize(
    ("body", "needle"),
    [
        ('<xacro:property name="s" value="${\'a\'*10**10}"/><a v="${s}"/>', "memory"),
        ('<xacro:macro name="m"><xacro:m/></xacro:macro><xacro:m/>', "recursion"),
        (
            "".join(
                f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>'
                for i in range(1, 40)
            ).replace('<xacro:macro name="m1"><xacro:m0/><xacro:m0/></xacro:macro>',
                      '<xacro:macro name="m1"><a/><a/></xacro:macro>')
            + "<xacro:m39/>",
            "did not finish|memory",
        ),
    ],
    ids=["giant-string", "infinite-recursion", "exponential-doubling"],
)
def test_hostile_input_stops_with_clear_error(body: str, needle: str) -> None:
    start = time.monotonic()
    with pytest.raises(XacroError, match=needle):
        expand_string(f"<robot {XACRO_NS}>{body}</robot>", timeout=10.0)
    assert time.monotonic() - start < 15.0  # generous bound on the 10 s limit, not a speed claim


def test_untrusted_refuses_env_and_outside_reads(tmp_path: Path) -> None:
    os.environ.setdefault("HOME", "/root")
    pkg = _package(tmp_path / "pkg_u", "pkg_u")
    outside = tmp_path / "secret.xacro"
    outside.write_text(f'<robot {XACRO_NS}><link name="secret"/></robot>', encoding="utf-8")
    env_doc = pkg / "env.xacro"
    env_doc.write_text(f'<robot {XACRO_NS} name="$(env HOME)"/>', encoding="utf-8")
    include_doc = pkg / "inc.xacro"
    include_doc.write_text(f'<robot {XACRO_NS} name="r"><xacro:include filename="../secret.xacro"/></robot>',
                           encoding="utf-8")
    assert "secret" in expand(include_doc)  # trusted: allowed
    with pytest.raises(UntrustedInputError, match=r"\$\(env\)"):
        expand(env_doc, untrusted=True)
    with pytest.raises(UntrustedInputError, match="outside the input's package roots"):
        expand(include_doc, untrusted=True)
    result = _cli("xacro", str(include_doc), "--untrusted")
    assert result.returncode == 1 and "outside the input's package roots" in result.stderr


def test_dirname_is_the_directory_of_the_file_being_processed(tmp_path: Path) -> None:
    # xacro 2.1.1 fails every $(dirname); ours answers as ROS 1 xacro did, includes too.
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "inc.xacro").write_text(f'<robot {XACRO_NS}><link name="$(dirname)"/></robot>',
                                                encoding="utf-8")
    top = tmp_path / "top.xacro"
    top.write_text(f'<robot {XACRO_NS} name="r"><link name="$(dirname)"/>'
                   '<xacro:include filename="sub/inc.xacro"/></robot>', encoding="utf-8")
    out = expand(top)
    assert f'<link name="{tmp_path}"/>' in out and f'<link name="{tmp_path / "sub"}"/>' in out
