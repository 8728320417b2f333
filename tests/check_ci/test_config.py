"""The project config (robotmodel.toml / [tool.robotmodel]) and macro-only xacro files."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from conftest import BUNDLED
from robotmodel.cli.main import main

from robotmodel.check import find_config, is_macro_only, read_config
from robotmodel.errors import ConfigError

PREFIX = "robotmodel check-urdf: "
ARM_ARGS = """<robot name="twin" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="inertia_macros.xacro"/>
  <xacro:arg name="side" default="left"/>
  <xacro:property name="side" value="$(arg side)"/>
  <link name="${side}_base">
    <xacro:box_inertial mass="1" x="0.1" y="0.1" z="0.1"><origin xyz="0 0 0"/></xacro:box_inertial>
  </link>
</robot>
"""


@pytest.fixture
def repo(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A robot repository: the bundled xacro files under urdf/, and a twin robot taking an arg."""
    shutil.copytree(BUNDLED, tmp_path / "urdf", ignore=shutil.ignore_patterns("*.py", "__pycache__"))
    (tmp_path / "urdf" / "twin.urdf.xacro").write_text(ARM_ARGS)
    (tmp_path / ".git").mkdir()
    monkeypatch.chdir(tmp_path)
    return tmp_path


def _singles(capsys: pytest.CaptureFixture[str], *runs: list[str]) -> str:
    out = ""
    for words in runs:
        assert main(["check-urdf", "--no-config", *words]) == 0
        out += capsys.readouterr().out
    return out


def test_macro_only_files() -> None:
    assert is_macro_only(BUNDLED / "inertia_macros.xacro")
    assert not any(is_macro_only(p) for p in BUNDLED.glob("*.urdf.xacro"))


def test_macro_only_corpus_files(corpus: Path) -> None:
    franka = corpus / "franka_description" / "franka_description"
    assert is_macro_only(franka / "robots/common/franka_arm.xacro")
    assert is_macro_only(franka / "robots/common/utils.xacro")
    assert not is_macro_only(franka / "robots/fr3/fr3.urdf.xacro")
    ur = corpus / "Universal_Robots_ROS2_Description" / "ur_description" / "urdf"
    assert is_macro_only(ur / "ur_macro.xacro") and not is_macro_only(ur / "ur.urdf.xacro")


