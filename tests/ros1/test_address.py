"""Where a node advertises and binds: as ROS 1 picks the host, and never 0.0.0.0 unless asked."""

from __future__ import annotations

import pytest

from robotmodel.errors import Ros1Error
from robotmodel.ros1 import address_override, node_address


def test_local_master_without_overrides_is_loopback() -> None:
    for uri in ("http://localhost:11311", "http://127.0.0.1:11411/", "http://127.0.1.1:11311"):
        address = node_address(uri, env={})
        assert (address.host, address.bind) == ("127.0.0.1", "127.0.0.1")


def test_ros_hostname_then_ros_ip_then_args() -> None:
    assert node_address("http://localhost:11311", env={"ROS_HOSTNAME": "localhost"}).bind == "127.0.0.1"
    both = {"ROS_HOSTNAME": "127.0.0.2", "ROS_IP": "127.0.0.3"}
    assert node_address("http://localhost:11311", env=both).host == "127.0.0.2"  # ROS_HOSTNAME wins, as in rosgraph
    assert node_address("http://localhost:11311", env={"ROS_IP": "127.0.0.3"}).bind == "127.0.0.3"
    assert address_override(["__ip:=127.0.0.4"], env=both) == "127.0.0.4"
    assert address_override([], env={}) is None


def test_bind_all_only_when_asked() -> None:
    assert node_address("http://localhost:11311", env={}, bind_all=True).bind == "0.0.0.0"
    assert node_address("http://localhost:11311", env={"ROS_IP": "127.0.0.5"}).bind != "0.0.0.0"


@pytest.mark.parametrize(("env", "text"), [
    ({"ROS_HOSTNAME": ""}, "invalid ROS_HOSTNAME (an empty string)"),
    ({"ROS_HOSTNAME": "http://host"}, "invalid ROS_HOSTNAME (protocol should not be included)"),
    ({"ROS_IP": "10.0.0.1:5"}, "invalid ROS_IP (port should not be included)"),
])
def test_bad_overrides_use_ros_wording(env: dict[str, str], text: str) -> None:
    with pytest.raises(Ros1Error) as info:
        node_address("http://localhost:11311", env=env)
    assert str(info.value) == text
