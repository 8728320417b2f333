"""``ros2 topic bw`` (a topic's bandwidth, printed once a second) and the rate arithmetic ``topic hz`` prints.

bw subscribes raw (no decoding, so any type is measured) and keeps the last ``window``
arrivals, as ros2cli's ``ROSTopicBandwidth`` does; times are the receiver's monotonic
clock in integer nanoseconds. ``topic hz`` itself is :mod:`._hz`.
"""

from __future__ import annotations

import itertools
import math
import threading
import time
from collections import deque
from collections.abc import Sequence
from time import monotonic_ns
from typing import Any, NamedTuple

__all__ = ["DEFAULT_WINDOW", "RateStats", "gap_stats", "rate_stats", "run_topic_bw"]

#: ros2 topic hz's default window (messages); bw's is 100.
DEFAULT_WINDOW = 10000
_BW_WINDOW = 100


class RateStats(NamedTuple):
    """What ros2 topic hz prints: rate (Hz), min/max/std dev of the gaps (s), window (the gaps counted, as ros2's)."""

    rate: float
    min_delta: float
    max_delta: float
    std_dev: float
    window: int

    def text(self) -> str:
        """The two lines ros2 topic hz prints."""
        return (f"average rate: {self.rate:.3f}\n\tmin: {self.min_delta:.3f}s max: {self.max_delta:.3f}s "
                f"std dev: {self.std_dev:.5f}s window: {self.window}")


def rate_stats(arrivals_ns: Sequence[int]) -> RateStats | None:
    """Stats of arrival times (ns, increasing); None below two arrivals."""
    return gap_stats([b - a for a, b in itertools.pairwise(arrivals_ns)])


def gap_stats(gaps_ns: Sequence[int]) -> RateStats | None:
    """Stats of the gaps between arrivals (ns), as ros2's ``ROSTopicHz.get_hz`` computes them; None when empty."""
    if not gaps_ns:
        return None
    deltas = [g / 1e9 for g in gaps_ns]
    mean = sum(deltas) / len(deltas)
    std = math.sqrt(sum((d - mean) ** 2 for d in deltas) / len(deltas))
    return RateStats(1.0 / mean if mean > 0 else 0.0, min(deltas), max(deltas), std, len(deltas))


def _size(n: float) -> str:
    for unit, scale in (("MB", 1e6), ("KB", 1e3)):
        if n >= scale:
            return f"{n / scale:.2f} {unit}"
    return f"{n:.2f} B"


def _watch(topic_name: str, window: int, connect: Sequence[str], spin_time: float, timeout: float | None,
           report: Any, name: str) -> int:
    """Subscribe raw to ``topic_name``; call ``report(list of (t_ns, size))`` every second until stopped."""
    from robotmodel.bus import Node
    from robotmodel.signals import stop_on_signals
    from robotmodel.topic._tools import _echo_qos, wait_for_topic

    stop = stop_on_signals()
    lock = threading.Lock()
    seen: deque[tuple[int, int]] = deque(maxlen=window)

    def on_message(msg: Any) -> None:
        with lock:
            seen.append((monotonic_ns(), len(msg.payload)))

    with Node(name, connect=list(connect)) as node:
        topic = node.resolve_topic_name(topic_name)
        deadline = None if timeout is None else time.monotonic() + timeout
        types = wait_for_topic(node, topic, spin_time, stop, deadline)
        if types is None:
            return 0
        node.create_subscription(types[0], topic, on_message, _echo_qos(node, topic), raw=True)
        report_start = monotonic_ns()
        while not stop.wait(1.0):
            with lock:
                snapshot = list(seen)
            report(snapshot)
            if timeout is not None and monotonic_ns() - report_start >= timeout * 1e9:
                break
    return 0


def run_topic_bw(topic_name: str, *, window: int = _BW_WINDOW, connect: Sequence[str] = (),
                 spin_time: float = 0.5, timeout: float | None = None) -> int:
    """``ros2 topic bw``: print the bandwidth of ``topic_name`` once a second until stopped; the exit code."""
    print(f"Subscribed to [{topic_name}]", flush=True)

    def report(seen: list[tuple[int, int]]) -> None:
        if len(seen) < 2:
            print("no new messages", flush=True)
            return
        span = (seen[-1][0] - seen[0][0]) / 1e9
        sizes = [s for _, s in seen]
        total = sum(sizes)
        bw = total / span if span > 0 else 0.0
        print(f"{_size(bw)}/s from {len(seen)} messages\n\tMessage size mean: {_size(total / len(sizes))} "
              f"min: {_size(min(sizes))} max: {_size(max(sizes))}", flush=True)

    return _watch(topic_name, window, connect, spin_time, timeout, report, "_robotmodel_topic_bw")
