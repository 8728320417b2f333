"""robotmodel.rclpy's Node on the in-process wire: QoS profiles, rates, and the parameter services end to end.

Each case has its own context (passed everywhere), so nothing leaks between tests. The
parameter services' answers are those Jazzy's rclpy gives to the same calls from its own
AsyncParameterClient (run once in .venv-rclpy on Fast DDS: the types, the empty answers for
an unknown name, the range text, the declaration order with start_type_description_service).
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

import pytest

from robotmodel.bus import Durability, Reliability
from robotmodel.msgs import String
from robotmodel.msgs.rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from robotmodel.rclpy.context import Context
from robotmodel.rclpy.executors import SingleThreadedExecutor
from robotmodel.rclpy.node import Node
from robotmodel.rclpy.parameter import Parameter
from robotmodel.rclpy.parameter_client import AsyncParameterClient
from robotmodel.rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data, to_bus_qos

DEADLINE_S = 20.0


@pytest.fixture
def context() -> Iterator[Context]:
    ctx = Context()
    ctx.init([], backend="inprocess", domain_id=62)
    yield ctx
    ctx.try_shutdown()


def test_qos_profiles_and_a_latched_topic(context: Context) -> None:
    sensor = to_bus_qos(qos_profile_sensor_data)
    assert (sensor.depth, sensor.reliability) == (5, Reliability.BEST_EFFORT)
    with pytest.raises(ValueError, match="KEEP_LAST requires a depth"):
        QoSProfile()
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    assert to_bus_qos(latched).durability is Durability.TRANSIENT_LOCAL
    talker = Node("talker", context=context)
    talker.create_publisher(String, "/latched", latched).publish(String(data="kept"))
    listener = Node("late", context=context)
    got: list[str] = []
    listener.create_subscription(String, "/latched", lambda m: got.append(m.data), latched)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(listener)
    executor.spin_once(timeout_sec=DEADLINE_S)
    assert got == ["kept"]


def test_rate_sleeps_its_period(context: Context) -> None:
    node = Node("looper", context=context)
    rate = node.create_rate(20.0)
    start = time.monotonic()
    for _ in range(4):
        rate.sleep()
    assert time.monotonic() - start >= 0.19  # four periods of 50 ms, the first one whole


def call(executor: SingleThreadedExecutor, future: Any) -> Any:
    executor.spin_until_future_complete(future, DEADLINE_S)
    assert future.done()
    return future.result()


def test_parameter_services_describe_type_get_and_set_atomically(context: Context) -> None:
    server = Node("tuned", context=context)
    server.declare_parameter("gain", 0.5, ParameterDescriptor(
        description="loop gain", floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0, step=0.0)]))
    server.declare_parameter("names", ["a", "b"])
    client_node = Node("tuner", context=context)
    client = AsyncParameterClient(client_node, "tuned")
    assert client.wait_for_services(DEADLINE_S)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(server)  # the server's services run in its executor, as rclpy's
    executor.add_node(client_node)
    described = call(executor, client.describe_parameters(["gain"])).descriptors[0]
    assert (described.name, described.type, described.description) == ("gain", 3, "loop gain")
    assert call(executor, client.get_parameter_types(["gain", "names"])).types == [3, 9]
    assert call(executor, client.get_parameter_types(["gain", "absent"])).types == []  # rclpy: none if one is unknown
    assert call(executor, client.get_parameters(["names"])).values[0].string_array_value == ["a", "b"]
    assert call(executor, client.get_parameters(["names", "absent"])).values == []  # rclpy: none if one is unknown
    result = call(executor, client.set_parameters_atomically(
        [Parameter("gain", value=0.25), Parameter("names", value=["c"])])).result
    assert result.successful and server.get_parameter("gain").value == 0.25
    refused = call(executor, client.set_parameters_atomically(
        [Parameter("gain", value=2.0), Parameter("names", value=["d"])])).result
    assert not refused.successful and refused.reason == "Parameter gain out of range Min: 0.0, Max: 1.0, value: 2.0"
    assert server.get_parameter("names").value == ["c"]  # all or nothing
    listed = call(executor, client.list_parameters()).result
    assert listed.names == ["use_sim_time", "start_type_description_service", "gain", "names"]
    fixed = call(executor, client.describe_parameters(["start_type_description_service"])).descriptors[0]
    assert (fixed.type, fixed.read_only) == (1, True)
