"""``robotmodel topic list|echo`` against live processes, and the YAML as ros2 topic echo prints it."""

from __future__ import annotations

from typing import Any

import numpy as np

from robotmodel.bus import typestore
from robotmodel.topic import message_to_yaml

# ros2 topic echo of tests/bus/peer.py's static-pub message (rosidl_runtime_py's
# message_to_yaml: PyYAML block style, fields in message order, sequences not indented).
STATIC_YAML = """\
transforms:
- header:
    stamp:
      sec: 0
      nanosec: 0
    frame_id: world
  child_frame_id: base
  transform:
    translation:
      x: 1.0
      y: 0.0
      z: 0.0
    rotation:
      x: 0.0
      y: 0.0
      z: 0.0
      w: 1.0
- header:
    stamp:
      sec: 0
      nanosec: 0
    frame_id: base
  child_frame_id: camera
  transform:
    translation:
      x: 0.0
      y: 0.0
      z: 0.5
    rotation:
      x: 0.0
      y: 0.0
      z: 0.0
      w: 1.0
---
"""


def test_topic_list_shows_the_latched_topic(procs: Any) -> None:
    procs.peer("static-pub").wait_line("ready")
    # 3 s of discovery rather than ros2's 0.5 s default: the graph query is slow on a loaded machine.
    plain = procs.cli("topic", "list", "--spin-time", "3")
    assert plain.popen.wait(30) == 0, plain.errors
    assert plain.wait_for(lambda ls: "/tf_static" in ls, 2), plain.lines
    typed = procs.cli("topic", "list", "-t", "--spin-time", "3")
    assert typed.popen.wait(30) == 0
    assert typed.wait_for(lambda ls: "/tf_static [tf2_msgs/msg/TFMessage]" in ls, 2), typed.lines
    count = procs.cli("topic", "list", "-c", "--spin-time", "3")
    assert count.popen.wait(30) == 0
    assert count.wait_for(lambda ls: ls == ["1"], 2), count.lines


def test_topic_echo_once_prints_ros2_yaml(procs: Any) -> None:
    procs.peer("static-pub").wait_line("ready")
    # Discovery runs its whole --spin-time (0.5 s by default, as ros2's): enough for a loaded machine.
    echo = procs.cli("topic", "echo", "/tf_static", "--once", "--spin-time", "3")
    assert echo.popen.wait(30) == 0, echo.errors
    echo.wait_for(lambda ls: "---" in ls, 2)
    assert "\n".join(echo.lines) + "\n" == STATIC_YAML


def test_topic_echo_field(procs: Any) -> None:
    procs.peer("static-pub").wait_line("ready")
    echo = procs.cli("topic", "echo", "/tf_static", "tf2_msgs/msg/TFMessage", "--once", "--spin-time", "3",
                     "--field", "transforms")
    assert echo.popen.wait(30) == 0, echo.errors
    echo.wait_for(lambda ls: "---" in ls, 2)
    assert echo.lines[0] == "- header:"


def test_topic_echo_with_a_type_discovers_the_latched_publisher_first(procs: Any) -> None:
    # With the type given there is nothing to look up, but the QoS still follows the publishers:
    # echoes started together, right after the publisher, each get its one latched message (they
    # subscribed volatile whenever their new session's graph did not show the publisher yet).
    procs.peer("static-pub").wait_line("ready")
    echoes = [procs.cli("topic", "echo", "/tf_static", "tf2_msgs/msg/TFMessage", "--once", "--spin-time", "3",
                        "--field", "transforms") for _ in range(4)]
    for echo in echoes:
        assert echo.wait_for(lambda ls: "---" in ls, 60), (echo.lines, echo.errors[-5:])
        assert echo.popen.wait(30) == 0, echo.errors
        assert echo.lines[0] == "- header:"


def test_topic_echo_unknown_topic_says_what_ros2_says(procs: Any) -> None:
    echo = procs.cli("topic", "echo", "/nothing_here", "--spin-time", "0.3")
    assert echo.popen.wait(30) == 1
    echo.wait_for(bool, 2, stream="stderr")
    assert echo.lines == ["WARNING: topic [/nothing_here] does not appear to be published yet"]
    assert echo.errors == ["robotmodel topic: error: Could not determine the type for the passed topic"]


def test_yaml_of_arrays_strings_and_truncation() -> None:
    store = typestore()
    JointState = store.types["sensor_msgs/msg/JointState"]
    Header = store.types["std_msgs/msg/Header"]
    Time = store.types["builtin_interfaces/msg/Time"]
    msg = JointState(Header(Time(3, 4), ""), ["a", "b", "c"], np.array([0.5, 1e-05, -2.0]),
                     np.array([], dtype=np.float64), np.array([1.0, 2.0, 3.0]))
    assert message_to_yaml(msg) == (
        "header:\n  stamp:\n    sec: 3\n    nanosec: 4\n  frame_id: ''\n"
        "name:\n- a\n- b\n- c\n"
        "position:\n- 0.5\n- 1.0e-05\n- -2.0\n"
        "velocity: []\n"
        "effort:\n- 1.0\n- 2.0\n- 3.0\n")
    assert message_to_yaml(msg, truncate_length=2).splitlines()[5:9] == ["name:", "- a", "- b", "- '...'"]
    String = store.types["std_msgs/msg/String"]
    assert message_to_yaml(String("abcdef"), truncate_length=3) == "data: abc...\n"
    assert message_to_yaml(String("yes")) == "data: 'yes'\n"


def test_topic_echo_refuses_a_topic_of_two_types(procs: Any) -> None:
    from robotmodel.bus import Node, typestore

    store = typestore()
    with Node("two_types") as node:
        node.create_publisher(store.types["std_msgs/msg/String"], "/mixed")
        node.create_publisher(store.types["sensor_msgs/msg/JointState"], "/mixed")
        # Both types must be seen: the first publisher's token alone once made echo subscribe to it.
        echo = procs.cli("topic", "echo", "/mixed", "--spin-time", "3")
        assert echo.popen.wait(30) == 1
    echo.wait_for(bool, 2, stream="stderr")
    assert echo.errors == ["robotmodel topic: error: Cannot echo topic '/mixed', as it contains more than one type: "
                           "[sensor_msgs/msg/JointState, std_msgs/msg/String]"]
