"""robotmodel.rclpy's executors: when callbacks run, and whether two can run at once (in-process wire).

Each case has its own context (``Context()`` passed everywhere, as rclpy allows), so no
global state leaks between tests. Overlap is measured by the callbacks themselves: each one
counts itself in, then waits (with a deadline) for the other to be in too; the peak count
says whether two ever ran at once. Two publishing threads deliver at the same moment on the
in-process wire (it delivers in the publisher's thread), which is what makes the bus's own
callbacks overlap.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

import pytest

from robotmodel import rclpy
from robotmodel.bus import Node as BusNode
from robotmodel.msgs import String
from robotmodel.rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from robotmodel.rclpy.context import Context
from robotmodel.rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, SingleThreadedExecutor
from robotmodel.rclpy.node import Node

# How long a callback waits for the other to join it: the answer when they never overlap.
JOIN_S = 0.4
DEADLINE_S = 20.0


class Overlap:
    """Callbacks that record how many of them ran at once."""

    def __init__(self) -> None:
        self._cond = threading.Condition()
        self.active = 0
        self.peak = 0
        self.done = 0

    def __call__(self, _msg: Any) -> None:
        with self._cond:
            self.active += 1
            self.peak = max(self.peak, self.active)
            self._cond.notify_all()
            self._cond.wait_for(lambda: self.peak >= 2, JOIN_S)
            self.active -= 1
            self.done += 1
            self._cond.notify_all()

    def wait_done(self, count: int) -> None:
        with self._cond:
            assert self._cond.wait_for(lambda: self.done >= count, DEADLINE_S), f"{self.done} of {count} ran"


def publish_both_at_once(node: Any) -> None:
    """One message on /a and one on /b, from two threads released together."""
    pubs = [node.create_publisher(String, topic, 10) for topic in ("/a", "/b")]
    start = threading.Barrier(2)

    def send(pub: Any) -> None:
        start.wait()
        pub.publish(String(data="x"))

    threads = [threading.Thread(target=send, args=(pub,)) for pub in pubs]
    for t in threads:
        t.start()
    for t in threads:
        t.join()


def spin_until(executor: Any, done: Callable[[], bool]) -> None:
    end = time.monotonic() + DEADLINE_S
    while not done():
        assert time.monotonic() < end, "callbacks did not run"
        executor.spin_once(timeout_sec=0.05)


@pytest.fixture
def context() -> Any:
    ctx = Context()
    ctx.init([], backend="inprocess", domain_id=61)
    yield ctx
    ctx.try_shutdown()


def test_the_bus_own_callbacks_overlap(context: Context) -> None:
    # What a program got before the rclpy stand-in: callbacks on the wire's threads, at once.
    overlap = Overlap()
    node = BusNode("plain", context=context.bus)
    for topic in ("/a", "/b"):
        node.create_subscription(String, topic, overlap, 10)
    publish_both_at_once(node)
    overlap.wait_done(2)
    assert overlap.peak == 2


def test_the_default_executor_never_runs_two_subscriptions_at_once(context: Context) -> None:
    overlap = Overlap()
    node = Node("listener", context=context)
    for topic in ("/a", "/b"):
        node.create_subscription(String, topic, overlap, 10)
    publish_both_at_once(node)
    assert overlap.done == 0, "a callback ran before anything spun"
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    spin_until(executor, lambda: overlap.done >= 2)
    assert overlap.peak == 1


@pytest.mark.parametrize(("group", "peak"), [(ReentrantCallbackGroup, 2), (MutuallyExclusiveCallbackGroup, 1)],
                         ids=["reentrant", "mutually_exclusive"])
def test_a_multithreaded_executor_overlaps_only_what_the_group_allows(context: Context, group: type,
                                                                       peak: int) -> None:
    overlap = Overlap()
    node = Node("listener", context=context)
    shared = group()
    for topic in ("/a", "/b"):
        node.create_subscription(String, topic, overlap, 10, callback_group=shared)
    executor = MultiThreadedExecutor(num_threads=2, context=context)
    executor.add_node(node)
    publish_both_at_once(node)
    spin_until(executor, lambda: overlap.done >= 2)
    executor.shutdown()
    assert overlap.peak == peak


def test_timers_futures_and_shutdown_while_spinning(context: Context) -> None:
    node = Node("timed", context=context)
    ticks: list[int] = []
    timer = node.create_timer(0.01, lambda: ticks.append(len(ticks)))
    future = rclpy.task.Future()
    node.create_timer(0.05, lambda: future.set_result("fired") if len(ticks) >= 3 else None)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    executor.spin_until_future_complete(future, timeout_sec=DEADLINE_S)
    assert future.result() == "fired" and len(ticks) >= 3
    timer.cancel()
    threading.Timer(0.05, context.try_shutdown).start()
    with pytest.raises(ExternalShutdownException):
        executor.spin()


def test_use_sim_time_makes_the_clock_and_timers_follow_clock(context: Context) -> None:
    from robotmodel.msgs import stamp
    from robotmodel.msgs.rosgraph_msgs import Clock as ClockMsg
    from robotmodel.rclpy.parameter import Parameter

    node = Node("simulated", context=context, parameter_overrides=[Parameter("use_sim_time", value=True)])
    assert node.get_parameter("use_sim_time").value is True and node.get_clock().ros_time_is_active
    clock = node.bus_node.create_publisher(ClockMsg, "/clock", 10)
    fired: list[int] = []
    node.create_timer(1.0, lambda: fired.append(node.get_clock().now().nanoseconds))
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(node)
    for seconds in (100, 100.5, 101, 101.5, 102):
        clock.publish(ClockMsg(clock=stamp(int(seconds * 1e9))))
        executor.spin_once(timeout_sec=0.05)
    # Made at ROS time 0, the 1 s timer is overdue at the first /clock (100 s) and fires then, then at
    # 101 and 102, on /clock's time: what Jazzy's rclpy does with the same steps (run in .venv-rclpy).
    assert fired == [100_000_000_000, 101_000_000_000, 102_000_000_000]
    node.set_parameters([Parameter("use_sim_time", value=False)])
    assert abs(node.get_clock().now().nanoseconds - time.time_ns()) < 5e9


def test_the_stand_in_on_a_real_ros1_master(ros1: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    # The ROS 1 wire has no ROS 2 services: the node keeps its parameters to itself and works.
    for key in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_HOME"):
        monkeypatch.setenv(key, ros1.env[key])
    ctx = Context()
    ctx.init([], backend="ros1")
    try:
        node = Node("rclpy_on_ros1", context=ctx)
        assert node.declare_parameter("gain", 0.5).value == 0.5
        got: list[str] = []
        node.create_subscription(String, "/chatter", lambda m: got.append(m.data), 10)
        pub = node.create_publisher(String, "/chatter", 10)
        executor = SingleThreadedExecutor(context=ctx)
        executor.add_node(node)
        end = time.monotonic() + DEADLINE_S
        while not got:
            assert time.monotonic() < end, "nothing arrived over TCPROS"
            pub.publish(String(data="over TCPROS"))
            executor.spin_once(timeout_sec=0.1)
        assert got[0] == "over TCPROS"
    finally:
        ctx.try_shutdown()
