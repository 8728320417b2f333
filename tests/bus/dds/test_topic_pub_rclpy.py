"""``robotmodel topic pub`` on the DDS wire, received by the real rclpy (Jazzy, Fast DDS)."""

from __future__ import annotations

import json
from typing import Any

from rclpyside import DEADLINE_S


def test_topic_pub_once_reaches_a_real_rclpy_subscription(rclpy: Any, procs: Any, bus_wire: str) -> None:
    assert bus_wire == "dds"
    listener = rclpy("joint_listener")
    # --keep-alive 2 rather than ros2's 0.1 s: once our writer sees the reader, Fast DDS's side may not
    # yet have matched it, and a writer gone after 0.1 s leaves nobody to repeat the sample (one run
    # of the first three here lost it on the loaded machine; ros2 topic pub --once has the same window).
    pub = procs.cli("topic", "pub", "--once", "--keep-alive", "2", "/joint_states", "sensor_msgs/msg/JointState",
                    "{name: [arm_elbow_joint], position: [0.25]}")
    assert pub.popen.wait(DEADLINE_S) == 0, pub.errors
    got = listener.wait_line("got ", timeout=DEADLINE_S)
    assert json.loads(got[len("got "):]) == [["arm_elbow_joint"], [0.25]]
    assert "publisher: beginning loop" in pub.lines
