"""``check-urdf --format github``: workflow commands parsed back into (level, file, line, message).

Expected lines are found by the tests in the text they wrote; expected findings are those the
text format prints for the same file, one run per file.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from check_ci.cihelpers import Annotation, parse_github
from conftest import BUNDLED, ERD_ROBOTS, erd_urdfs
from robotmodel.cli.main import main

# A robot whose defects are known: line numbers are found below by searching this text.
ROBOT = """<?xml version="1.0"?>
<robot name="odd">
  <link name="base"/>
  <link name="l,1:%x">
    <visual><geometry><mesh filename="missing, really: 100%.stl"/></geometry></visual>
  </link>
  <link name="tip">
    <inertial><mass value="-1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
  </link>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="l,1:%x"/><axis xyz="0 0 1"/>
    <limit lower="1" upper="-1" effort="0" velocity="1"/>
  </joint>
  <joint name="j2" type="fixed"><parent link="base"/><child link="tip"/></joint>
</robot>
"""


def _line_of(text: str, needle: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


def _text_findings(path: str, capsys: pytest.CaptureFixture[str]) -> tuple[int, list[tuple[str, str, str]]]:
    """(exit code, [(level, code, 'element: message')]) from the text format of one file."""
    code = main(["check-urdf", path])
    err = capsys.readouterr().err
    found = []
    for line in err.splitlines():
        match = re.match(r"robotmodel check-urdf: (error|warning): \[([\w-]+)\] (.*)$", line)
        if match:
            found.append((match.group(1), match.group(2), match.group(3)))
        else:
            found.append(("error", "", line.removeprefix("robotmodel check-urdf: error: ")))
    return code, found


def test_escaped_paths_and_names_come_back_whole(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "we,ird:dir"
    folder.mkdir()
    (folder / "r%1.urdf").write_text(ROBOT)
    monkeypatch.chdir(tmp_path)
    name = "we,ird:dir/r%1.urdf"
    code, text_view = _text_findings(name, capsys)
    assert main(["check-urdf", "--format", "github", name]) == code == 0
    out, err = capsys.readouterr()
    got = parse_github(out)
    mesh_line = _line_of(ROBOT, 'filename="missing')
    expected = [
        Annotation("warning", name, _line_of(ROBOT, '<joint name="j1"'), "limit-lower-above-upper",
                   "joint [j1]: lower limit 1 is above upper limit -1"),
        Annotation("warning", name, _line_of(ROBOT, '<joint name="j1"'), "limit-zero-effort",
                   "joint [j1]: effort limit is 0; the joint cannot be driven"),
        Annotation("warning", name, _line_of(ROBOT, '<link name="tip"'), "mass-not-positive", "link [tip]: mass is -1"),
        Annotation("warning", name, _line_of(ROBOT, '<link name="l,1:%x"'), "moving-link-without-inertial",
                   "link [l,1:%x]: moves with joint [j1] but neither it nor anything fixed to it has an <inertial>"),
    ]
    assert [a for a in got if a.title != "mesh-not-found"] == expected
    mesh = [a for a in got if a.title == "mesh-not-found"]
    assert len(mesh) == 1 and mesh[0][:3] == ("warning", name, mesh_line)
    assert mesh[0].message.startswith("link [l,1:%x]: mesh 'missing, really: 100%.stl' resolves to ")
    # The same findings, in the same order, as the text format gives for this file.
    assert [(a.level, a.title, a.message) for a in got] == text_view
    assert err == "robotmodel check-urdf: 1 file checked: 1 passed, 0 failed (0 errors, 5 warnings)\n"


def test_raw_command_escapes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                             capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "a,b:c.urdf").write_text(ROBOT.replace('effort="0"', 'effort="1"').replace("-1", "1"))
    monkeypatch.chdir(tmp_path)
    assert main(["check-urdf", "--format", "github", "a,b:c.urdf"]) == 0
    lines = capsys.readouterr().out.splitlines()
    # Properties escape , and : (and %); the message keeps them, escaping only %.
    assert lines[0].startswith("::warning file=a%2Cb%3Ac.urdf,line=")
    assert any("::link [l,1:%25x]: moves with joint [j1]" in line for line in lines)


def test_xacro_findings_point_at_the_xacro_sources(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    parts = tmp_path / "parts.xacro"
    parts.write_text("""<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="segment" params="name mass">
    <link name="${name}">
      <inertial><mass value="${mass}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    </link>
  </xacro:macro>
  <xacro:macro name="wrist" params="prefix">
    <link name="${prefix}wrist_link"/>
    <joint name="${prefix}wrist_joint" type="revolute">
      <parent link="${prefix}fore"/><child link="${prefix}wrist_link"/><axis xyz="1 0 0"/>
      <limit lower="-1" upper="1" effort="1" velocity="0"/>
    </joint>
  </xacro:macro>
  <link name="tool"/>
