"""Package search beside the input stays inside the input's own workspace, repository or package chain."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robotmodel.errors import PackageNotFoundError
from robotmodel.resources import find_package


@pytest.fixture(autouse=True)
def _no_ros_env(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.chdir(tmp_path)


def _package(root: Path, name: str) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    (root / "package.xml").write_text(f"<package><name>{name}</name></package>", encoding="utf-8")
    return root


def _entry(folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    entry = folder / "robot.urdf"
    entry.write_text('<robot name="r"><link name="a"/></robot>')
    return entry


def test_a_loose_file_finds_no_unrelated_copy_nearby(tmp_path: Path) -> None:
    # The reported case: a file in a scratch folder picked up some other copy of the package.
    _package(tmp_path / "someone_else" / "project" / "meshes_pkg", "meshes_pkg")
    entry = _entry(tmp_path / "scratch")
    with pytest.raises(PackageNotFoundError, match="nothing beside the input"):
        find_package("meshes_pkg", start=entry)


def test_repository_bounds_the_search(tmp_path: Path) -> None:
    repo = tmp_path / "repo"
    (repo / ".git").mkdir(parents=True)
    inside = _package(repo / "a" / "b" / "c" / "pkg_in", "pkg_in")
    entry = _entry(repo / "robots")
    _package(tmp_path / "pkg_out", "pkg_out")
    assert find_package("pkg_in", start=entry) == inside
    with pytest.raises(PackageNotFoundError, match=f"the input's repository {repo}"):
        find_package("pkg_out", start=entry)


def test_workspace_bounds_the_search_and_beats_an_outer_copy(tmp_path: Path) -> None:
    ws = tmp_path / "ws"
    (ws / ".catkin_workspace").parent.mkdir(parents=True)
    (ws / ".catkin_workspace").write_text("")
    own = _package(ws / "src" / "repo_a" / "desc_pkg", "desc_pkg")
    sibling = _package(ws / "src" / "repo_b" / "group" / "dep_pkg", "dep_pkg")
    (ws / "src" / "repo_a" / ".git").mkdir()  # a repository inside the workspace: the workspace still bounds
    _package(tmp_path / "dep_pkg", "dep_pkg")  # outside the workspace: never used
    entry = _entry(own / "urdf")
    assert find_package("dep_pkg", start=entry) == sibling


def test_colcon_workspace_marker(tmp_path: Path) -> None:
    ws = tmp_path / "cws"
    (ws / "install").mkdir(parents=True)
    (ws / "install" / ".colcon_install_layout").write_text("isolated")
    dep = _package(ws / "src" / "x" / "dep_c", "dep_c")
    entry = _entry(ws / "src" / "y" / "urdf")
    assert find_package("dep_c", start=entry) == dep


def test_package_chain_finds_sibling_packages_of_an_unversioned_checkout(tmp_path: Path) -> None:
    # A repository copied without .git (as kuka_experimental in the corpus): its packages see each other.
    checkout = tmp_path / "kuka_like"
    resources = _package(checkout / "kuka_resources", "kuka_resources")
    support = _package(checkout / "kuka_kr6_support", "kuka_kr6_support")
    entry = _entry(support / "urdf")
    assert find_package("kuka_resources", start=entry) == resources
    _package(tmp_path / "elsewhere" / "unrelated", "unrelated")
    with pytest.raises(PackageNotFoundError, match=f"the input's package folder {checkout}"):
        find_package("unrelated", start=entry)


def test_never_the_temp_root_or_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A package directly in $HOME (or the temp folder): its parent is not crawled.
    home = tmp_path / "home"
    monkeypatch.setenv("HOME", str(home))
    pkg = _package(home / "my_pkg", "my_pkg")
    _package(home / "projects" / "other_pkg", "other_pkg")
    entry = _entry(pkg / "urdf")
    assert find_package("my_pkg", start=entry) == pkg
    with pytest.raises(PackageNotFoundError):
        find_package("other_pkg", start=entry)
    (home / ".git").mkdir()  # a dotfiles repository in $HOME does not make $HOME the bound
    with pytest.raises(PackageNotFoundError):
        find_package("other_pkg", start=entry)


def test_verbose_says_which_copy_was_used(tmp_path: Path) -> None:
    repo = tmp_path / "repo"
    (repo / ".git").mkdir(parents=True)
    pkg = _package(repo / "desc", "desc")
    (pkg / "meshes").mkdir()
    (pkg / "meshes" / "m.stl").write_text("solid m\nendsolid m\n")
    xacro_doc = pkg / "urdf" / "r.urdf.xacro"
    xacro_doc.parent.mkdir()
    xacro_doc.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r"><link name="a"><visual>'
                         '<geometry><mesh filename="package://desc/meshes/m.stl"/></geometry></visual></link>'
                         '<link name="$(find desc)"/><joint name="j" type="fixed"><parent link="a"/>'
                         '<child link="$(find desc)"/></joint></robot>')
    line = f"package 'desc': {pkg} (the input's repository {repo})"
    for command in (["xacro"], ["check-urdf"]):
        result = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *command, str(xacro_doc),
                                 "--verbose"], capture_output=True, text=True, cwd=tmp_path, check=False)
        assert result.returncode == 0, result.stderr
        assert result.stderr.splitlines().count(line) == 1, result.stderr
        quiet = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", *command, str(xacro_doc)],
                               capture_output=True, text=True, cwd=tmp_path, check=False)
        assert line not in quiet.stderr


def test_installed_environment_is_not_searched(tmp_path: Path) -> None:
    # A virtualenv inside a git checkout (as pyenv is): the checkout does not bound an installed file.
    (tmp_path / "tool" / ".git").mkdir(parents=True)
    site = tmp_path / "tool" / "lib" / "python3.11" / "site-packages"
    _package(tmp_path / "tool" / "stray_pkg", "stray_pkg")
    installed = _package(site / "robots_pkg", "robots_pkg")
    entry = _entry(installed / "urdf")
    assert find_package("robots_pkg", start=entry) == installed
    with pytest.raises(PackageNotFoundError):
        find_package("stray_pkg", start=entry)


def test_the_install_prefix_the_input_lies_in(tmp_path: Path) -> None:
    # As example-robot-data installs: <prefix>/share/<dir>, named in the prefix's ament index.
    prefix = tmp_path / "prefix"
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "robot-data").write_text("")
    (prefix / "share" / "robot-data").mkdir()
    entry = _entry(_package(prefix / "share" / "robot-data", "robot_data_descriptions") / "robots" / "r")
    assert find_package("robot-data", start=entry) == prefix / "share" / "robot-data"


def test_a_file_directly_in_the_temp_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import tempfile

    fake_tmp = tmp_path / "tmp"
    monkeypatch.setattr(tempfile, "tempdir", str(fake_tmp))
    _package(fake_tmp / "x" / "y" / "copy_pkg", "copy_pkg")
    loose = _entry(fake_tmp)
    with pytest.raises(PackageNotFoundError, match="nothing beside the input"):
        find_package("copy_pkg", start=loose)
    mine = _package(fake_tmp / "mine", "mine")
    assert find_package("mine", start=_entry(mine / "urdf")) == mine
    with pytest.raises(PackageNotFoundError, match=f"the input's package folder {mine}"):
        find_package("copy_pkg", start=mine / "urdf" / "robot.urdf")
