"""robotmodel diff --git REV FILE in a temporary git repository: the file (and, for xacro, every file it
includes, from this package or another) as it was at REV, against the working copy."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from conftest import BUNDLED
from diff.pairs import PANDA, changes, edited, element, only, run, run_json

PACKAGE_XML = '<?xml version="1.0"?>\n<package format="3"><name>{name}</name><version>0.0.0</version>' \
              '<description>d</description><maintainer email="a@b.c">m</maintainer><license>BSD</license></package>\n'


def _git(repo: Path, *args: str) -> str:
    done = subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@example.com", *args], cwd=repo,
                          capture_output=True, text=True, check=True)
    return done.stdout


def _commit(repo: Path, message: str) -> None:
    _git(repo, "add", "-A")
    _git(repo, "commit", "-q", "-m", message)


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    """A robot repository: arm_description (the bundled arm) including macros from a second package."""
    root = tmp_path / "robots"
    arm = root / "arm_description"
    common = root / "robot_common"
    (arm / "urdf").mkdir(parents=True)
    (common / "urdf").mkdir(parents=True)
    (arm / "package.xml").write_text(PACKAGE_XML.format(name="arm_description"))
    (common / "package.xml").write_text(PACKAGE_XML.format(name="robot_common"))
    text = (BUNDLED / "arm.urdf.xacro").read_text()
    include = '<xacro:include filename="inertia_macros.xacro"/>'
    assert include in text
    (arm / "urdf" / "arm.urdf.xacro").write_text(
        text.replace(include, '<xacro:include filename="$(find robot_common)/urdf/inertia_macros.xacro"/>'))
    shutil.copy(BUNDLED / "inertia_macros.xacro", common / "urdf" / "inertia_macros.xacro")
    shutil.copy(PANDA, arm / "urdf" / "panda.urdf")
    _git(root, "init", "-q")
    _commit(root, "first")
    return root


def test_unchanged_working_copy_is_equal(repo: Path) -> None:
    done = run("--git", "HEAD", "arm_description/urdf/arm.urdf.xacro", cwd=repo)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")


def test_included_file_comes_from_the_revision(repo: Path) -> None:
    """Only the included macros changed (in another package): the revision's copy must be the one expanded."""
    macros = repo / "robot_common" / "urdf" / "inertia_macros.xacro"
    text = macros.read_text()
    assert text.count("izz=\"${mass / 2.0 * radius*radius}\"") == 1
    macros.write_text(text.replace("izz=\"${mass / 2.0 * radius*radius}\"", "izz=\"${mass * radius*radius}\""))
    code, report = run_json("--git", "HEAD", "arm_description/urdf/arm.urdf.xacro", cwd=repo)
    assert code == 1
    assert report["old"]["source"] == "HEAD:arm_description/urdf/arm.urdf.xacro"
    only(report, "links")
    # Every link built with cylinder_inertial (the seven segments), izz doubled: m r² instead of m r² / 2.
    segments = {"arm_base_link": 2.0, "arm_turret_link": 1.0, "arm_upper_link": 1.5, "arm_fore_link": 1.0,
                "arm_wrist_pitch_link": 0.3, "arm_wrist_roll_link": 0.3, "arm_wrist_yaw_link": 0.3}
    got = changes(report, "links")
    assert set(got) == set(segments)
    for link, mass in segments.items():
        assert list(got[link]) == ["inertial.inertia.izz"]
        izz = got[link]["inertial.inertia.izz"]
        assert (izz["old"], izz["new"]) == (pytest.approx(mass * 0.04**2 / 2), pytest.approx(mass * 0.04**2))


