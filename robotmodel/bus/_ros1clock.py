"""ROS time for a node: ``/clock`` when ``use_sim_time`` is true (ROS 1's ``/use_sim_time``, ROS 2's node parameter).

As rospy's ``init_simtime`` and roscpp's ``ros::Time::init`` read it: ``/use_sim_time`` is
looked at once, when the node starts. True, the node's time is the last
``rosgraph_msgs/Clock`` on ``/clock`` (0 until the first one, and it may jump back, as when
a bag loops); otherwise it is the system clock. On the ROS 2 wires the node's own ``use_sim_time``
parameter decides, as rclpy's ``TimeSource`` does; the caller passes its value.
:func:`node_clock` gives the clock; :meth:`TopicClock.wait_for_valid` is roscpp's
``ros::Time::waitForValid`` (what lets its timers start only once time runs);
:meth:`TopicClock.on_jump_back` is how tf2_ros's Buffer, given the node's clock, hears of a
jump back (a looping bag) and clears itself (see :func:`robotmodel.tf_ros.clear_on_jump_back`).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

from robotmodel.time import Clock, Duration, SimClock, SystemClock, Time

__all__ = ["TopicClock", "node_clock"]

_STEP = Duration(seconds=0.1)
_VALID = Time(nanoseconds=1)


class TopicClock(SimClock):
    """A :class:`robotmodel.time.SimClock` set by each message on ``/clock``."""

    def __init__(self, node: Any) -> None:
        from robotmodel.msgs.rosgraph_msgs import Clock as ClockMsg

        super().__init__()
        self._jump_back: list[Callable[[Time, Time], None]] = []
        self._sub = node.create_subscription(ClockMsg, "/clock", self._on_clock, 10)

    def on_jump_back(self, callback: Callable[[Time, Time], None]) -> None:
        """Call ``callback(before, after)`` whenever ``/clock`` goes back (rcl's jump callback, backward only)."""
        self._jump_back.append(callback)

    def _on_clock(self, msg: Any) -> None:
        before = self.now()
        after = Time(nanoseconds=msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)
        self.set(after)
        if after < before:
            for callback in list(self._jump_back):
                callback(before, after)

    def wait_for_valid(self, stop: threading.Event | None = None, timeout: float | None = None) -> bool:
        """Block until the first ``/clock`` came (time is not 0); False when ``stop`` or ``timeout`` came first."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self.sleep_until(_VALID, _STEP):
            if (stop is not None and stop.is_set()) or (deadline is not None and time.monotonic() > deadline):
                return False
        return True

    def close(self) -> None:
        """Stop following ``/clock``."""
        self._sub.close()


def node_clock(node: Any, use_sim_time: bool = False) -> Clock:
    """The clock of ``node``'s ROS time: a :class:`TopicClock` when sim time is on, else the system clock.

    Sim time is on with ``/use_sim_time`` true on ROS 1, and on a ROS 2 wire with the node's
    ``use_sim_time`` parameter true (passed in, as rclpy's TimeSource reads it from
    ``--ros-args -p use_sim_time:=true``).
    """
    if node.context.backend.name != "ros1":
        return TopicClock(node) if use_sim_time else SystemClock()
    store = node.parameters
    if not (store.has("/use_sim_time") and store.get("/use_sim_time") is True):
        return SystemClock()
    return TopicClock(node)
