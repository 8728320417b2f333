"""Bad launch files: one line on stderr naming the file and the line, non-zero exit, nothing started."""

from __future__ import annotations

import subprocess
import sys

import pytest
from robotmodel.cli.main import main


def run_cli(capsys, *words: str) -> tuple[int, list[str], str]:
    code = main(["launch", *words, "--dry-run"])
    captured = capsys.readouterr()
    return code, captured.err.splitlines(), captured.out


CASES = {
    "unknown_ros1_substitution": ("bad.launch", """
        <launch>
          <arg name="x" default="1"/>
          <arg name="y" default="$(foo bar)"/>
        </launch>
    """, 3, "Unknown substitution command [foo bar]. Valid commands are "),
    "unknown_ros2_substitution": ("bad.launch.xml", """
        <launch>
          <node pkg="tf2_ros" exec="static_transform_publisher"
                args="$(find probe_description)"/>
        </launch>
    """, 2, "Unknown substitution: find"),
    "missing_include": ("bad.launch", """
        <launch>

          <include file="$(dirname)/nowhere.launch"/>
        </launch>
    """, 3, "<include>: launch file not found: "),
    "bad_xml": ("bad.launch", """
        <launch>
          <arg name="x" default="1">
        </launch>
    """, 3, "invalid XML: mismatched tag"),
    "undefined_arg": ("bad.launch", """
        <launch>
          <node pkg="tf" type="static_transform_publisher" name="s" args="$(arg nope)"/>
        </launch>
    """, 2, "arg 'nope' is not defined"),
    "unset_arg": ("bad.launch", """
        <launch>
          <arg name="needed"/>
          <node pkg="tf" type="static_transform_publisher" name="s" args="$(arg needed)"/>
        </launch>
    """, 3, "arg 'needed' is not set"),
    "missing_ros2_argument": ("bad.launch.xml", """
        <launch>
          <arg name="model" description="the robot"/>
        </launch>
    """, 2, "Included launch description missing required argument 'model' (description: 'the robot'), "
            "given: [other]"),
    "not_xacro": ("bad.launch", """
        <launch>
          <param name="robot_description" command="cat /etc/hostname"/>
        </launch>
    """, 2, "command 'cat /etc/hostname': only xacro commands are run, not 'cat'"),
    "bad_boolean": ("bad.launch", """
        <launch>
          <group if="maybe"/>
        </launch>
    """, 2, 'if="maybe": value must be true or false (or 1/0)'),
    "eval_dunder": ("bad.launch", """
        <launch>
          <arg name="x" value="$(eval ().__class__)"/>
        </launch>
    """, 2, "$(eval ...) may not contain double underscore expressions"),
    "eval_import": ("bad.launch.xml", """
        <launch>
          <let name="x" value="$(eval &quot;open('/etc/passwd')&quot;)"/>
        </launch>
    """, 2, "function 'open' is not available in $(eval)"),
    "override_fixed_value": ("bad.launch", """
        <launch>
          <include file="$(dirname)/fixed.launch"><arg name="v" value="2"/></include>
        </launch>
    """, None, "cannot override arg 'v', which has already been set"),
    "unused_include_arg": ("bad.launch", """
        <launch>
          <include file="$(dirname)/fixed.launch">
            <arg name="w" value="2"/>
          </include>
        </launch>
    """, 2, "unused args [w] for include of ["),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_launch_file_gives_one_line_naming_file_and_line(pkg, capsys, case):
    name, text, line, message = CASES[case]
    pkg.launch("fixed.launch", """
        <launch>
          <arg name="v" value="1"/>
        </launch>
    """)
    path = pkg.launch(name, text)
    code, err, out = run_cli(capsys, str(path), "--package-path", str(pkg.root), "other:=1")
    assert code != 0
    assert out == ""
    assert len(err) == 1, err
    # line None: the error is inside the included file.
    where = f"{pkg.dir / 'launch' / 'fixed.launch'}:2: " if line is None else f"{path}:{line}: "
    assert err[0].startswith(f"robotmodel launch: error: {where}"), err[0]
    assert message in err[0]


def test_error_inside_a_nested_include_names_the_included_file(pkg, capsys):
    pkg.launch("inner.launch", """
        <launch>
          <arg name="a" default="1"/>

          <node pkg="tf" type="static_transform_publisher" name="s" args="$(optenv)"/>
        </launch>
    """)
    pkg.launch("middle.launch", """
        <launch><include file="$(dirname)/inner.launch"/></launch>
    """)
    top = pkg.launch("top.launch", """
        <launch><include file="$(find probe_description)/launch/middle.launch"/></launch>
    """)
    code, err, _ = run_cli(capsys, str(top), "--package-path", str(pkg.root))
    assert code == 1
    assert err == [f"robotmodel launch: error: {pkg.dir / 'launch' / 'inner.launch'}:4: $(optenv) takes 1 "
                   "argument(s), got 0: '$(optenv )'"]


def test_include_cycle_is_an_error_not_a_hang(pkg, capsys):
    path = pkg.launch("loop.launch", """
        <launch><include file="$(dirname)/loop.launch"/></launch>
    """)
    code, err, _ = run_cli(capsys, str(path))
    assert code == 1 and len(err) == 1
    assert f"{path}:1: includes nested deeper than 32" in err[0]


def test_missing_file_and_unknown_package(pkg, capsys, tmp_path):
    code, err, _ = run_cli(capsys, str(tmp_path / "none.launch"))
    assert (code, err) == (1, [f"robotmodel launch: error: {tmp_path / 'none.launch'}: no such launch file"])
    code, err, _ = run_cli(capsys, "probe_description", "none.launch", "--package-path", str(pkg.root))
    assert code == 1
    assert err == ["robotmodel launch: error: [none.launch] is neither a launch file in package "
                   "[probe_description] nor is [probe_description] a launch file name"]


def test_as_a_process_exit_code_and_no_traceback(pkg):
    path = pkg.launch("bad.launch", "<launch>\n  <node\n</launch>\n")
    proc = subprocess.run([sys.executable, "-m", "robotmodel.cli.main", "launch", str(path)],
                          capture_output=True, text=True, timeout=60, check=False)
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [f"robotmodel launch: error: {path}:3: invalid XML: not well-formed "
                                        "(invalid token) (column 1)"]


def test_python_launch_file_without_generate_launch_description_is_one_line(pkg, capsys):
    path = pkg.launch("display.launch.py", "from launch import LaunchDescription\n")
    code, err, _ = run_cli(capsys, str(path))
    assert code == 1
    assert err == [f"robotmodel launch: error: launch file at '{path}' does not contain the required function "
                   "'generate_launch_description()'"]


def test_yaml_launch_file_missing_an_argument_is_one_line(pkg, capsys):
    path = pkg.launch("display.launch.yaml", "launch:\n- arg:\n    name: model\n")
    code, err, _ = run_cli(capsys, str(path))
    assert code == 1
    assert err == [f"robotmodel launch: error: {path}:2: Included launch description missing required argument "
                   "'model' (description: 'no description given'), given: []"]


def test_deeply_nested_substitutions_and_groups_are_errors(pkg, capsys):
    path = pkg.launch("deep.launch", '<launch>\n<arg name="x" value="' + "$(arg " * 1200 + "y" + ")" * 1200 + '"/>\n</launch>\n')
    code, err, _ = run_cli(capsys, str(path))
    assert (code, err) == (1, [f"robotmodel launch: error: {path}:2: substitutions nested too deep"])
    path = pkg.launch("groups.launch", "<launch>" + "<group>" * 1200 + "</group>" * 1200 + "</launch>")
    code, err, _ = run_cli(capsys, str(path))
    assert (code, err) == (1, [f"robotmodel launch: error: {path}: elements nested too deep"])
