"""Launch files run as real processes on a private bus: TF comes out (remapped topics too), all stop together."""

from __future__ import annotations

import io
import math
import re
import signal
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from robotmodel.bus import Node
from robotmodel.errors import TransformException
from robotmodel.tf import Buffer, Time
from robotmodel.tf_ros import TransformListener

STARTED = re.compile(r"process\[(.+)\]: started with pid \[(\d+)\]")


def launch(live, *words: str):
    return live.start(sys.executable, "-m", "robotmodel.cli.main", "launch", "--no-browser", *words)


def started(proc, count: int, timeout: float = 30.0) -> dict[str, int]:
    """{label: pid} once ``count`` processes are reported started."""
    found: dict[str, int] = {}

    def enough() -> bool:
        found.clear()
        for line in proc.err:
            m = STARTED.search(line)
            if m:
                found[m.group(1)] = int(m.group(2))
        return len(found) >= count

    proc.wait_for(enough, timeout, f"{count} processes started")
    return dict(found)


def wait_pose(buffer: Buffer, target: str, source: str, timeout: float = 40.0):
    """(translation, quaternion xyzw) of ``source`` in ``target``, as soon as the buffer can look it up."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            t = buffer.lookup_transform(target, source, Time()).transform
        except TransformException as exc:
            if time.monotonic() > deadline:
                pytest.fail(f"{target} <- {source} not available within {timeout} s: {exc}\n"
                            f"frames: {buffer.all_frames_as_string()}")
            time.sleep(0.05)
            continue
        return ((t.translation.x, t.translation.y, t.translation.z),
                (t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w))


def wait_value(buffer: Buffer, target: str, source: str, expected, timeout: float = 40.0):
    """Wait until the translation equals ``expected`` (the first states may predate the launch's zeros)."""
    deadline = time.monotonic() + timeout
    while True:
        xyz, q = wait_pose(buffer, target, source, timeout)
        if np.allclose(xyz, expected, atol=1e-9) or time.monotonic() > deadline:
            return xyz, q
        time.sleep(0.05)


def gone(pid: int) -> bool:
    """True once the process no longer runs (exited and reaped, or a zombie awaiting init)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return True
    return stat.rsplit(")", 1)[1].split()[0] == "Z"


def wait_gone(pids, timeout: float = 20.0) -> None:
    deadline = time.monotonic() + timeout
    while not all(gone(p) for p in pids):
        if time.monotonic() > deadline:
            pytest.fail(f"still running: {[p for p in pids if not gone(p)]}")
        time.sleep(0.05)


def test_ros1_launch_tree_publishes_tf_and_sigterm_stops_every_process(live, pkg, ros1_top):
    proc = launch(live, str(ros1_top), "--package-path", str(pkg.root))
    pids = started(proc, 3)
    assert sorted(pids) == ["jsp-1", "map_odom-3", "rsp-2"]
    proc.wait_line(r"^skipped: /sensors/scan_filter \(probe_description/scan_filter.py\)")
    buffer = Buffer()
    with TransformListener(buffer):
        # shoulder = 0.5 from the <rosparam> zeros: tool at (0.25 cos q, 0.25 sin q, 0.5).
        q = 0.5
        xyz, quat = wait_value(buffer, "base_link", "tool", (0.25 * math.cos(q), 0.25 * math.sin(q), 0.5))
        assert np.allclose(xyz, (0.25 * math.cos(q), 0.25 * math.sin(q), 0.5), atol=1e-9)
        assert np.allclose(quat, (0, 0, math.sin(q / 2), math.cos(q / 2)), atol=1e-9)
        # ROS 1 tf's period form: map -> odom republished on /tf.
        xyz, quat = wait_pose(buffer, "map", "odom")
        assert np.allclose(xyz, (1, 2, 0)) and np.allclose(quat, (0, 0, 0, 1))
    assert proc.stop(signal.SIGTERM) == 0
    wait_gone(pids.values(), timeout=1.0)  # reaped by the launcher before it exited


def test_ros2_launch_tree_with_tf2_echo(live, pkg, ros2_top):
    proc = launch(live, str(ros2_top), "--package-path", str(pkg.root))
    pids = started(proc, 4)
    assert sorted(pids) == ["map_odom-3", "robot1/joint_state_publisher-2", "robot1/robot_state_publisher-1", "rviz2-4"]
    echo = live.robotmodel("tf2-echo", "map", "odom")
    echo.wait_line(r"^- Translation: \[1\.000, 2\.000, 0\.000\]$", timeout=40)
    buffer = Buffer()
    with TransformListener(buffer):
        # The xacro command's prefix:=a_, the node's frame_prefix x/, and zeros a_shoulder = 0.5.
        q = 0.5
        xyz, _ = wait_value(buffer, "x/a_base_link", "x/a_tool", (0.25 * math.cos(q), 0.25 * math.sin(q), 0.5))
        assert np.allclose(xyz, (0.25 * math.cos(q), 0.25 * math.sin(q), 0.5), atol=1e-9)
    assert echo.stop(signal.SIGINT) == 0
    # Ctrl-C, as from a terminal.
    assert proc.stop(signal.SIGINT) == 0
    wait_gone(pids.values(), timeout=1.0)


DISPLAY = """\
<launch>
  <arg name="model" default="$(find urdf_tutorial)/urdf/08-macroed.urdf.xacro"/>
  <arg name="gui" default="true"/>
  <arg name="rvizconfig" default="$(find urdf_tutorial)/rviz/urdf.rviz"/>
  <param name="robot_description" command="$(find xacro)/xacro $(arg model)"/>
  <node if="$(arg gui)" name="joint_state_publisher" pkg="joint_state_publisher_gui"
        type="joint_state_publisher_gui"/>
  <node unless="$(arg gui)" name="joint_state_publisher" pkg="joint_state_publisher"
        type="joint_state_publisher"/>
  <node name="robot_state_publisher" pkg="robot_state_publisher" type="robot_state_publisher"/>
  <node name="rviz" pkg="rviz" type="rviz" args="-d $(arg rvizconfig)" required="true"/>
</launch>
"""


def jsp_defaults(urdf_text: str) -> dict[str, float]:
    """joint_state_publisher's start values, by its rule: 0, or the middle of the limits when 0 is outside."""
    import xml.etree.ElementTree as ET

    values = {}
    for joint in ET.fromstring(urdf_text).iter("joint"):
        kind = joint.get("type")
        if kind in ("fixed", "floating", "planar") or joint.find("mimic") is not None:
            continue
        limit = joint.find("limit")
        lo, hi = (-math.pi, math.pi) if kind == "continuous" or limit is None else (
            float(limit.get("lower", 0)), float(limit.get("upper", 0)))
        values[joint.get("name")] = 0.0 if lo <= 0 <= hi else (lo + hi) / 2
    return values


def test_urdf_tutorial_display_launch_opens_sliders_viewer_and_tf(live, corpus, tmp_path):
    """The display.launch shape of urdf_tutorial (ROS 1), on the corpus's urdf_tutorial package."""
    import xacro
    import yourdfpy

    package = corpus / "urdf_tutorial"
    path = tmp_path / "display.launch"
    path.write_text(DISPLAY)
    proc = launch(live, str(path), "--package-path", str(package))
    pids = started(proc, 3)
    assert sorted(pids) == ["joint_state_publisher-1", "robot_state_publisher-2", "rviz-3"]
    # Both pages are served (the sliders and the rviz stand-in), each on its own port.
    proc.wait_for(lambda: sum(bool(re.match(r"^http://127\.0\.0\.1:\d+/( |$)", line)) for line in proc.out) >= 2,
                  60, "two page URLs")
    urls = {line for line in proc.out if line.startswith("http://")}
    assert len(urls) == 2
    # Reference: xacro (the PyPI package) and yourdfpy's FK at joint_state_publisher's start values.
    model = package / "urdf_tutorial" / "urdf" / "08-macroed.urdf.xacro"
    text = xacro.process_file(str(model)).toxml()
    robot = yourdfpy.URDF.load(io.BytesIO(text.encode()), load_meshes=False)
    robot.update_cfg(jsp_defaults(text))
    expected = robot.get_transform("left_gripper", "base_link")[:3, 3]
    buffer = Buffer()
    with TransformListener(buffer):
        xyz, _ = wait_pose(buffer, "base_link", "left_gripper")
    assert np.allclose(xyz, expected, atol=1e-9)
    # The launcher killed outright: its processes still go (they get SIGTERM when it dies).
    proc.kill()
    wait_gone(pids.values(), timeout=20.0)


def test_sensors_launch_shape_runs_what_it_can(live, pkg):
    """robot_description from textfile, map->odom with a period, RSP, rviz, and the package's own scripts."""
    urdf = pkg.dir / "urdf" / "sensors.urdf"
    urdf.write_text('<robot name="s"><link name="base_link"/><link name="laser"/>'
                    '<joint name="laser_mount" type="fixed"><parent link="base_link"/><child link="laser"/>'
                    '<origin xyz="0.15 0 0.3" rpy="0 0 0"/></joint></robot>')
    path = pkg.launch("sensors.launch", """
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/sensors.urdf"/>
          <node pkg="tf" type="static_transform_publisher" name="map_to_odom" args="0 0 0 0 0 0 map odom 100"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="robot_state_publisher"/>
          <node pkg="rviz" type="rviz" name="rviz"/>
          <node pkg="probe_description" type="odometry_node.py" name="odometry"/>
          <node pkg="probe_description" type="laser_node.py" name="laser"/>
        </launch>
    """)
    proc = launch(live, str(path), "--package-path", str(pkg.root))
    pids = started(proc, 3)
    assert sorted(pids) == ["map_to_odom-1", "robot_state_publisher-2", "rviz-3"]
    proc.wait_line(r"^skipped: /laser ")
    assert [line.split(" (")[0] for line in proc.out if line.startswith("skipped:")] == [
        "skipped: /odometry", "skipped: /laser"]
    buffer = Buffer()
    with TransformListener(buffer):
        assert np.allclose(wait_pose(buffer, "base_link", "laser")[0], (0.15, 0, 0.3))
        assert np.allclose(wait_pose(buffer, "map", "odom")[0], (0, 0, 0))
    assert proc.stop(signal.SIGTERM) == 0
    wait_gone(pids.values(), timeout=1.0)


def test_required_node_exiting_brings_the_launch_down(live, pkg):
    path = pkg.launch("required.launch", """
        <launch>
          <param name="robot_description" textfile="$(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          <node pkg="tf2_ros" type="static_transform_publisher" name="broken" args="1 2 map" required="true"/>
        </launch>
    """)
    proc = launch(live, str(path), "--package-path", str(pkg.root))
    pids = started(proc, 2)
    assert proc.popen.wait(60) == 1
    proc.wait_line(r"^\[broken-2\] process has died \[pid \d+, exit code 1\]$", stream="err")
    proc.wait_line(r"^\[broken-2\] required process has exited, shutting down$", stream="err")
    wait_gone(pids.values(), timeout=1.0)


# Remaps: /tf comes only through the remapped joint_states. With shoulder = Q the probe's tool
# sits at (0.25 cos Q, 0.25 sin Q, 0.5) in base_link.
Q = 0.5
TOOL = (0.25 * math.cos(Q), 0.25 * math.sin(Q), 0.5)


def wait_graph(node: Node, proc, timeout: float = 40.0) -> None:
    """Until /arm/joint_states has its publisher (jsp) and subscriber (rsp)."""
    deadline = time.monotonic() + timeout
    while node.count_publishers("/arm/joint_states") < 1 or node.count_subscribers("/arm/joint_states") < 1:
        if time.monotonic() > deadline or proc.popen.poll() is not None:
            pytest.fail(f"/arm/joint_states: {node.count_publishers('/arm/joint_states')} publishers, "
                        f"{node.count_subscribers('/arm/joint_states')} subscribers within {timeout} s\n"
                        + "\n".join(proc.err[-20:]))
        time.sleep(0.05)


def only_remapped(node: Node, *unused: str) -> None:
    for topic in unused:
        assert (node.count_publishers(topic), node.count_subscribers(topic)) == (0, 0), topic


def test_ros1_remaps_in_node_and_group_route_joint_states(live, pkg):
    path = pkg.launch("remapped.launch", """
        <launch>
          <param name="robot_description"
                 command="$(find xacro)/xacro $(find probe_description)/urdf/probe.urdf.xacro"/>
          <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp">
            <remap from="joint_states" to="/arm/joint_states"/>
            <rosparam param="zeros">{shoulder: 0.5}</rosparam>
          </node>
          <group>
            <remap from="joint_states" to="/arm/joint_states"/>
            <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
          </group>
        </launch>
    """)
    proc = launch(live, str(path), "--package-path", str(pkg.root))
    pids = started(proc, 2)
    with Node("launch_probe") as node:
        wait_graph(node, proc)
        only_remapped(node, "/joint_states")
        buffer = Buffer()
        with TransformListener(buffer):
            xyz, _ = wait_value(buffer, "base_link", "tool", TOOL)
            assert np.allclose(xyz, TOOL, atol=1e-9)
        only_remapped(node, "/joint_states")
    assert proc.stop(signal.SIGTERM) == 0
    wait_gone(pids.values(), timeout=1.0)


def test_ros2_set_remap_node_remap_name_namespace_and_params_file(live, pkg):
    config = pkg.dir / "config" / "jsp.yaml"
    config.parent.mkdir()
    # Reaches the node only under its launch-given name and namespace (/r2/my_jsp).
    config.write_text("/r2/my_jsp:\n  ros__parameters:\n    zeros:\n      shoulder: 0.5\n")
    path = pkg.launch("remapped.launch.xml", """
        <launch>
          <let name="model" value="$(find-pkg-share probe_description)/urdf/probe.urdf.xacro"/>
          <group>
            <push-ros-namespace namespace="r2"/>
            <node pkg="joint_state_publisher" exec="joint_state_publisher" name="my_jsp" args="$(var model)">
              <param from="$(find-pkg-share probe_description)/config/jsp.yaml"/>
              <remap from="joint_states" to="/arm/joint_states"/>
            </node>
            <set_remap from="joint_states" to="/arm/joint_states"/>
            <node pkg="robot_state_publisher" exec="robot_state_publisher" name="my_rsp">
              <param name="robot_description" value="$(command 'xacro $(var model)')"/>
            </node>
          </group>
        </launch>
    """)
    proc = launch(live, str(path), "--package-path", str(pkg.root))
    pids = started(proc, 2)
    assert sorted(pids) == ["r2/my_jsp-1", "r2/my_rsp-2"]
    with Node("launch_probe") as node:
        wait_graph(node, proc)
        only_remapped(node, "/joint_states", "/r2/joint_states")
        buffer = Buffer()
        with TransformListener(buffer):
            xyz, _ = wait_value(buffer, "base_link", "tool", TOOL)
            assert np.allclose(xyz, TOOL, atol=1e-9)
        only_remapped(node, "/joint_states", "/r2/joint_states")
    assert proc.stop(signal.SIGINT) == 0
    wait_gone(pids.values(), timeout=1.0)
