"""``robotmodel param list|get|set|dump`` on the DDS wire against a real rclpy node (Jazzy, Fast DDS).

The node's parameters and their values are what the rclpy node reports through its own
``get_parameters``; the output forms are ros2cli's. Our client calls rmw_fastrtps_cpp's
parameter services with bare requests and pairs the bare replies in order
(robotmodel/bus/_dds_service.py); before that, every call here got no answer.
"""

from __future__ import annotations

import json
from typing import Any

import yaml
from rclpyside import DEADLINE_S

NODE = "/rclpy_params"


def _params(peer: Any) -> dict[str, list[Any]]:
    line = peer.wait_line("params ", timeout=DEADLINE_S)
    reported: dict[str, list[Any]] = json.loads(line[len("params "):])
    return reported


def _param(procs: Any, *args: str) -> list[str]:
    proc = procs.cli("param", *args)
    assert proc.popen.wait(DEADLINE_S) == 0, proc.errors
    proc.wait_for(lambda _: False, 0.1)  # the readers drain what is left
    return list(proc.lines)


def test_param_list_and_dump_show_what_the_rclpy_node_reports(rclpy: Any, procs: Any) -> None:
    params = _params(rclpy("params"))
    assert _param(procs, "list", NODE) == [f"{NODE}:", *(f"  {name}" for name in sorted(params))]
    dumped = yaml.safe_load("\n".join(_param(procs, "dump", NODE)))
    assert dumped == {NODE: {"ros__parameters": {name: value for name, (_type, value) in params.items()}}}


def test_param_set_then_get_on_a_real_rclpy_node(rclpy: Any, procs: Any) -> None:
    peer = rclpy("params")
    params = _params(peer)
    value = params["id"][1] + 5
    assert _param(procs, "set", NODE, "id", str(value)) == ["Set parameter successful"]
    assert json.loads(peer.wait_line("set ", timeout=DEADLINE_S)[len("set "):]) == [["id", value]]
    # ros2param's words; the request for a name this short is 16 bytes or less.
    assert _param(procs, "get", NODE, "id") == [f"Integer value is: {value}"]


def test_param_get_prints_arrays_as_ros2param_does(rclpy: Any, procs: Any) -> None:
    """ros2param prints the message field itself: ``array('q', [3, 4])`` for integers, a list for strings."""
    peer = rclpy("params")
    shown = json.loads(peer.wait_line("shown ", timeout=DEADLINE_S)[len("shown "):])
    words = {"ids": "Integer values are", "gains": "Double values are", "joints": "String values are"}
    for name, label in words.items():
        assert _param(procs, "get", NODE, name) == [f"{label}: {shown[name]}"]
    assert _param(procs, "get", NODE, "ids", "--hide-type") == [shown["ids"]]
