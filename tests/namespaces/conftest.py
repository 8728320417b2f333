"""Fixtures for the namespace tests: a two-joint robot with a xacro prefix, and a private bus.

Hand values of the robot: base_link -> arm turns about z by ``shoulder`` at 0.5 above the
base; arm -> tool is 0.25 along x (fixed). So tool sits at (0.25 cos q, 0.25 sin q, 0.5) in
base_link, with the rotation (0, 0, sin q/2, cos q/2).
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from livebus import Bus, joined

ROBOT_XACRO = """\
<?xml version="1.0"?>
<robot name="probe" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="p" value="$(arg prefix)"/>
  <link name="${p}base_link"/><link name="${p}arm"/><link name="${p}tool"/>
  <joint name="${p}shoulder" type="revolute"><parent link="${p}base_link"/><child link="${p}arm"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="${p}tool_mount" type="fixed"><parent link="${p}arm"/><child link="${p}tool"/>
    <origin xyz="0.25 0 0"/></joint>
</robot>
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3"><name>ns_probe</name><version>0.0.1</version><description>test</description>
<maintainer email="a@b.c">t</maintainer><license>BSD</license></package>
"""


@pytest.fixture
def package(tmp_path: Path) -> Path:
    """A ``ns_probe`` package (package.xml, urdf/probe.urdf.xacro, launch/) under ``tmp_path/ws``; returns its root."""
    root = tmp_path / "ws"
    pkg = root / "ns_probe"
    (pkg / "urdf").mkdir(parents=True)
    (pkg / "launch").mkdir()
    (pkg / "package.xml").write_text(PACKAGE_XML)
    (pkg / "urdf" / "probe.urdf.xacro").write_text(ROBOT_XACRO)
    return root


ROBOT_LAUNCH = """
    <launch>
      <arg name="prefix"/>
      <arg name="q"/>
      <arg name="x"/>
      <param name="robot_description"
             command="$(find xacro)/xacro $(find ns_probe)/urdf/probe.urdf.xacro prefix:=$(arg prefix)"/>
      <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
      <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp">
        <param name="zeros/$(arg prefix)shoulder" value="$(arg q)"/>
      </node>
      <node pkg="tf2_ros" type="static_transform_publisher" name="mount"
            args="$(arg x) 0 0 0 0 0 world $(arg prefix)base_link"/>
    </launch>
"""

TWO_ROBOTS = """
    <launch>
      <group ns="r1">
        <include file="$(find ns_probe)/launch/robot.launch">
          <arg name="prefix" value="r1_"/><arg name="q" value="0.3"/><arg name="x" value="1"/>
        </include>
      </group>
      <group ns="r2">
        <include file="$(find ns_probe)/launch/robot.launch">
          <arg name="prefix" value="r2_"/><arg name="q" value="-0.7"/><arg name="x" value="-1"/>
        </include>
      </group>
    </launch>
"""


def write_launch(package: Path, name: str, text: str) -> Path:
    """Write ``ns_probe/launch/NAME`` (dedented) under the package root; returns its path."""
    path = package / "ns_probe" / "launch" / name
    path.write_text(textwrap.dedent(text).lstrip())
    return path


@pytest.fixture
def two_robots(package: Path) -> Path:
    """``two.launch``: the same robot.launch included in groups r1 and r2 (other prefix, joint value, place)."""
    write_launch(package, "robot.launch", ROBOT_LAUNCH)
    return write_launch(package, "two.launch", TWO_ROBOTS)


@pytest.fixture
def write(package: Path) -> Callable[[str, str], Path]:
    """``write(NAME, TEXT)``: :func:`write_launch` in this test's package."""
    return lambda name, text: write_launch(package, name, text)


@pytest.fixture
def live(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Bus]:
    """A private bus (own port and ROS_DOMAIN_ID) that the test process joins too; every child is reaped."""
    yield from joined(Bus(tmp_path, "zenoh"), monkeypatch)
