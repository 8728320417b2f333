"""robotmodel diff's command line: exit codes as diff (0 equal, 1 different, 2 error, one line), identical
descriptions in any form, xacro arguments for both sides, stdin, and the output's layout."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from conftest import BUNDLED, erd_urdfs
from diff.pairs import PANDA, UR5, UR5_LIMITED, edited, element, expanded, links_below, run, run_process, write

XACRO = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
         '<xacro:arg name="p" default="a_"/><xacro:arg name="z" default="3"/>'
         '<link name="$(arg p)base"/><link name="$(arg p)arm"/>'
         '<joint name="j" type="prismatic"><parent link="$(arg p)base"/><child link="$(arg p)arm"/>'
         '<origin xyz="1 2 $(arg z)"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
         "</joint></robot>")


@pytest.mark.parametrize("name", ["arm.urdf.xacro", "diffbot.urdf.xacro", "skid_steer.urdf.xacro"])
def test_identical_descriptions_exit_0_and_print_nothing(tmp_path: Path, name: str) -> None:
    """The same file twice, and the xacro against upstream xacro's expansion of it."""
    urdf = write(tmp_path, "expanded.urdf", expanded(name))
    for old, new in ((BUNDLED / name, BUNDLED / name), (BUNDLED / name, urdf)):
        done = run_process(str(old), str(new), cwd=tmp_path)
        assert (done.returncode, done.stdout, done.stderr) == (0, "", "")
    done = run(str(BUNDLED / name), str(urdf), "--format", "json", cwd=tmp_path)
    assert done.returncode == 0
    report = json.loads(done.stdout)
    assert report["equal"] is True and report["poses"] == []


@pytest.mark.parametrize("path", erd_urdfs()[::7], ids=lambda p: p.name)
def test_every_sampled_robot_equals_itself(tmp_path: Path, path: Path) -> None:
    done = run(str(path), str(path), cwd=tmp_path)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")


def test_xacro_arguments_apply_to_both_sides(tmp_path: Path) -> None:
    write(tmp_path, "r.urdf.xacro", XACRO)
    shutil.copy(tmp_path / "r.urdf.xacro", tmp_path / "s.urdf.xacro")
    assert run("p:=b_", "r.urdf.xacro", "s.urdf.xacro", "z:=5", cwd=tmp_path).returncode == 0
    # Against a URDF written with the argument's values: equal only with the same arguments.
    urdf = XACRO.replace("$(arg p)", "b_").replace("$(arg z)", "5").replace(
        '<xacro:arg name="p" default="a_"/><xacro:arg name="z" default="3"/>', "")
    write(tmp_path, "b.urdf", urdf.replace(' xmlns:xacro="http://www.ros.org/wiki/xacro"', ""))
    assert run("r.urdf.xacro", "b.urdf", "p:=b_", "z:=5", cwd=tmp_path).returncode == 0
    done = run("r.urdf.xacro", "b.urdf", "p:=b_", "--format", "json", cwd=tmp_path)
    assert done.returncode == 1
    moved = json.loads(done.stdout)["joints"]["changed"][0]["changes"]
    assert moved == [{"field": "origin.xyz", "old": [1000.0, 2000.0, 3000.0], "new": [1000.0, 2000.0, 5000.0],
                      "unit": "mm", "delta": 2000.0, "delta_unit": "mm"}]


def test_stdin_as_either_side(tmp_path: Path) -> None:
    text = PANDA.read_text()
    assert run_process("-", str(PANDA), cwd=tmp_path, stdin=text).returncode == 0
    done = run_process(str(UR5), "-", cwd=tmp_path, stdin=UR5_LIMITED.read_text())
    assert done.returncode == 1 and done.stdout.splitlines()[1].startswith("+++ - (robot 'ur5'")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["only.urdf"], "two files to compare"),
        (["a.urdf", "b.urdf", "--git", "HEAD"], "--git REV compares one FILE"),
        (["-", "-"], "only one of OLD and NEW"),
        (["a.urdf", "a.urdf", "--tolerance", "-1"], "--tolerance must be a finite number >= 0"),
        (["a.urdf", "missing.urdf"], "missing.urdf: no such file"),
        (["a.urdf", "bad.urdf"], "bad.urdf"),
        (["a.urdf", "cycle.urdf"], "cycle.urdf"),
    ],
    ids=["one-file", "git-and-two-files", "two-stdins", "negative-tolerance", "missing", "not-xml", "invalid-robot"],
)
def test_errors_exit_2_with_one_line(tmp_path: Path, args: list[str], message: str) -> None:
    shutil.copy(PANDA, tmp_path / "a.urdf")
    write(tmp_path, "bad.urdf", "<robot name='x'><link name='a'>")
    write(tmp_path, "cycle.urdf", "<robot name='c'><link name='a'/><link name='b'/>"
          "<joint name='j1' type='fixed'><parent link='a'/><child link='b'/></joint>"
          "<joint name='j2' type='fixed'><parent link='b'/><child link='a'/></joint></robot>")
    done = run_process(*args, cwd=tmp_path)
    assert done.returncode == 2 and done.stdout == ""
    assert len(done.stderr.splitlines()) == 1, done.stderr
    assert done.stderr.startswith("robotmodel diff: error: ") and message in done.stderr


