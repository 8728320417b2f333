"""``robotmodel launch`` of a ROS 1 display.launch (urdf_tutorial's shape) on a real roscore.

As roslaunch: robot_description (xacro's output) and the other <param>s go to the parameter
server before the nodes start (read back with the real ``rosparam get``), robot_state_publisher
and joint_state_publisher read the robot there, and the real ``rostopic echo /tf`` sees the
robot's moving joints.
"""

from __future__ import annotations

import signal
import sys
from pathlib import Path

import yaml
from ros1helpers import Ros1World, wait_until

from robotmodel.model import load

ARM = Path(__file__).resolve().parent.parent.parent / "urdf" / "arm.urdf.xacro"
DISPLAY = """<launch>
  <arg name="model" default="{model}"/>
  <arg name="gui" default="false"/>
  <param name="robot_description" command="$(find xacro)/xacro $(arg model)"/>
  <param name="use_gui" value="$(arg gui)"/>
  <node name="joint_state_publisher" pkg="joint_state_publisher" type="joint_state_publisher"/>
  <node name="robot_state_publisher" pkg="robot_state_publisher" type="robot_state_publisher">
    <param name="publish_frequency" value="30"/>
  </node>
</launch>
"""


def test_launch_of_a_ros1_display_launch_sets_the_parameter_server_and_publishes_tf(ros1: Ros1World,
                                                                                    tmp_path: Path) -> None:
    launch_file = tmp_path / "display.launch"
    launch_file.write_text(DISPLAY.format(model=ARM), encoding="utf-8")
    ros1.env["ROS_VERSION"] = "1"
    launch = ros1.start(sys.executable, "-m", "robotmodel.cli.main", "launch", str(launch_file))
    wait_until(lambda: "pub /tf" in ros1.registrations_of("/robot_state_publisher"), 60, "RSP's /tf")
    desc = load(ARM)
    got = ros1.tool("rosparam", "get", "/robot_description")
    assert yaml.safe_load(got) == desc.source_text, got[:200]
    assert ros1.tool("rosparam", "get", "/use_gui").strip() == "false"
    assert ros1.tool("rosparam", "get", "/robot_state_publisher/publish_frequency").strip() == "30"
    echoed = ros1.tool("rostopic", "echo", "-n", "1", "/tf")
    moving = {j.child for j in desc.joints if j.type.value in ("revolute", "continuous", "prismatic")}
    children = {line.split(":", 1)[1].strip().strip('"') for line in echoed.splitlines()
                if line.strip().startswith("child_frame_id:")}
    assert children and children <= moving, echoed
    launch.kill(signal.SIGINT)
