"""``robotmodel topic pub`` on the DDS wire, received by the real rclpy (Jazzy, Fast DDS)."""

from __future__ import annotations

import json
from typing import Any

from rclpyside import DEADLINE_S


def test_topic_pub_once_reaches_a_real_rclpy_subscription(rclpy: Any, procs: Any, bus_wire: str) -> None:
    assert bus_wire == "dds"
    listener = rclpy("joint_listener")
    pub = procs.cli("topic", "pub", "--once", "/joint_states", "sensor_msgs/msg/JointState",
                    "{name: [arm_elbow_joint], position: [0.25]}")
    assert pub.popen.wait(DEADLINE_S) == 0, pub.errors
    got = listener.wait_line("got ", timeout=DEADLINE_S)
    assert json.loads(got[len("got "):]) == [["arm_elbow_joint"], [0.25]]
    assert "publisher: beginning loop" in pub.lines
