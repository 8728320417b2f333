"""The demo's private bus stays zenoh on its own port whatever the user's shell sourced."""

from __future__ import annotations

import pytest

from robotmodel.bus import default_wire
from robotmodel.demo._run import private_bus_env


@pytest.mark.parametrize("sourced", [
    {"ROS_VERSION": "1", "ROS_MASTER_URI": "http://127.0.0.1:11311"},   # a sourced ROS 1
    {"RMW_IMPLEMENTATION": "rmw_fastrtps_cpp", "ROS_VERSION": "2"},     # a stock ROS 2
    {"ZENOH_SESSION_CONFIG_URI": "/nonexistent.json5", "ZENOH_CONFIG_OVERRIDE": "mode=\"client\""},
])
def test_the_demo_children_stay_on_a_private_zenoh_bus(monkeypatch: pytest.MonkeyPatch,
                                                        sourced: dict[str, str]) -> None:
    for key, value in sourced.items():
        monkeypatch.setenv(key, value)
    env = private_bus_env()
    assert default_wire(env) == "zenoh"
    assert not {"ROS_MASTER_URI", "ZENOH_SESSION_CONFIG_URI", "ZENOH_CONFIG_OVERRIDE"} & set(env)
    assert int(env["ROBOTMODEL_ZENOH_PORT"]) > 0 and 0 < int(env["ROS_DOMAIN_ID"]) <= 232
