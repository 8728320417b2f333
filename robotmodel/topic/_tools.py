"""``ros2 topic list`` and ``ros2 topic echo`` as programs: what is on the bus, as ros2cli shows it.

``echo`` prints each message as ros2's ``message_to_yaml`` does (fields in message order,
arrays and strings cut after ``--truncate-length`` items with ``'...'``), each followed by
``---``. The type comes from the graph (liveliness tokens) unless given.
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robotmodel.rcl import RosArgs

__all__ = ["DEFAULT_SPIN_TIME", "DEFAULT_TRUNCATE_LENGTH", "message_to_yaml", "run_topic_echo", "run_topic_list"]

DEFAULT_TRUNCATE_LENGTH = 128
# ros2cli's direct node spins this long to discover the graph before answering.
DEFAULT_SPIN_TIME = 0.5


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


def _convert(value: Any, limit: int | None) -> Any:
    if hasattr(type(value), "__msgtype__"):
        return {name: _convert(getattr(value, name), limit) for name in _field_names(value)}
    if hasattr(value, "tolist"):  # numpy arrays of numbers
        value = value.tolist()
    if isinstance(value, bytes | bytearray):
        value = list(value)
    if isinstance(value, list):
        items = [_convert(v, limit) for v in (value if limit is None else value[:limit])]
        return [*items, "..."] if limit is not None and len(value) > limit else items
    if isinstance(value, str) and limit is not None and len(value) > limit:
        return value[:limit] + "..."
    return value


def _field_names(msg: Any) -> list[str]:
    from dataclasses import fields

    return [f.name for f in fields(msg) if not f.name.startswith("__")]


def message_to_yaml(msg: Any, truncate_length: int | None = DEFAULT_TRUNCATE_LENGTH,
                    flow_style: bool = False) -> str:
    """A message (or a field value) as YAML, the way ros2's ``message_to_yaml`` writes it."""
    import yaml

    return str(yaml.dump(_convert(msg, truncate_length), allow_unicode=True, width=sys.maxsize,
                         default_flow_style=flow_style, sort_keys=False))


def _echo_qos(node: Any, topic: str) -> Any:
    """ros2 echo's choice: reliable / transient local only when every publisher offers it."""
    from robotmodel.bus import Durability, EntityKind, QoS, Reliability

    pubs = node.context.graph.endpoints(topic, EntityKind.PUBLISHER)
    latched = bool(pubs) and all(p.qos is not None and p.qos.transient_local for p in pubs)
    reliable = not pubs or all(p.qos is not None and p.qos.reliability == Reliability.RELIABLE for p in pubs)
    return QoS(5, Reliability.RELIABLE if reliable else Reliability.BEST_EFFORT,
               Durability.TRANSIENT_LOCAL if latched else Durability.VOLATILE)


def run_topic_echo(topic_name: str, message_type: str | None = None, *, field: str | None = None,
                   full_length: bool = False, truncate_length: int = DEFAULT_TRUNCATE_LENGTH,
                   flow_style: bool = False, raw: bool = False, once: bool = False, timeout: float | None = None,
                   connect: Sequence[str] = (), spin_time: float = DEFAULT_SPIN_TIME, namespace: str = "/",
                   ros: RosArgs | None = None) -> int:
    """``ros2 topic echo``: print each message until SIGINT/SIGTERM, ``once`` or ``timeout``; the exit code.

    The type comes from the graph unless ``message_type`` is given; ``field`` picks a
    sub-field (``a.b``); a relative ``topic_name`` resolves under ``namespace``.
    """
    from robotmodel.bus import Node
    from robotmodel.errors import BusError
    from robotmodel.rcl import RosArgs
    from robotmodel.signals import stop_on_signals

    ros = ros or RosArgs()
    fields = None
    if field is not None:
        fields = [f for f in field.split(".") if f]
        if not fields:
            raise BusError(f"Invalid field value '{field}'")
    limit = None if full_length else truncate_length
    stop = stop_on_signals()
    lock = threading.Lock()
    problems: list[str] = []

    from robotmodel.rcl import warn_ignored_params

    name = ros.node_name or "_robotmodel_topic_echo"
    warn_ignored_params(ros, namespace, name)
    with Node(name, namespace, connect=list(connect), remappings=ros.remaps) as node:
        topic = node.resolve_topic_name(topic_name)
        typename = message_type
        # Discovery first, type given or not: the QoS follows the publishers, and a new session's
        # graph does not show them yet, so an echo of a latched topic would subscribe volatile
        # and miss the one latched message.
        found = dict(_discover(node, spin_time))
        if typename is None:
            if topic not in found:
                print(f"WARNING: topic [{topic_name}] does not appear to be published yet", flush=True)
                raise BusError("Could not determine the type for the passed topic")
            if len(found[topic]) > 1:
                raise BusError(f"Cannot echo topic '{topic_name}', as it contains more than one type: "
                               f"[{', '.join(found[topic])}]")
            typename = found[topic][0]
        qos = _echo_qos(node, topic)

        def on_message(msg: Any) -> None:
            if stop.is_set():
                return
            sub = msg.payload if raw else msg
            if fields is not None and not raw:
                for name in fields:
                    if not hasattr(sub, name):
                        problems.append(f"Invalid field '{'.'.join(fields)}': "
                                        f"'{type(sub).__name__}' object has no attribute '{name}'")
                        stop.set()
                        return
                    sub = getattr(sub, name)
            with lock:
                if raw:
                    print(sub, end="\n---\n", flush=True)
                else:
                    print(message_to_yaml(sub, limit, flow_style), end="---\n", flush=True)
                if once:
                    stop.set()

        try:
            if raw:
                node.create_subscription(typename, topic, on_message, qos, raw=True)
            else:
                node.create_subscription(typename, topic, on_message, qos)
        except BusError as exc:
            if "unknown message type" in str(exc):
                raise BusError("The passed message type is invalid") from None
            raise
        stop.wait(timeout)
    if problems:
        raise BusError(problems[0])
    return 0
