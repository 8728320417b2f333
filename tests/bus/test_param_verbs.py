"""``robotmodel param describe|delete|load`` against robotmodel's robot_state_publisher (an rclcpp node's rules)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from conftest import BUNDLED

ARM = BUNDLED / "arm.urdf.xacro"
DEADLINE_S = 40.0


def test_describe_delete_load_on_robot_state_publisher(procs: Any, bus_wire: str, tmp_path: Path) -> None:
    assert bus_wire == "zenoh"
    rsp = procs.cli("robot-state-publisher", str(ARM))
    assert rsp.wait_for(lambda ls: any("Robot initialized" in ln for ln in ls), DEADLINE_S, "stderr"), rsp.errors

    def param(code: int, *args: str) -> tuple[list[str], list[str]]:
        proc = procs.cli("param", *args)
        assert proc.popen.wait(DEADLINE_S) == code, (proc.lines, proc.errors)
        proc.wait_for(lambda _: False, 0.1)  # the readers drain what is left
        return proc.lines, proc.errors

    # robot_state_publisher declares publish_frequency a double and ignore_timestamp a bool, with no constraints.
    out, _ = param(0, "describe", "/robot_state_publisher", "publish_frequency", "ignore_timestamp")
    assert out == ["Parameter name: publish_frequency", "  Type: double", "  Constraints:",
                   "Parameter name: ignore_timestamp", "  Type: boolean", "  Constraints:"]
    # rclcpp's check_parameters: NOT_SET is a wrong type for a statically typed parameter.
    _, err = param(1, "delete", "/robot_state_publisher", "publish_frequency")
    assert err == ["robotmodel param: error: Deleting parameter failed: Wrong parameter type, parameter "
                   "{publish_frequency} is of type {double}, setting it to {not set} is not allowed."]
    params = tmp_path / "rsp.yaml"
    params.write_text("/robot_state_publisher:\n  ros__parameters:\n    publish_frequency: 40.0\n    frame_prefix: 5\n"
                      "/**:\n  ros__parameters:\n    ignore_timestamp: true\n")
    out, err = param(1, "load", "/robot_state_publisher", str(params))
    # The /** section first; each value typed from its text (5 an integer, refused for a string parameter).
    assert out == ["Set parameter ignore_timestamp successful", "Set parameter publish_frequency successful"]
    assert err == ["Set parameter frame_prefix failed: Wrong parameter type, parameter {frame_prefix} is of type "
                   "{string}, setting it to {integer} is not allowed."]
    out, _ = param(0, "get", "/robot_state_publisher", "publish_frequency")
    assert out == ["Double value is: 40.0"]
