"""``ros2 topic list`` as a program, and what the topic verbs share: ros2cli's discovery spin, echo's QoS choice."""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence
from typing import Any

__all__ = ["DEFAULT_SPIN_TIME", "run_topic_list", "wait_for_topic"]

# ros2cli's direct node spins this long to discover the graph before answering.
DEFAULT_SPIN_TIME = 0.5
_POLL_S = 0.1  # how often the graph is read while waiting for a topic


def _hidden(name: str) -> bool:
    return any(token.startswith("_") for token in name.split("/"))


def _discover(node: Any, spin_time: float) -> list[tuple[str, list[str]]]:
    """The graph after ``spin_time`` s of discovery.

    The whole time, as ros2cli's direct node spins before it answers: a topic's publishers
    (their types, their QoS) come in one by one, so the first sign of a topic is not all of it.
    """
    end = time.monotonic() + spin_time
    node.get_topic_names_and_types()  # starts following the graph
    time.sleep(max(0.0, end - time.monotonic()))
    return list(node.get_topic_names_and_types())


def wait_for_topic(node: Any, topic: str, spin_time: float, stop: threading.Event,
                   deadline: float | None = None) -> list[str] | None:
    """The types of ``topic`` once the graph shows it; None when ``stop`` or the monotonic ``deadline`` came first.

    A topic not published yet gets ros2's and rostopic's warning line, then is waited for, as
    ``ros2 topic hz|bw`` (``get_msg_class(blocking=True)``) and ``rostopic hz`` wait.
    """
    found = dict(_discover(node, spin_time))
    if topic not in found:
        print(f"WARNING: topic [{topic}] does not appear to be published yet", flush=True)
    while topic not in found:
        if stop.wait(_POLL_S) or (deadline is not None and time.monotonic() > deadline):
            return None
        found = dict(node.get_topic_names_and_types())
    return list(found[topic])


def run_topic_list(*, show_types: bool = False, count_topics: bool = False, include_hidden_topics: bool = False,
                   connect: Sequence[str] = (), spin_time: float = DEFAULT_SPIN_TIME) -> int:
    """``ros2 topic list``: print the topics (and types) of the domain, sorted; returns the exit code."""
    from robotmodel.bus import Node

    with Node("_robotmodel_topic_list", connect=list(connect)) as node:
        topics = _discover(node, spin_time)
    topics = [(n, t) for n, t in topics if include_hidden_topics or not _hidden(n)]
    if count_topics:
        print(len(topics))
        return 0
    for name, types in topics:
        print(f"{name} [{', '.join(types)}]" if show_types else name)
    return 0


def _echo_qos(node: Any, topic: str, base: Any = None, say: bool = False) -> Any:
    """ros2 echo's QoS: ``base`` (a preset) made reliable / transient local only when every publisher offers it.

    Without ``base``, sensor_data's depth; ``say``: print ros2's line when only some publishers offer it.
    """
    from dataclasses import replace

    from robotmodel.bus import Durability, EntityKind, QoS, Reliability

    pubs = node.context.graph.endpoints(topic, EntityKind.PUBLISHER)
    if not pubs:  # a named preset as it is; by default reliable, which a later reliable publisher matches fully
        return base if base is not None else QoS(5, Reliability.RELIABLE, Durability.VOLATILE)
    base = base if base is not None else QoS(5, Reliability.BEST_EFFORT, Durability.VOLATILE)
    reliable = sum(p.qos is not None and p.qos.reliability == Reliability.RELIABLE for p in pubs)
    latched = sum(p.qos is not None and p.qos.transient_local for p in pubs)
    if say and 0 < reliable < len(pubs):
        print("Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE. Falling back to "
              "QoSReliabilityPolicy.BEST_EFFORT as it will connect to all publishers", flush=True)
    if say and 0 < latched < len(pubs):
        print("Some, but not all, publishers are offering QoSDurabilityPolicy.TRANSIENT_LOCAL. Falling back to "
              "QoSDurabilityPolicy.VOLATILE as it will connect to all publishers", flush=True)
    return replace(base, reliability=Reliability.RELIABLE if reliable == len(pubs) else Reliability.BEST_EFFORT,
                   durability=Durability.TRANSIENT_LOCAL if latched == len(pubs) else Durability.VOLATILE)
