"""Which dialect a launch file is read in: from its content and its includer, not from its name alone.

ROS 1 packages often name includes ``*.launch.xml`` (turtlebot3_bringup's
``launch/includes/description.launch.xml``, ur_gazebo's ``launch/inc/*.launch.xml``); roslaunch
reads every include as ROS 1, whatever its name.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from robotmodel.launch import Dialect, build_plan, load_launch_file
from robotmodel.launch._xml import parse_file
from robotmodel.xacro import expand

# The shape of turtlebot3_bringup's (noetic) includes/description.launch.xml, written here:
# a required arg, an arg holding a whole xacro command line, a global <param command>.
DESCRIPTION_INCLUDE = """
    <launch>
      <arg name="model"/>
      <arg name="urdf_file" default="$(find xacro)/xacro '$(find {pkg})/urdf/{stem}.urdf.xacro'"/>
      <param name="robot_description" command="$(arg urdf_file)"/>
    </launch>
"""
# ...and of its includer, turtlebot3_remote.launch.
REMOTE = """
    <launch>
      <arg name="model" default="burger"/>
      <include file="$(find {pkg})/launch/includes/description.launch.xml">
        <arg name="model" value="$(arg model)"/>
      </include>
      <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher">
        <param name="publish_frequency" type="double" value="30.0"/>
      </node>
    </launch>
"""


def rsp_argv(path: Path, args: dict[str, str], paths: list[Path], tmp_path: Path) -> tuple[str, ...]:
    plan = build_plan(load_launch_file(path, args, paths), tmp_path, package_paths=paths, browser=False)
    [rsp] = [p for p in plan.processes if p.kind == "robot_state_publisher"]
    return rsp.argv


def test_ros1_include_named_launch_xml_is_read_as_ros1(pkg, tmp_path):
    pkg.launch("includes/description.launch.xml",
               DESCRIPTION_INCLUDE.format(pkg="probe_description", stem="$(arg model)"))
    top = pkg.launch("remote.launch", REMOTE.format(pkg="probe_description"))
    argv = rsp_argv(top, {"model": "probe"}, [pkg.root], tmp_path)
    # The description the include set reaches the node: the xacro file the include names.
    assert argv[:2] == ("robot-state-publisher", str(pkg.xacro))


def test_ros1_launch_xml_run_on_its_own_is_ros1(pkg, tmp_path):
    path = pkg.launch("includes/description.launch.xml",
                      DESCRIPTION_INCLUDE.format(pkg="probe_description", stem="$(arg model)"))
    launch = load_launch_file(path, {"model": "probe"}, [pkg.root])
    assert launch.params["/robot_description"].xacro is not None
    assert launch.params["/robot_description"].xacro.file == pkg.xacro


def test_ros1_launch_xml_include_without_ros1_substitutions_keeps_its_global_param(pkg, tmp_path):
    # ur_gazebo's inc/ style with nothing ROS 2 would choke on: read as ROS 2, the
    # global <param> was dropped and the node skipped for want of a robot_description.
    pkg.launch("inc/load_description.launch.xml", """
        <launch>
          <param name="robot_description" textfile="$(dirname)/../../urdf/probe.urdf.xacro"/>
        </launch>
    """)
    top = pkg.launch("top.launch", """
        <launch>
          <include file="$(dirname)/inc/load_description.launch.xml"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
        </launch>
    """)
    assert rsp_argv(top, {}, [pkg.root], tmp_path)[:2] == ("robot-state-publisher", str(pkg.xacro))


def write(tmp_path: Path, name: str, body: str) -> Path:
    path = tmp_path / name
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    return path


@pytest.mark.parametrize(("name", "body", "includer", "expected"), [
    # The content decides when it speaks one dialect only.
    ("a.launch.xml", '<arg name="m" default="$(find p)/x"/>', None, Dialect.ROS1),
    ("a.launch.xml", '<node pkg="p" type="t" name="n"/>', None, Dialect.ROS1),
    ("a.launch.xml", '<rosparam param="z">{a: 1}</rosparam>', None, Dialect.ROS1),
    ("a.launch.xml", '<arg name="m" doc="the model"/>', None, Dialect.ROS1),
    ("a.launch", '<node pkg="p" exec="e"/>', None, Dialect.ROS2),
    ("a.launch", '<let name="x" value="1"/>', None, Dialect.ROS2),
    ("a.xml", '<node pkg="p" exec="e"><param name="robot_description" value="$(var d)"/></node>', None,
     Dialect.ROS2),
    ("a.xml", '<include file="$(find-pkg-share p)/a.launch.xml"/>', None, Dialect.ROS2),
    # Both dialects' words, or neither: the name, then the includer.
    ("a.launch.xml", '<node pkg="p" exec="e" args="$(find p)"/>', None, Dialect.ROS2),
    ("a.launch", '<node pkg="p" exec="e" args="$(find p)"/>', None, Dialect.ROS1),
    ("a.launch.xml", '<arg name="x" default="1"/>', None, Dialect.ROS2),
    ("a.launch", '<arg name="x" default="1"/>', None, Dialect.ROS1),
    ("a.xml", '<arg name="x" default="1"/>', None, Dialect.ROS1),
    ("a.xml", '<arg name="x" default="1"/>', Dialect.ROS2, Dialect.ROS2),
    # roslaunch reads whatever a ROS 1 file includes as ROS 1.
    ("a.launch.xml", '<node pkg="p" exec="e"/>', Dialect.ROS1, Dialect.ROS1),
    ("a.launch.xml", '<arg name="x" default="1"/>', Dialect.ROS1, Dialect.ROS1),
])
def test_dialect_from_content_then_name(tmp_path, name, body, includer, expected):
    from robotmodel.launch._dialect import detect_dialect

    path = write(tmp_path, name, body)
    assert detect_dialect(path, parse_file(path), includer) is expected


def test_turtlebot3_noetic_description_through_a_launch_xml_include(corpus, tmp_path):
    """The corpus's real turtlebot3_description (noetic) behind the bringup's include layout."""
    noetic = corpus / "turtlebot3_noetic"
    bringup = tmp_path / "ws" / "turtlebot3_bringup"
    (bringup / "launch" / "includes").mkdir(parents=True)
    (bringup / "package.xml").write_text(
        '<package format="2"><name>turtlebot3_bringup</name><version>1.0.0</version><description>d</description>'
        '<maintainer email="a@b.c">m</maintainer><license>Apache 2.0</license></package>')
    (bringup / "launch" / "includes" / "description.launch.xml").write_text(
        DESCRIPTION_INCLUDE.format(pkg="turtlebot3_description", stem="turtlebot3_$(arg model)"))
    top = bringup / "launch" / "turtlebot3_remote.launch"
    top.write_text(REMOTE.format(pkg="turtlebot3_bringup"))
    # noetic first: turtlebot3_description exists in the ROS 2 folder of the corpus too.
    paths = [noetic, tmp_path / "ws"]
    argv = rsp_argv(top, {"model": "waffle"}, paths, tmp_path)
    xacro = noetic / "turtlebot3_description" / "urdf" / "turtlebot3_waffle.urdf.xacro"
    assert argv[:2] == ("robot-state-publisher", str(xacro))
    # MANIFEST.md row 8 (xacro 2.1.1 + check_urdf): robot turtlebot3_waffle, 13 links.
    robot = ET.fromstring(expand(xacro, {}, package_paths=paths))
    assert (robot.get("name"), len(robot.findall("link"))) == ("turtlebot3_waffle", 13)
