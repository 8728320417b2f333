"""robotmodel.resources: ROS package lookup and package:// / file:// resolution, outside xacro."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robotmodel.errors import PackageNotFoundError, ResourceError, RobotModelError, XacroError
from robotmodel.resources import find_package, resolve_uri


def _package(root: Path, name: str) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    (root / "package.xml").write_text(f"<package><name>{name}</name></package>", encoding="utf-8")
    return root


def test_missing_package_is_a_resource_error_not_a_xacro_error(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    with pytest.raises(PackageNotFoundError) as info:
        resolve_uri("package://no_such_pkg/meshes/a.stl", base_dir=tmp_path)
    assert isinstance(info.value, ResourceError) and isinstance(info.value, RobotModelError)
    assert not isinstance(info.value, XacroError)
    assert info.value.package == "no_such_pkg"


def test_resolution(tmp_path: Path) -> None:
    pkg = _package(tmp_path / "repo" / "pkg_x", "pkg_x")
    (tmp_path / "repo" / ".git").mkdir()
    assert find_package("pkg_x", start=pkg / "urdf" / "r.urdf") == pkg
    assert resolve_uri("package://pkg_x/meshes/a.stl", base_dir=pkg / "urdf") == pkg / "meshes" / "a.stl"
    assert resolve_uri("file:///abs/a.stl") == Path("/abs/a.stl")
    assert resolve_uri("meshes/a.stl", base_dir=pkg) == pkg / "meshes" / "a.stl"
    with pytest.raises(ResourceError, match=r"unsupported URI scheme in 'http://x/a\.stl'"):
        resolve_uri("http://x/a.stl")
    with pytest.raises(ResourceError, match=r"malformed package URI 'package:///a\.stl'"):
        resolve_uri("package:///a.stl")


def test_xacro_expansion_reports_a_missing_package_as_a_resource_error(tmp_path: Path) -> None:
    from robotmodel.xacro import expand_string

    doc = '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r"><link name="$(find no_such_pkg)"/></robot>'
    with pytest.raises(PackageNotFoundError, match="package 'no_such_pkg' not found"):
        expand_string(doc, base_dir=tmp_path)


def test_resources_import_neither_xacro_nor_the_model() -> None:
    code = "import sys, robotmodel.resources; print(sorted(m for m in sys.modules if m.startswith(('xacro', 'robotmodel.'))))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert eval(out) == ["robotmodel.errors", "robotmodel.resources", "robotmodel.resources._packages",
                         "robotmodel.resources._uri"]


def test_package_not_found_names_the_way_to_give_it(tmp_path: Path) -> None:
    """The one line says how to point at the package (--package-path, ROS_PACKAGE_PATH), and doing so works."""
    import os

    work = tmp_path / "work"
    work.mkdir()
    robot = work / "r.urdf.xacro"
    robot.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="$(find my_pkg)/parts.xacro"/><link name="a"/></robot>')
    pkg = _package(tmp_path / "elsewhere" / "my_pkg", "my_pkg")
    (pkg / "parts.xacro").write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"/>')
    env = {k: v for k, v in os.environ.items() if k not in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH")}

    def run(*words: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *words], capture_output=True,
                              text=True, timeout=120, check=False, cwd=work, env=env)

    proc = run("check_urdf", str(robot))
    assert proc.returncode == 1
    (line,) = proc.stderr.splitlines()
    assert "package 'my_pkg' not found" in line and "--package-path DIR" in line and "ROS_PACKAGE_PATH" in line
    assert run("check_urdf", str(robot), "--package-path", str(tmp_path / "elsewhere")).returncode == 0
