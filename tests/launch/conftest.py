"""Fixtures for the launch tests: a small description package written per test, and a private bus."""

from __future__ import annotations

import textwrap
from collections.abc import Iterator
from pathlib import Path

import pytest
from livebus import Bus, joined

# A two-joint robot with a xacro argument. Hand values: base_link -> arm is a z rotation by
# `shoulder` about a point 0.5 above; arm -> tool is 0.25 along x, so tool sits at
# (0.25 cos q, 0.25 sin q, 0.5) in base_link.
PROBE_XACRO = """\
<?xml version="1.0"?>
<robot name="probe" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="p" value="$(arg prefix)"/>
  <link name="${p}base_link"/><link name="${p}arm"/><link name="${p}tool"/>
  <joint name="${p}shoulder" type="revolute"><parent link="${p}base_link"/><child link="${p}arm"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="${p}tool_mount" type="fixed"><parent link="${p}arm"/><child link="${p}tool"/>
    <origin xyz="0.25 0 0"/></joint>
</robot>
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>test</description>
<maintainer email="a@b.c">t</maintainer><license>BSD</license></package>
"""


class Package:
    """``probe_description`` under ``root``: package.xml, urdf/probe.urdf.xacro, launch/ files."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.dir = root / "probe_description"
        (self.dir / "urdf").mkdir(parents=True)
        (self.dir / "launch").mkdir()
        (self.dir / "package.xml").write_text(PACKAGE_XML.format(name="probe_description"))
        self.xacro = self.dir / "urdf" / "probe.urdf.xacro"
        self.xacro.write_text(PROBE_XACRO)

    def launch(self, name: str, text: str) -> Path:
        """Write ``launch/NAME`` (dedented) and return its path."""
        path = self.dir / "launch" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip())
        return path


@pytest.fixture
def pkg(tmp_path: Path) -> Package:
    """A fresh probe_description package in this test's folder."""
    return Package(tmp_path / "ws")


@pytest.fixture
def live(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Bus]:
    """A private bus that the test process joins too; every process started on it is reaped."""
    yield from joined(Bus(tmp_path, "zenoh"), monkeypatch)


def write_ros1(pkg: Package) -> Path:
    """A ROS 1 launch tree: top.launch includes parts/publishers.launch, which includes parts/rsp.launch."""
    pkg.launch("parts/rsp.launch", """
        <launch>
          <arg name="freq" default="20"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">
            <param name="publish_frequency" value="$(arg freq)"/>
          </node>
        </launch>
    """)
    pkg.launch("parts/publishers.launch", """
        <launch>
          <arg name="rate"/>
          <arg name="gui" default="false"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp" unless="$(arg gui)">
            <param name="rate" value="$(arg rate)"/>
            <rosparam param="zeros">{shoulder: 0.5}</rosparam>
          </node>
          <node pkg="joint_state_publisher_gui" type="joint_state_publisher_gui" name="jsp_gui" if="$(arg gui)"/>
          <include file="$(dirname)/rsp.launch">
            <arg name="freq" value="$(eval rate * 5)"/>
          </include>
        </launch>
    """)
    return pkg.launch("top.launch", """
        <launch>
          <arg name="prefix" default=""/>
          <arg name="with_static" default="true"/>
          <arg name="gui" default="false"/>
          <param name="robot_description"
                 command="$(find xacro)/xacro $(find probe_description)/urdf/probe.urdf.xacro prefix:=$(arg prefix)"/>
          <include file="$(find probe_description)/launch/parts/publishers.launch">
            <arg name="rate" value="$(eval 2 * 5)"/>
            <arg name="gui" value="$(arg gui)"/>
          </include>
          <group if="$(arg with_static)">
            <node pkg="tf" type="static_transform_publisher" name="map_odom" args="1 2 0 0 0 0 map odom 100"/>
          </group>
          <group ns="sensors" unless="$(eval not with_static)">
            <node pkg="probe_description" type="scan_filter.py" name="scan_filter"/>
          </group>
        </launch>
    """)


def write_ros2(pkg: Package) -> Path:
    """A ROS 2 launch tree: probe.launch.xml includes statics.launch.xml, which includes frames.launch.xml."""
    pkg.launch("frames.launch.xml", """
        <launch>
          <arg name="child"/>
          <node pkg="tf2_ros" exec="static_transform_publisher" name="map_odom"
                args="--x 1 --y 2 --frame-id map --child-frame-id $(var child)"/>
        </launch>
    """)
    pkg.launch("statics.launch.xml", """
        <launch>
          <arg name="child" default="base"/>
          <include file="$(dirname)/frames.launch.xml"/>
        </launch>
    """)
    return pkg.launch("probe.launch.xml", """
        <launch>
          <arg name="model" default="$(find-pkg-share probe_description)/urdf/probe.urdf.xacro"/>
          <arg name="gui" default="false"/>
          <arg name="rate_base" default="25"/>
          <let name="freq" value="$(eval '$(var rate_base) * 2')"/>
          <group>
            <push-ros-namespace namespace="robot1"/>
            <let name="scoped_only" value="1"/>
            <node pkg="robot_state_publisher" exec="robot_state_publisher">
              <param name="robot_description" value="$(command 'xacro $(var model) prefix:=a_')"/>
              <param name="publish_frequency" value="$(var freq)"/>
              <param name="frame_prefix" value="x/"/>
            </node>
            <node pkg="joint_state_publisher" exec="joint_state_publisher" unless="$(var gui)">
              <param name="zeros"><param name="a_shoulder" value="0.5"/></param>
              <param name="source_list" value="[/extra_states]"/>
            </node>
            <node pkg="joint_state_publisher_gui" exec="joint_state_publisher_gui" if="$(var gui)"/>
          </group>
          <include file="$(dirname)/statics.launch.xml">
            <arg name="child" value="odom"/>
          </include>
          <node pkg="rviz2" exec="rviz2" args="-d $(var child).rviz" if="$(equals $(var child) odom)"/>
          <node pkg="probe_description" exec="teleop.py"/>
        </launch>
    """)


@pytest.fixture
def ros1_top(pkg: Package) -> Path:
    """The ROS 1 tree of :func:`write_ros1` in this test's package."""
    return write_ros1(pkg)


@pytest.fixture
def ros2_top(pkg: Package) -> Path:
    """The ROS 2 tree of :func:`write_ros2` in this test's package."""
    return write_ros2(pkg)
