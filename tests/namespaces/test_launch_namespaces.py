"""Launch files with namespaces: each node started with its namespace, as launch_ros passes it.

ROS 1: ``<group ns>`` and a node's ``ns`` (relative to its group); ROS 2: ``<push-ros-namespace>``
and a node's ``namespace`` (relative ones pushed down, absolute ones kept).
"""

from __future__ import annotations

import pytest
from robotmodel.cli.main import main

from robotmodel.errors import LaunchError
from robotmodel.launch import build_plan, load_launch_file


def test_ros1_groups_dry_run_gives_each_process_its_namespace(package, two_robots, capsys):
    xacro, root = package / "ns_probe" / "urdf" / "probe.urdf.xacro", str(package)
    assert main(["launch", str(two_robots), "--package-path", root, "--dry-run", "--no-browser"]) == 0
    out, err = capsys.readouterr()
    assert "note:" not in err
    expected = []
    for ns, prefix, q, x in (("r1", "r1_", "0.3", "1"), ("r2", "r2_", "-0.7", "-1")):
        # Each node also gets the name the file gave it (-r __node:=NAME), as launch passes it.
        tail = f"--package-path {root} --ros-args -r __node:=rsp -r __ns:=/{ns}"
        expected += [
            f"/{ns}/rsp: robotmodel robot-state-publisher {xacro} prefix:={prefix} {tail}",
            f"/{ns}/jsp: robotmodel joint-state-publisher {xacro} prefix:={prefix}"
            f" --package-path {root} --zeros {prefix}shoulder={q} --ros-args -r __node:=jsp -r __ns:=/{ns}",
            f"/{ns}/mount: robotmodel static-transform-publisher {x} 0 0 0 0 0 world {prefix}base_link "
            f"--ros-args -r __node:=mount -r __ns:=/{ns}",
        ]
    assert out.splitlines() == expected


def test_ros2_push_ros_namespace_and_node_namespace(package, write, tmp_path):
    path = write("ns.launch.xml", """
        <launch>
          <group>
            <push-ros-namespace namespace="robot"/>
            <node pkg="robot_state_publisher" exec="robot_state_publisher" namespace="left">
              <param name="robot_description" value="$(command 'xacro $(find-pkg-share ns_probe)/urdf/probe.urdf.xacro')"/>
            </node>
            <node pkg="joint_state_publisher" exec="joint_state_publisher" namespace="/elsewhere"/>
            <node pkg="rviz2" exec="rviz2"/>
          </group>
          <node pkg="tf2_ros" exec="static_transform_publisher" args="--frame-id a --child-frame-id b"/>
        </launch>
    """)
    plan = build_plan(load_launch_file(path, {}, [package]), tmp_path, package_paths=[package], browser=False)
    tails = {p.name: p.argv[p.argv.index("--ros-args"):] if "--ros-args" in p.argv else () for p in plan.processes}
    assert tails == {
        "/robot/left/robot_state_publisher": ("--ros-args", "-r", "__ns:=/robot/left"),
        # An absolute node namespace is not pushed down, as in launch_ros.
        "/elsewhere/joint_state_publisher": ("--ros-args", "-r", "__ns:=/elsewhere"),
        # The viewer standing in for rviz reads robot_description and joint_states in /robot.
        "/robot/rviz2": ("--ros-args", "-r", "__ns:=/robot"),
        "/static_transform_publisher": (),
    }
    assert plan.notes == []


def test_invalid_namespace_in_a_launch_file_is_one_line_error(package, write, tmp_path):
    path = write("bad.launch", """
        <launch>
          <group ns="9lives">
            <node pkg="tf2_ros" type="static_transform_publisher" name="s" args="0 0 0 0 0 0 a b"/>
          </group>
        </launch>
    """)
    with pytest.raises(LaunchError, match=r"bad\.launch:3: node s: invalid namespace '/9lives': "):
        build_plan(load_launch_file(path, {}, [package]), tmp_path, package_paths=[package], browser=False)
