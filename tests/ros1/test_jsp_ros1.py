"""robotmodel's joint_state_publisher on ROS 1 reads its settings from the parameter server as Debian's does.

Debian's joint_state_publisher (1.15.1) and ours run side by side, each in its own namespace
with the same parameters: private ones (``_rate:=`` on the command line, ``~zeros``), the
namespace's where the private one is unset (``zeros/JOINT``, ``publish_default_velocities``,
``source_list``, ``dependent_joints``). A rospy reader compares their messages field by field, and their rates.
"""

from __future__ import annotations

import itertools
import json
import statistics
import sys
from pathlib import Path

from ros1helpers import SYSTEM_PYTHON, Ros1World, wait_until

from robotmodel.model import load

HERE = Path(__file__).resolve().parent
ARM = HERE.parent.parent / "urdf" / "arm.urdf.xacro"
REAL_JSP = "/usr/lib/joint_state_publisher/joint_state_publisher"


def _messages(lines: list[str], topic: str) -> list[tuple[int, list[list[object]]]]:
    found = []
    for line in lines[1:]:
        name, stamp, fields = line.split(" ", 2)
        if name == topic:
            found.append((int(stamp), json.loads(fields)))
    return found


def test_jsp_settings_from_the_server_as_the_real_jsp(ros1: Ros1World) -> None:
    params = ros1.node("setter").params
    for ns, node in (("/real", "joint_state_publisher"), ("/ours", "joint_state_publisher")):
        params.set_param(f"{ns}/robot_description", load(ARM).source_text)
        params.set_param(f"{ns}/{node}/zeros", {"arm_elbow_joint": 1.1, "arm_wrist_roll_joint": 0.0})
        params.set_param(f"{ns}/zeros", {"arm_shoulder_joint": -0.7, "arm_elbow_joint": 5.0})
        params.set_param(f"{ns}/publish_default_velocities", True)
        params.set_param(f"{ns}/source_list", ["/extra_states"])
        params.set_param(f"{ns}/dependent_joints", {"arm_wrist_yaw_joint": {"parent": "arm_elbow_joint", "factor": 2.0,
                                                                            "offset": 0.1}})
    echo = ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_joint_echo.py"), "/real/joint_states", "/ours/joint_states")
    echo.wait_line("^ready", 60)
    ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_joint_states.py"), "/extra_states", "arm_base_joint=0.3")
    ros1.start(SYSTEM_PYTHON, REAL_JSP, "__ns:=/real", "_rate:=40")
    ros1.env["ROS_VERSION"] = "1"
    ros1.start(sys.executable, "-m", "robotmodel.cli.main", "joint_state_publisher", "__ns:=/ours", "_rate:=40")

    def merged(topic: str) -> list[tuple[int, list[list[object]]]]:
        return [m for m in _messages(echo.lines, topic) if 0.3 in m[1][1]]  # the source's value is in

    wait_until(lambda: len(merged("/real/joint_states")) > 20 and len(merged("/ours/joint_states")) > 20, 60,
               "twenty merged messages from each")
    real, ours = merged("/real/joint_states"), merged("/ours/joint_states")
    assert ours[-1][1] == real[-1][1], (ours[-1][1], real[-1][1])
    names, positions, velocities, _ = real[-1][1]
    value = dict(zip(names, positions, strict=True))  # type: ignore[call-overload]
    # private over the namespace's, a zero as unset (the middle of the limits when 0 is outside)
    assert value["arm_elbow_joint"] == 1.1 and value["arm_shoulder_joint"] == -0.7 and velocities
    assert value["arm_wrist_yaw_joint"] == 1.1 * 2.0 + 0.1  # dependent_joints: follows the elbow
    rates = [statistics.median(b[0] - a[0] for a, b in itertools.pairwise(ms)) / 1e9 for ms in (real, ours)]
    assert abs(rates[1] - 1 / 40) < 0.01 and abs(rates[0] - 1 / 40) < 0.01, rates


def test_gui_reads_its_settings_from_the_server(ros1: Ros1World) -> None:
    """joint_state_publisher_gui on ROS 1: named as ROS's, its robot, ``~zeros`` (the sliders' start) and
    ``~rate`` from the parameter server, as the GUI's joint_state_publisher inside it reads them."""
    params = ros1.node("setter").params
    params.set_param("/robot_description", load(ARM).source_text)
    params.set_param("/joint_state_publisher_gui/zeros", {"arm_elbow_joint": 0.7})
    params.set_param("/joint_state_publisher_gui/rate", 20)
    echo = ros1.start(SYSTEM_PYTHON, str(HERE / "rospy_joint_echo.py"), "/joint_states")
    echo.wait_line("^ready", 60)
    ros1.env["ROS_VERSION"] = "1"
    ros1.start(sys.executable, "-m", "robotmodel.cli.main", "joint_state_publisher_gui", "--port", "0")
    wait_until(lambda: len(_messages(echo.lines, "/joint_states")) > 15, 60, "fifteen messages from the GUI")
    got = _messages(echo.lines, "/joint_states")
    names, positions, _, _ = got[-1][1]
    assert dict(zip(names, positions, strict=True))["arm_elbow_joint"] == 0.7  # type: ignore[call-overload]
    rate = statistics.median(b[0] - a[0] for a, b in itertools.pairwise(got)) / 1e9
    assert abs(rate - 1 / 20) < 0.01, rate
    assert "/joint_state_publisher_gui" in ros1.tool("rosnode", "list").split()