def test_unknown_option_is_a_usage_error(tmp_path: Path) -> None:
    done = run(str(PANDA), str(PANDA), "--no-such-option", cwd=tmp_path)
    assert done.returncode == 2 and "usage: robotmodel diff" in done.stderr


def test_text_layout_groups_sections_with_markers(tmp_path: Path) -> None:
    """A renamed joint, two changed joints, a changed material, and the poses they move."""
    old = expanded("arm.urdf.xacro")

    def change(root):
        element(root, "joint", "arm_wrist_yaw_joint").set("name", "arm_yaw_joint")
        element(root, "joint", "arm_shoulder_joint").find("axis").set("xyz", "1 0 0")
        element(root, "material", "blue").find("color").set("rgba", "0 0 1 1")
        element(root, "joint", "arm_base_joint").find("origin").set("rpy", "0 0 0.5")

    new = edited(old, change)
    done = run(str(write(tmp_path, "old.urdf", old)), str(write(tmp_path, "new.urdf", new)), cwd=tmp_path)
    assert done.returncode == 1
    lines = done.stdout.splitlines()
    assert lines[0] == f"--- {tmp_path / 'old.urdf'} (robot 'arm', root 'world')"
    assert lines[1] == f"+++ {tmp_path / 'new.urdf'} (robot 'arm', root 'world')"
    headers = [line for line in lines if not line.startswith(" ")]
    turned = len(links_below(old, "arm_base_joint"))  # the shoulder's new axis does not show at q = 0
    assert headers[2:] == ["joints: 1 renamed, 2 changed", "materials: 1 changed",
                           f"link poses at the zero configuration (T_root_link, largest change first): {turned} changed"]
    joints = lines[lines.index("joints: 1 renamed, 2 changed") + 1:lines.index("materials: 1 changed")]
    assert joints == [
        "  ~ joint arm_wrist_yaw_joint → arm_yaw_joint (renamed)",
        "  ~ joint arm_base_joint",
        "      origin.rpy: [0, 0, 0] → [0, 0, 28.64788976] deg (turned 28.64788976 deg)",
        "  ~ joint arm_shoulder_joint",
        "      axis: [0, 1, 0] → [1, 0, 0]",
    ]
    assert lines[lines.index("materials: 1 changed") + 1:][:2] == [
        "  ~ material blue", "      color: [0.15, 0.3, 0.8, 1] → [0, 0, 1, 1] rgba"]


def test_help_names_the_exit_codes(tmp_path: Path) -> None:
    done = run("--help", cwd=tmp_path)
    assert done.returncode == 0
    assert "Exit 0 when equal, 1 when different, 2 on error" in " ".join(done.stdout.split())


def test_docs_example_is_what_the_command_prints(tmp_path: Path) -> None:
    """docs/commands/diff.md's example: the elbow raised 25 mm and its upper limit lowered to 2 rad in the bundled arm."""
    page = (BUNDLED.parent / "docs" / "commands" / "diff.md").read_text(encoding="utf-8")
    block = page.split("$ robotmodel diff old/arm.urdf.xacro new/arm.urdf.xacro\n", 1)[1].split("  ...\n", 1)[0]
    for side in ("old", "new"):
        (tmp_path / side).mkdir()
        shutil.copy(BUNDLED / "inertia_macros.xacro", tmp_path / side)
    text = (BUNDLED / "arm.urdf.xacro").read_text()
    (tmp_path / "old" / "arm.urdf.xacro").write_text(text)
    for old, new in (('z="${upper_length}"', 'z="${upper_length + 0.025}"'),
                     ('lower="${-2.5}" upper="${2.5}"', 'lower="${-2.5}" upper="${2.0}"')):
        assert text.count(old) == 1
        text = text.replace(old, new)
    (tmp_path / "new" / "arm.urdf.xacro").write_text(text)
    done = run("old/arm.urdf.xacro", "new/arm.urdf.xacro", cwd=tmp_path)
    assert done.returncode == 1
    assert done.stdout.startswith(block)
