"""``topic echo``'s printing forms as ros2 topic echo (rosidl_runtime_py): --csv, --no-arr, --no-str, -i, --filter.

Expected texts are worked out by hand from rosidl_runtime_py's rules (fields in message
order, sequences comma-joined in CSV, an array field replaced by ``<array type: T[N]>`` or
``<sequence type: T, length: L>`` with rosidl's IDL type names, a string by ``<string
length: <L>>``); the IDL names of every field of three message types are checked against
Jazzy's own rosidl_parser reading of the real messages where .venv-rclpy has them.
"""

from __future__ import annotations

import itertools
import json
import os
import subprocess
import threading
from pathlib import Path
from typing import Any

import pytest

from robotmodel.bus import Node
from robotmodel.msgs import typestore
from robotmodel.topic import message_to_csv, message_to_yaml
from robotmodel.topic._convert import _abbreviated

ROOT = Path(__file__).resolve().parents[2]
DEADLINE_S = 40.0
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(ROOT / ".venv-rclpy" / "bin" / "python")))


def _joint_state() -> Any:
    store = typestore()
    js = store.types["sensor_msgs/msg/JointState"]
    header = store.types["std_msgs/msg/Header"](store.types["builtin_interfaces/msg/Time"](1, 2), "base")
    import numpy as np

    return js(header, ["a", "b"], np.array([0.5, 1.5]), np.array([], dtype=float), np.array([], dtype=float))


def test_csv_no_arr_and_no_str_as_rosidl_runtime_py() -> None:
    msg = _joint_state()
    assert message_to_csv(msg) == "1,2,base,a,b,0.5,1.5,,"
    assert message_to_csv(msg, 1) == "1,2,b...,a,...,0.5,...,,"  # strings and sequences cut after 1
    assert message_to_csv(msg, no_arr=True) == ("1,2,base,<sequence type: string, length: 2>,<sequence type: double, "
                                                "length: 2>,<sequence type: double, length: 0>,<sequence type: double, "
                                                "length: 0>")
    assert message_to_csv(msg, no_str=True) == ("1,2,<string length: <4>>,<string length: <1>>,<string length: <1>>,"
                                                "0.5,1.5,,")
    assert message_to_yaml(msg, no_arr=True, no_str=True).splitlines() == [
        "header:", "  stamp:", "    sec: 1", "    nanosec: 2", "  frame_id: '<string length: <4>>'",
        "name: '<sequence type: string, length: 2>'", "position: '<sequence type: double, length: 2>'",
        "velocity: '<sequence type: double, length: 0>'", "effort: '<sequence type: double, length: 0>'"]
    pose = typestore().types["geometry_msgs/msg/PoseWithCovariance"]
    fixed = message_to_yaml(pose(typestore().types["geometry_msgs/msg/Pose"](
        typestore().types["geometry_msgs/msg/Point"](0, 0, 0),
        typestore().types["geometry_msgs/msg/Quaternion"](0, 0, 0, 1)), __import__("numpy").zeros(36)), no_arr=True)
    assert fixed.splitlines()[-1] == "covariance: '<array type: double[36]>'"


def test_idl_type_names_are_rosidl_parsers() -> None:
    """Every array field of three message types abbreviated as Jazzy's rosidl_parser names its type."""
    if not RCLPY.exists():
        pytest.skip(f"no real rclpy at {RCLPY} (run .ci/rclpy-venv)")
    types = ["sensor_msgs/msg/JointState", "sensor_msgs/msg/CameraInfo", "geometry_msgs/msg/PoseWithCovariance"]
    script = """
import importlib, json, sys
import rosidl_parser.definition as d
def name(t):
    if isinstance(t, d.BasicType): return t.typename
    if isinstance(t, d.AbstractString): return 'string'
    if isinstance(t, d.NamespacedType): return '/'.join(t.namespaced_name())
    return 'unknown'
out = {}
for full in sys.argv[1:]:
    pkg, _, cls = full.split('/')
    msg = getattr(importlib.import_module(pkg + '.msg'), cls)
    for field, t in zip(msg.get_fields_and_field_types(), msg.SLOT_TYPES):
        if isinstance(t, d.Array):
            out[full + '.' + field] = ['array', name(t.value_type), t.size]
        elif isinstance(t, d.AbstractSequence):
            out[full + '.' + field] = ['sequence', name(t.value_type), getattr(t, 'maximum_size', 0)]
print(json.dumps(out))
"""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))}
    done = subprocess.run([str(RCLPY), "-c", script, *types], capture_output=True, text=True, timeout=120,
                          check=True, env=env)
    theirs = json.loads(done.stdout)
    store = typestore()
    ours = {}
    for full in types:
        for field, spec in store.fielddefs[full][1]:
            if spec[0] in (3, 4):
                text = _abbreviated([0, 0], spec)
                kind = "array" if text.startswith("<array") else "sequence"
                element = text.split("type: ", 1)[1].split("[", 1)[0].split(",", 1)[0].rstrip(">")
                ours[f"{full}.{field}"] = [kind, element, spec[1][1]]
    assert ours == theirs and len(ours) >= 8


def test_live_echo_csv_with_filter_and_message_info(procs: Any, bus_wire: str) -> None:
    """``--csv -i --filter`` on a live topic: only the 'b' messages, each line info fields first."""
    from robotmodel.msgs.std_msgs import String

    stop = threading.Event()
    with Node("echo_source") as node:
        pub = node.create_publisher(String, "/echo_forms", 10)

        def loop() -> None:
            tick = 0
            while not stop.wait(0.05):  # publishing pace, not a wait for a condition
                pub.publish(String(data="ab"[tick % 2] + str(tick)))
                tick += 1

        thread = threading.Thread(target=loop, daemon=True)
        thread.start()
        try:
            # rostopic's -n: three printed, then it exits by itself.
            echo = procs.cli("rostopic", "echo", "/echo_forms", "--csv", "-i", "--filter", "m.data.startswith('b')",
                             "-n", "3", "--spin-time", "1")
            assert echo.popen.wait(DEADLINE_S) == 0, echo.errors
            assert echo.wait_for(lambda ls: len(ls) >= 3, 5), echo.errors
        finally:
            stop.set()
            thread.join(5)
    assert len(echo.lines) == 3, echo.lines
    rows = [line.split(",") for line in echo.lines]
    for source, received, published, reception, data in rows:
        assert data.startswith("b") and int(data[1:]) % 2 == 1, rows
        assert 0 < int(source) <= int(received) and int(published) > 0 and int(reception) > 0
    # Every other message is printed: both sequence numbers (the sender's and the reader's) step by 2.
    for column in (2, 3):
        numbers = [int(row[column]) for row in rows]
        assert [b - a for a, b in itertools.pairwise(numbers)] == [2, 2], rows