def test_fragment_checked_through_its_entries_with_their_args(repo: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (repo / "pyproject.toml").write_text("""[project]
name = "my_robot"

[tool.robotmodel]
[[tool.robotmodel.entry]]
file = "urdf/twin.urdf.xacro"
args = { side = "right" }

[[tool.robotmodel.entry]]
file = "urdf/twin.urdf.xacro"

[[tool.robotmodel.entry]]
file = "urdf/arm.urdf.xacro"
""")
    config = find_config()
    assert config is not None and config.path == repo / "pyproject.toml"
    assert [(e.file.name, e.args) for e in config.entries] == [
        ("twin.urdf.xacro", (("side", "right"),)), ("twin.urdf.xacro", ()), ("arm.urdf.xacro", ())]
    # Only the macro file changed (as pre-commit passes it): every entry including it is checked.
    assert main(["check-urdf", "urdf/inertia_macros.xacro"]) == 0
    out, err = capsys.readouterr()
    assert out == _singles(capsys, ["urdf/twin.urdf.xacro", "side:=right"], ["urdf/twin.urdf.xacro"],
                           ["urdf/arm.urdf.xacro"])
    assert err == f"{PREFIX}3 files checked: 3 passed, 0 failed (0 errors, 0 warnings)\n"
    # An entry point named on the line takes its configured args; the command line's win.
    assert main(["check-urdf", "urdf/twin.urdf.xacro", "urdf/inertia_macros.xacro", "side:=up"]) == 0
    out, _ = capsys.readouterr()
    # Both twin entries become side:=up, the same check: it runs once.
    assert out.count("root Link: up_base") == 1 and "left_base" not in out and "world" in out
    # Without FILE: every entry.
    assert main(["check-urdf"]) == 0
    assert capsys.readouterr().out.count("robot name is:") == 3


def test_defect_in_a_fragment_fails_through_its_entry(repo: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A macro renamed in the fragment breaks the entry using it: the run fails, placed at the broken call."""
    from check_ci.cihelpers import Annotation, parse_github

    (repo / "robotmodel.toml").write_text('[[entry]]\nfile = "urdf/arm.urdf.xacro"\n')
    macros = repo / "urdf" / "inertia_macros.xacro"
    text = macros.read_text()
    broken = text.replace('<xacro:macro name="cylinder_inertial"', '<xacro:macro name="tube_inertial"', 1)
    assert broken != text
    macros.write_text(broken)
    assert main(["check-urdf", "--format", "github", "urdf/inertia_macros.xacro"]) == 1
    out, err = capsys.readouterr()
    arm = (repo / "urdf" / "arm.urdf.xacro").read_text().splitlines()
    call = next(i for i, line in enumerate(arm, 1) if "<xacro:cylinder_inertial" in line)
    assert parse_github(out) == [Annotation(
        "error", "urdf/arm.urdf.xacro", call, "xacro-error",
        "urdf/arm.urdf.xacro: unknown macro name: xacro:cylinder_inertial (in macro segment; in file "
        "urdf/arm.urdf.xacro)")]
    assert err == f"{PREFIX}1 file checked: 0 passed, 1 failed (1 error, 0 warnings)\n"
    macros.write_text(text)
    assert main(["check-urdf", "--format", "github", "urdf/inertia_macros.xacro"]) == 0
    assert capsys.readouterr() == ("", f"{PREFIX}1 file checked: 1 passed, 0 failed (0 errors, 0 warnings)\n")


def test_orphan_fragments_are_reported_not_failed(repo: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (repo / "robotmodel.toml").write_text('[[entry]]\nfile = "urdf/twin.urdf.xacro"\n')
    orphan = repo / "urdf" / "unused_macros.xacro"
    orphan.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="m"/></robot>')
    assert main(["check-urdf", "urdf/unused_macros.xacro"]) == 0
    out, err = capsys.readouterr()
    assert out == ""
    assert err.splitlines() == [
        f"{PREFIX}warning: [fragment-not-checked] urdf/unused_macros.xacro: macro-only xacro file included by no "
        "configured entry point; not checked on its own",
        f"{PREFIX}0 files checked: 0 passed, 0 failed (0 errors, 1 warning); 1 macro-only file not checked "
        "(no configured entry includes it)"]
    assert main(["check-urdf", "--strict", "urdf/unused_macros.xacro"]) == 1
    capsys.readouterr()
    # Without a config a macro-only file is never checked on its own either.
    assert main(["check-urdf", "--no-config", "urdf/inertia_macros.xacro"]) == 0
    assert "fragment-not-checked" in capsys.readouterr().err


@pytest.mark.parametrize(("text", "message"), [
    ("[[entry]]\nargs = {}\n", "entry[0]: needs file ="),
    ('[[entry]]\nfile = "a.xacro"\nargz = {}\n', "entry[0]: unknown key 'argz'"),
    ('[[entry]]\nfile = "a.xacro"\nargs = { x = [1] }\n', "entry[0].args.x: xacro arg values must be"),
    ("entry = 3\n", "entry must be an array of tables"),
    ("package-path = 3\n", "package-path must be a list"),
    ("[entry\n", "not valid TOML"),
    ("colour = 1\n", "unknown key 'colour'"),
])
def test_bad_config_is_one_line(repo: Path, capsys: pytest.CaptureFixture[str], text: str, message: str) -> None:
    (repo / "robotmodel.toml").write_text(text)
    with pytest.raises(ConfigError, match=r"robotmodel\.toml"):
        read_config(repo / "robotmodel.toml")
    assert main(["check-urdf", "urdf/arm.urdf.xacro"]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert err.startswith(f"{PREFIX}error: {repo / 'robotmodel.toml'}: ") and message in err, err


def test_config_search_stops_at_the_repository_root(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "robotmodel.toml").write_text('[[entry]]\nfile = "x.urdf"\n')
    inner = tmp_path / "repo" / "sub"
    inner.mkdir(parents=True)
    assert find_config(inner) is not None and find_config(inner).path == tmp_path / "robotmodel.toml"
    (tmp_path / "repo" / ".git").mkdir()
    assert find_config(inner) is None
    (tmp_path / "repo" / "pyproject.toml").write_text('[project]\nname = "x"\n')  # no [tool.robotmodel]
    assert find_config(inner) is None
    monkeypatch.chdir(inner)
    (tmp_path / "repo" / "robotmodel.toml").write_text('package-path = ["pkgs"]\n')
    config = find_config()
    assert config is not None and config.package_paths == (tmp_path / "repo" / "pkgs",)


def test_readme_config_example_is_read(tmp_path: Path) -> None:
    """The config shown in the module docs of robotmodel.check._project parses as documented."""
    from robotmodel.check import _project

    doc = _project.__doc__ or ""
    lines = []
    for line in doc.split("folder)::", 1)[1].splitlines()[1:]:
        if line.strip() and not line.startswith("    "):
            break
        lines.append(line[4:])
    text = "\n".join(lines)
    (tmp_path / "robotmodel.toml").write_text(text)
    config = read_config(tmp_path / "robotmodel.toml")
    assert [(e.file, e.args) for e in config.entries] == [
        (tmp_path / "urdf/robot.urdf.xacro", (("prefix", "left_"), ("use_gripper", "true")))]


def test_corpus_ur_fragments_go_through_configured_variants(corpus: Path, tmp_path: Path,
                                                            monkeypatch: pytest.MonkeyPatch,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    """UR's macro files, as a pre-commit run passes them, are checked as the configured UR variants."""
    urdf = corpus / "Universal_Robots_ROS2_Description" / "ur_description" / "urdf"
    (tmp_path / "robotmodel.toml").write_text(
        f'[[entry]]\nfile = "{urdf / "ur.urdf.xacro"}"\nargs = {{ ur_type = "ur3", name = "ur" }}\n'
        f'[[entry]]\nfile = "{urdf / "ur.urdf.xacro"}"\nargs = {{ ur_type = "ur5e", name = "ur" }}\n')
    monkeypatch.chdir(tmp_path)
    fragments = [str(urdf / "ur_macro.xacro"), str(urdf / "inc" / "ur_common.xacro")]
    assert all(is_macro_only(f) for f in fragments)
    assert main(["check-urdf", *fragments]) == 0
    out, err = capsys.readouterr()
    assert out == _singles(capsys, [str(urdf / "ur.urdf.xacro"), "ur_type:=ur3", "name:=ur"],
                           [str(urdf / "ur.urdf.xacro"), "ur_type:=ur5e", "name:=ur"])
    assert err.splitlines()[-1].startswith(f"{PREFIX}2 files checked: 2 passed, 0 failed (0 errors, ")
    assert "fragment-not-checked" not in err
    # A UR file no configured variant includes is reported, not checked alone.
    mock = str(urdf / "ros2_control_mock_hardware.xacro")
    assert main(["check-urdf", mock]) == 0
    assert f"[fragment-not-checked] {mock}: " in capsys.readouterr().err