def test_older_revision_and_the_joint_it_moved(repo: Path) -> None:
    arm = repo / "arm_description" / "urdf" / "arm.urdf.xacro"
    arm.write_text(arm.read_text().replace('z="${upper_length}"', 'z="${upper_length + 0.025}"'))
    _commit(repo, "move the elbow up 25 mm")
    # In a subfolder, with the path relative to it, as a user in the package would type it.
    code, report = run_json("--git", "HEAD~1", "arm.urdf.xacro", cwd=arm.parent)
    assert code == 1
    only(report, "joints", "poses")
    moved = changes(report, "joints")["arm_elbow_joint"]["origin.xyz"]
    assert (moved["old"], moved["new"], moved["delta"]) == ([0.0, 0.0, 400.0], [0.0, 0.0, 425.0], 25.0)
    assert len(report["poses"]) == 7 and all(p["translation_mm"] == 25.0 for p in report["poses"])
    assert run("--git", "HEAD", "arm.urdf.xacro", cwd=arm.parent).returncode == 0


def test_plain_urdf_at_a_revision(repo: Path) -> None:
    panda = repo / "arm_description" / "urdf" / "panda.urdf"
    panda.write_text(edited(panda.read_text(), lambda r: element(r, "joint", "panda_joint2").find("limit").set(
        "effort", "90")))
    code, report = run_json("--git", "HEAD", str(panda), cwd=repo)
    assert code == 1
    only(report, "joints")
    effort = changes(report, "joints")["panda_joint2"]["limit.effort"]
    assert (effort["old"], effort["new"]) == (87.0, 90.0)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--git", "no-such-rev", "arm_description/urdf/arm.urdf.xacro"], "unknown revision 'no-such-rev'"),
        (["--git", "HEAD", "arm_description/urdf/new.urdf"], "no such file at revision 'HEAD'"),
        (["--git", "HEAD", "arm_description"], "not a file at revision 'HEAD'"),
    ],
    ids=["unknown-revision", "absent-at-revision", "a-folder"],
)
def test_git_errors_are_one_line_and_exit_2(repo: Path, args: list[str], message: str) -> None:
    (repo / "arm_description" / "urdf" / "new.urdf").write_text((repo / "arm_description/urdf/panda.urdf").read_text())
    done = run(*args, cwd=repo)
    assert done.returncode == 2 and done.stdout == ""
    assert len(done.stderr.splitlines()) == 1 and done.stderr.startswith("robotmodel diff: error: ")
    assert message in done.stderr


def test_file_outside_a_repository(tmp_path: Path) -> None:
    shutil.copy(PANDA, tmp_path / "panda.urdf")
    done = run("--git", "HEAD", "panda.urdf", cwd=tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1
    assert "panda.urdf" in done.stderr and "not a git repository" in done.stderr


def test_broken_xacro_at_the_revision_names_it_by_revision(repo: Path) -> None:
    arm = repo / "arm_description" / "urdf" / "arm.urdf.xacro"
    good = arm.read_text()
    arm.write_text(good.replace('<xacro:segment name="arm_fore_link"', '<xacro:no_such_macro name="arm_fore_link"'))
    _commit(repo, "broken")
    arm.write_text(good)
    done = run("--git", "HEAD", str(arm), cwd=repo)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    assert "robotmodel-diff-" not in done.stderr
    assert "HEAD:arm_description/urdf/arm.urdf.xacro" in done.stderr and "no_such_macro" in done.stderr


def test_links_out_of_the_repository_are_skipped_not_fatal(repo: Path) -> None:
    """A symlink to an absolute path (e.g. into /opt/ros) is left out of the export; the rest still resolves."""
    (repo / "arm_description" / "urdf" / "ros").symlink_to("/opt/ros/humble/share")
    (repo / "arm_description" / "escape").symlink_to("../../..")
    _commit(repo, "links")
    done = run("--git", "HEAD", "arm_description/urdf/arm.urdf.xacro", cwd=repo)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")


def test_repository_reached_through_a_symlinked_folder(repo: Path, tmp_path: Path) -> None:
    alias = tmp_path / "alias"
    alias.symlink_to(repo)
    arm = alias / "arm_description" / "urdf" / "arm.urdf.xacro"
    arm.write_text(arm.read_text().replace('upper="${2.5}"', 'upper="${2.0}"'))
    code, report = run_json("--git", "HEAD", str(arm), cwd=tmp_path)
    assert code == 1 and report["old"]["source"] == "HEAD:arm_description/urdf/arm.urdf.xacro"
    assert list(changes(report, "joints")) == ["arm_elbow_joint"]
