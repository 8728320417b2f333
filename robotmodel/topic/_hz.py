"""``ros2 topic hz``: a topic's average rate, as ros2cli's ``ROSTopicHz`` measures and prints it.

Each arrival is stamped with the node's ROS time (``/clock`` under ``--use-sim-time`` on ROS 2,
under ``/use_sim_time`` on ROS 1, as rostopic reads it; the system clock otherwise) or, with
``--wall-time``, the system clock. The gaps between arrivals are kept, the last ``window`` of
them, and a report is printed when an arrival comes at least a second (of that clock) after the
last report's, so under a paused ``/clock`` nothing is printed, as in ROS 2. ``--filter`` is
ros2's: a Python expression on ``m``, the decoded message; messages for which it is false are
not counted.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Sequence
from types import CodeType
from typing import Any

from robotmodel.errors import BusError
from robotmodel.topic._rate import DEFAULT_WINDOW, RateStats, gap_stats

__all__ = ["TIME_RESET", "HzMeter", "compile_filter", "run_topic_hz"]

#: What ros2 topic hz prints when its clock reads 0 again (a /clock restarted) with gaps counted.
TIME_RESET = "time has reset, resetting counters"
_SECOND_NS = 1_000_000_000


class HzMeter:
    """ros2cli's ``ROSTopicHz`` for one topic: the last ``window`` gaps between arrivals, in one clock's ns."""

    def __init__(self, window: int = DEFAULT_WINDOW) -> None:
        if window < 1:
            raise BusError(f"window must be a positive number of messages, got {window}")
        self._gaps: deque[int] = deque(maxlen=window)
        self._t0 = -1
        self._tn = 0
        self._printed = 0

    def add(self, now_ns: int) -> str:
        """Count an arrival at ``now_ns``; the line ros2 prints then (:data:`TIME_RESET`) or ''.

        As ros2's: a clock at 0 counts nothing (and drops the gaps); a time before the first
        arrival starts over; any other time adds its gap from the previous arrival.
        """
        if now_ns == 0:
            if self._gaps:
                self._gaps.clear()
                return TIME_RESET
            return ""
        if self._t0 < 0 or self._t0 > now_ns:
            self._t0 = self._tn = now_ns
            self._gaps.clear()
        else:
            self._gaps.append(now_ns - self._tn)
            self._tn = now_ns
        return ""

    def report(self) -> RateStats | None:
        """The stats to print now, or None: nothing counted, the first report's time just set, or < 1 s since."""
        if not self._gaps:
            return None
        if self._printed == 0:
            self._printed = self._tn
            return None
        if self._tn < self._printed + _SECOND_NS:
            return None
        self._printed = self._tn
        return gap_stats(list(self._gaps))


def compile_filter(expr: str) -> CodeType:
    """``--filter EXPR`` compiled; a BusError naming it when it is not a Python expression."""
    try:
        return compile(expr, "--filter", "eval")
    except SyntaxError as exc:
        raise BusError(f"--filter {expr!r} is not a Python expression: {exc.msg}") from None


def run_topic_hz(topic_name: str, *, window: int = DEFAULT_WINDOW, filter_expr: str | None = None,
                 wall_time: bool = False, use_sim_time: bool = False, connect: Sequence[str] = (),
                 spin_time: float = 0.5, timeout: float | None = None) -> int:
    """``ros2 topic hz``: print the average rate of ``topic_name`` until stopped (or ``timeout`` s); the exit code.

    A topic not published yet is waited for, after ros2's and rostopic's warning line. On the
    ROS 1 wire the lines are rostopic's: ``subscribed to [TOPIC]`` first, and ``window`` counts
    the messages in it (the gaps and one, at most ``window``).
    """
    from robotmodel.bus import Node
    from robotmodel.bus._ros1clock import node_clock
    from robotmodel.signals import stop_on_signals
    from robotmodel.time import SystemClock
    from robotmodel.topic._tools import _echo_qos, wait_for_topic

    check = compile_filter(filter_expr) if filter_expr else None
    meter = HzMeter(window)
    stop = stop_on_signals()
    lock = threading.Lock()
    failed: list[str] = []
    deadline = None if timeout is None else time.monotonic() + timeout
    with Node("_robotmodel_topic_hz", connect=list(connect)) as node:
        topic = node.resolve_topic_name(topic_name)
        types = wait_for_topic(node, topic, spin_time, stop, deadline)
        if types is None:
            return 0
        ros1 = node.context.encoding == "ros1"
        clock = SystemClock() if wall_time else node_clock(node, use_sim_time)

        def on_message(m: Any) -> None:
            if check is not None:
                try:
                    if not eval(check, {}, {"m": m}):  # ros2 evaluates --filter as the user's Python
                        return
                except Exception as exc:  # whatever the user's expression raises ends hz, named
                    failed.append(f"--filter {filter_expr!r} failed on a message of {topic}: "
                                  f"{type(exc).__name__}: {exc}")
                    stop.set()
                    return
            with lock:
                note = meter.add(clock.now().nanoseconds)
                stats = meter.report()
            if note:
                print(note, flush=True)
            if stats is not None:
                print((stats._replace(window=min(stats.window + 1, window)) if ros1 else stats).text(), flush=True)

        node.create_subscription(types[0], topic, on_message, _echo_qos(node, topic), raw=check is None)
        if ros1:
            print(f"subscribed to [{topic}]", flush=True)
        stop.wait(None if deadline is None else max(0.0, deadline - time.monotonic()))
    if failed:
        raise BusError(failed[0])
    return 0
