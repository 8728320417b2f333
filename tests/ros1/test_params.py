"""The parameter server client against a real rosmaster, read back and written by the real rosparam."""

from __future__ import annotations

import pytest
import yaml
from ros1helpers import Ros1World, free_port, wait_until

from robotmodel.errors import MasterError
from robotmodel.ros1 import MasterClient, ParamClient

URDF = '<robot name="r"><link name="base"/></robot>'


def test_robotmodel_sets_rosparam_reads(ros1: Ros1World) -> None:
    params = ros1.node("rm_params").params
    params.set_param("/robot_description", URDF)
    params.set_param("/arm/gains", {"p": 2.5, "i": 0, "names": ["a", "b"], "on": True})  # a tree, as in ROS
    assert ros1.tool("rosparam", "get", "/robot_description").strip() == URDF
    gains = {"p": 2.5, "i": 0, "names": ["a", "b"], "on": True}
    assert yaml.safe_load(ros1.tool("rosparam", "get", "/arm/gains")) == gains


def test_rosparam_sets_robotmodel_reads(ros1: Ros1World) -> None:
    ros1.tool("rosparam", "set", "/from_ros", "[1, 2.5, hello]")
    ros1.tool("rosparam", "set", "/a/robot_description", URDF)
    node = ros1.node("rm_reader", namespace="/a/b")
    params = node.params
    assert params.get_param("/from_ros") == [1, 2.5, "hello"]
    assert params.has_param("/from_ros") and not params.has_param("/nope")
    # searched up the caller's namespace, as ROS 1 searches robot_description
    assert params.search_param("robot_description") == "/a/robot_description"
    assert params.search_param("absent_everywhere") is None
    assert {"/from_ros", "/a/robot_description"} <= set(params.get_param_names())
    params.delete_param("/from_ros")
    assert "/from_ros" not in ros1.tool("rosparam", "list").split()


def test_subscribe_param_sees_rosparam_set(ros1: Ros1World) -> None:
    node = ros1.node("rm_watcher")
    seen: list[tuple[str, object]] = []
    assert node.subscribe_param("/gain", lambda key, value: seen.append((key, value))) == {}
    ros1.tool("rosparam", "set", "/gain", "3")
    wait_until(lambda: ("/gain", 3) in seen, 30, "paramUpdate of /gain")
    node.unsubscribe_param("/gain")
    ros1.tool("rosparam", "set", "/gain", "4")
    assert ros1.tool("rosparam", "get", "/gain").strip() == "4"
    assert ("/gain", 4) not in seen


def test_failures_name_the_master(ros1: Ros1World) -> None:
    params = ParamClient(ros1.uri, "/rm")
    with pytest.raises(MasterError) as info:
        params.get_param("/nope")
    assert str(info.value) == f"master {ros1.uri}: getParam failed: Parameter [/nope] is not set"
    assert (info.value.code, info.value.method, info.value.master_uri) == (-1, "getParam", ros1.uri)


def test_unreachable_master_is_one_error_naming_it() -> None:
    uri = f"http://127.0.0.1:{free_port()}"
    with pytest.raises(MasterError) as info:
        MasterClient(uri, "/rm").get_system_state()
    assert str(info.value).startswith(f"master {uri} is unreachable (getSystemState): ")
    assert "refused" in str(info.value) and info.value.code is None