</robot>
""")
    entry = tmp_path / "robot.urdf.xacro"
    entry.write_text("""<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="parts.xacro"/>
  <xacro:arg name="prefix" default="a_"/>
  <link name="base"/>
  <xacro:segment name="fore" mass="0"/>
  <joint name="elbow" type="continuous"><parent link="base"/><child link="$(arg prefix)fore"/></joint>
  <xacro:wrist prefix="$(arg prefix)"/>
  <joint name="tool_joint" type="fixed"><parent link="a_wrist_link"/><child link="tool"/></joint>
</robot>
""".replace('name="fore"', 'name="a_fore"'))
    monkeypatch.chdir(tmp_path)
    assert main(["check-urdf", "--format", "github", "robot.urdf.xacro"]) == 0
    got = parse_github(capsys.readouterr().out)
    etext, ptext = entry.read_text(), parts.read_text()
    assert sorted(got) == sorted([
        # Made by a macro call given its name: the call's line in the entry file.
        Annotation("warning", "robot.urdf.xacro", _line_of(etext, '<xacro:segment name="a_fore"'),
                   "mass-not-positive", "link [a_fore]: mass is 0 on a body moved by joint [elbow]"),
        # Made from a name template in the included file: the template's line there.
        Annotation("warning", "parts.xacro", _line_of(ptext, '<joint name="${prefix}wrist_joint"'),
                   "limit-zero-velocity", "joint [a_wrist_joint]: velocity limit is 0; the joint cannot move"),
        Annotation("warning", "parts.xacro", _line_of(ptext, '<link name="${prefix}wrist_link"'),
                   "moving-link-without-inertial",
                   "link [a_wrist_link]: moves with joint [a_wrist_joint] but neither it nor anything fixed to it "
                   "has an <inertial>"),
    ])
    # A load error inside an included file is placed in that file.
    parts.write_text(ptext.replace("<link name=\"tool\"/>", "<link name=\"tool\"/>\n  <xacro:undefined_macro/>"))
    assert main(["check-urdf", "--format", "github", "robot.urdf.xacro"]) == 1
    (error,) = parse_github(capsys.readouterr().out)
    assert (error.level, error.file, error.title) == ("error", "parts.xacro", "xacro-error")
    assert "undefined_macro" in error.message
    # A URDF error after expansion is placed at the element it names.
    parts.write_text(ptext)
    entry.write_text(etext.replace('<child link="tool"/>', '<child link="nowhere"/>'))
    assert main(["check-urdf", "--format", "github", "robot.urdf.xacro"]) == 1
    (error,) = parse_github(capsys.readouterr().out)
    assert (error.level, error.file, error.line, error.title) == (
        "error", "robot.urdf.xacro", _line_of(etext, '<joint name="tool_joint"'), "urdf-invalid")


def test_bundled_robots_are_clean_and_a_broken_one_is_placed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                             capsys: pytest.CaptureFixture[str]) -> None:
    files = sorted(str(p) for p in BUNDLED.glob("*.urdf.xacro"))
    assert main(["check-urdf", "--format", "github", *files]) == 0
    out, err = capsys.readouterr()
    assert out == ""
    assert err == f"robotmodel check-urdf: {len(files)} files checked: {len(files)} passed, 0 failed (0 errors, 0 warnings)\n"
    # The arm with one segment made massless: the finding lands on that macro call.
    work = tmp_path / "urdf"
    work.mkdir()
    for path in BUNDLED.glob("*.xacro"):
        (work / path.name).write_text(path.read_text())
    arm = (work / "arm.urdf.xacro").read_text()
    call = '<xacro:segment name="arm_upper_link" length="${upper_length}" mass="1.5"'
    assert call in arm
    (work / "arm.urdf.xacro").write_text(arm.replace(call, call.replace('mass="1.5"', 'mass="-1.5"')))
    monkeypatch.chdir(tmp_path)
    assert main(["check-urdf", "--format", "github", "urdf/arm.urdf.xacro"]) == 0
    (got,) = parse_github(capsys.readouterr().out)
    assert got == Annotation("warning", "urdf/arm.urdf.xacro", _line_of(arm, call), "mass-not-positive",
                             "link [arm_upper_link]: mass is -1.5")


def test_example_robot_data_annotations(capsys: pytest.CaptureFixture[str]) -> None:
    """All of example-robot-data in one run: per file, the text format's findings; each line holds its element."""
    files = [str(p) for p in erd_urdfs()]
    assert len(files) >= 60
    code = main(["check-urdf", "--format", "github", *files])
    got = parse_github(capsys.readouterr().out)
    by_file: dict[str, list[Annotation]] = {}
    for a in got:
        by_file.setdefault(a.file, []).append(a)
    codes = []
    for path in files:
        single, text_view = _text_findings(path, capsys)
        codes.append(single)
        mine = by_file.pop(path, [])
        # A load error's text line carries no code: compare its level and message only.
        assert len(mine) == len(text_view), path
        assert [(a.level, a.title if c else "", a.message) for a, (_, c, _) in zip(mine, text_view, strict=True)] == text_view
        lines = Path(path).read_text().splitlines()
        for a in mine:
            if a.title == "urdf-malformed":
                continue  # ur3.urdf has no robot name: the whole file is at fault
            assert a.line is not None, a
            written = lines[a.line - 1]
            # A start tag may span lines: its text from the reported line to its '>'.
            tag_text = "\n".join(lines[a.line - 1:a.line + 10]).split(">", 1)[0]
            if a.title == "mesh-not-found":
                uri = a.message.split("mesh '", 1)[1].split("'", 1)[0]
                assert f'"{uri}"' in written or f"'{uri}'" in written, (a, written)
            else:
                tag, name = re.match(r"(link|joint) \[([^\]]+)\]", a.message).groups()
                assert re.match(rf"\s*<{tag}\s[^>]*?name\s*=\s*[\"']{re.escape(name)}[\"']", tag_text), (a, tag_text)
    assert by_file == {}
    assert code == max(codes) == 1  # files with mimics of missing joints, a robot without a name
    assert ERD_ROBOTS.is_dir()


def test_a_transmission_joint_is_not_the_joint(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    """A <transmission> written first names the joint too (without a type): the annotation is on the joint."""
    text = """<robot name="r">
  <transmission name="t"><type>transmission_interface/SimpleTransmission</type>
    <joint name="j"><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
  </transmission>
  <link name="a"/>
  <link name="b"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint
      name="j" type="revolute"><parent link="a"/><child link="b"/><limit effort="0" velocity="1"/></joint>
</robot>
"""
    (tmp_path / "r.urdf").write_text(text)
    monkeypatch.chdir(tmp_path)
    assert main(["check-urdf", "--format", "github", "r.urdf"]) == 0
    (got,) = parse_github(capsys.readouterr().out)
    joint_line = next(i for i, line in enumerate(text.splitlines(), 1) if line.strip() == "<joint")
    assert (got.title, got.line) == ("limit-zero-effort", joint_line)
