"""ROS 1 ``<param type=...>``: the value reaches the node's ``-p`` with roslaunch's type.

Expected values from roslaunch's documented rules: ``str``/``string`` keep the text,
``int``/``double``/``float`` convert it, ``bool``/``boolean`` take true/1/false/0 in any case,
``yaml`` parses it; with no type roslaunch's ``convert_value(value.strip(), 'auto')``: a float
when the text holds '.', else an int (none with '_'), else true/false (any case), else text,
so ``1e3`` stays text. A string rcl would read as a number or bool goes quoted.
"""

from __future__ import annotations

import pytest

from robotmodel.errors import LaunchError
from robotmodel.launch import build_plan, load_launch_file


def params_of(pkg, tmp_path, body: str) -> list[str]:
    path = pkg.launch("typed.launch", f"""
        <launch>
          <node pkg="tf2_ros" type="static_transform_publisher" name="s" args="0 0 0 0 0 0 a b">
            {body}
          </node>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [pkg.root]), tmp_path, package_paths=[pkg.root], browser=False)
    words = plan.processes[0].argv
    return [words[i + 1] for i, w in enumerate(words) if w == "-p"]


def test_ros1_param_type_attribute_decides_the_value(pkg, tmp_path):
    assert params_of(pkg, tmp_path, """
        <param name="a_str" type="str" value="50"/>
        <param name="a_string" type="string" value="true"/>
        <param name="an_int" type="int" value=" 7 "/>
        <param name="a_double" type="double" value="50"/>
        <param name="a_float" type="float" value="2"/>
        <param name="one" type="bool" value="1"/>
        <param name="zero" type="boolean" value="0"/>
        <param name="upper" type="bool" value="TRUE"/>
        <param name="a_yaml" type="yaml" value="[1, 2]"/>
    """) == ["a_str:='50'", "a_string:='true'", "an_int:=7", "a_double:=50.0", "a_float:=2.0",
             "one:=true", "zero:=false", "upper:=true", "a_yaml:=[1, 2]"]


def test_ros1_param_without_type_is_guessed(pkg, tmp_path):
    assert params_of(pkg, tmp_path, """
        <param name="i" value="5"/>
        <param name="f" value=" 2.5 "/>
        <param name="e" value="1e3"/>
        <param name="u" value="1_000"/>
        <param name="b" value="False"/>
        <param name="s" value="yes"/>
        <param name="y" value="y"/>
        <param name="n" value="null"/>
        <param name="one" value="1"/>
    """) == ["i:=5", "f:=2.5", "e:='1e3'", "u:='1_000'", "b:=false", "s:='yes'", "y:='y'", "n:='null'", "one:=1"]


@pytest.mark.parametrize(("ptype", "value"), [("bool", "2"), ("int", "1.5"), ("double", "x")])
def test_ros1_param_value_not_of_its_type_is_refused(pkg, tmp_path, ptype, value):
    with pytest.raises(LaunchError, match=rf"typed.launch:\d+: .*'{value}' is not a '{ptype}' type"):
        params_of(pkg, tmp_path, f'<param name="p" type="{ptype}" value="{value}"/>')
