"""A display launch serves two pages (the sliders and rviz's stand-in): each URL line says which it is."""

from __future__ import annotations

import re
import signal
import sys

_DISPLAY = """
    <launch>
      <param name="robot_description" command="$(find xacro)/xacro $(find probe_description)/urdf/probe.urdf.xacro"/>
      <node name="joint_state_publisher" pkg="joint_state_publisher_gui" type="joint_state_publisher_gui"/>
      <node name="robot_state_publisher" pkg="robot_state_publisher" type="robot_state_publisher"/>
      <node name="rviz" pkg="rviz" type="rviz"/>
    </launch>
"""


def test_each_page_url_names_its_page(live, pkg):
    path = pkg.launch("display.launch", _DISPLAY)
    proc = live.start(sys.executable, "-m", "robotmodel.cli.main", "launch", "--no-browser", str(path),
                      "--package-path", str(pkg.root))
    try:
        proc.wait_for(lambda: sum(line.startswith("http://") for line in proc.out) >= 2, 90, "two page URLs")
        lines = sorted(line for line in proc.out if line.startswith("http://"))
        pages = [re.fullmatch(r"http://127\.0\.0\.1:(\d+)/ \((\w+): (.+)\)", line) for line in lines]
        assert all(pages), lines
        described = {m.group(2): m.group(3) for m in pages}
        assert described == {"joint_state_publisher": "sliders publishing /joint_states",
                             "rviz": "the robot following /joint_states"}
        assert len({m.group(1) for m in pages}) == 2  # each on its own port
    finally:
        assert proc.stop(signal.SIGINT) == 0
