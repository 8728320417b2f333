"""``robotmodel topic list|echo``: what is on the bus, as ``ros2 topic list`` and ``ros2 topic echo`` show it.

``echo`` prints each message as ros2's ``message_to_yaml`` does (fields in message order,
arrays and strings cut after ``--truncate-length`` items with ``'...'``), each followed by
``---``. The type comes from the graph (liveliness tokens) unless given.
"""

from __future__ import annotations

import argparse
import sys
import threading
import time
from typing import Any

from robotmodel.cli._node_args import add_node_arguments

__all__ = ["message_to_yaml", "register"]

DEFAULT_TRUNCATE_LENGTH = 128
# ros2cli's direct node spins this long to discover the graph before answering.
DEFAULT_SPIN_TIME = 0.5


def _add_bus_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to instead of the local rendezvous (repeatable)")
    parser.add_argument("--spin-time", type=float, default=DEFAULT_SPIN_TIME, metavar="S",
                        help=f"seconds to wait for discovery (default {DEFAULT_SPIN_TIME})")


def register(sub: Any) -> None:
    """Add the ``topic`` subcommand with its ``list`` and ``echo`` verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "topic", help="list the topics on the bus, or print the messages of one (as ros2 topic)",
        description="Inspect the ROS 2 graph on the zenoh bus (rmw_zenoh's wire format).")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True

    lst = verbs.add_parser("list", help="output a list of available topics",
                           description="Output a list of available topics.")
    lst.add_argument("-t", "--show-types", action="store_true", help="additionally show the topic type")
    lst.add_argument("-c", "--count-topics", action="store_true", help="only display the number of topics")
    lst.add_argument("--include-hidden-topics", action="store_true", help="consider hidden topics as well")
    _add_bus_options(lst)
    lst.set_defaults(func=run_list)

    echo = verbs.add_parser("echo", help="output messages from a topic",
                            description="Output messages from a topic.")
    echo.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    echo.add_argument("message_type", nargs="?", help="type of the ROS message (e.g. 'std_msgs/msg/String')")
    echo.add_argument("--field", default=None,
                      help="echo a selected field of a message; use '.' to select sub-fields")
    echo.add_argument("--full-length", "-f", action="store_true",
                      help="output all elements of arrays, bytes and strings longer than --truncate-length")
    echo.add_argument("--truncate-length", "-l", type=int, default=DEFAULT_TRUNCATE_LENGTH,
                      help=f"the length to truncate arrays, bytes and strings to (default: {DEFAULT_TRUNCATE_LENGTH})")
    echo.add_argument("--flow-style", action="store_true", help="print collections in the flow style")
    echo.add_argument("--raw", action="store_true", help="echo the raw binary representation")
    echo.add_argument("--once", action="store_true", help="print the first message received and then exit")
    echo.add_argument("--timeout", type=float, metavar="N", default=None,
                      help="set a timeout in seconds for waiting")
    _add_bus_options(echo)
    add_node_arguments(echo, "_robotmodel_topic_echo")  # a relative TOPIC_NAME resolves under --namespace
    echo.set_defaults(func=run_echo)


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


def run_list(args: argparse.Namespace) -> int:
    """Print the topics (and types) of the domain, sorted."""
    from robotmodel.bus import Node

    with Node("_robotmodel_topic_list", connect=args.connect) as node:
        topics = _discover(node, args.spin_time)
    topics = [(n, t) for n, t in topics if args.include_hidden_topics or not _hidden(n)]
    if args.count_topics:
        print(len(topics))
        return 0
    for name, types in topics:
        print(f"{name} [{', '.join(types)}]" if args.show_types else name)
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


def run_echo(args: argparse.Namespace) -> int:
    """Subscribe to the topic and print each message until Ctrl-C, --once or --timeout."""
    from robotmodel.bus import Node
    from robotmodel.errors import BusError
    from robotmodel.signals import stop_on_signals

    fields = None
    if args.field is not None:
        fields = [f for f in args.field.split(".") if f]
        if not fields:
            raise BusError(f"Invalid field value '{args.field}'")
    limit = None if args.full_length else args.truncate_length
    stop = stop_on_signals()
    lock = threading.Lock()
    problems: list[str] = []

    from robotmodel.rcl import warn_ignored_params

    warn_ignored_params(args.ros, args.namespace, args.node_name or "_robotmodel_topic_echo")
    with Node(args.node_name or "_robotmodel_topic_echo", args.namespace, connect=args.connect,
              remappings=args.ros.remaps) as node:
        topic = node.resolve_topic_name(args.topic_name)
        typename = args.message_type
        # Discovery first, type given or not: the QoS follows the publishers, and a new session's
        # graph does not show them yet, so an echo of a latched topic would subscribe volatile
        # and miss the one latched message.
        found = dict(_discover(node, args.spin_time))
        if typename is None:
            if topic not in found:
                print(f"WARNING: topic [{args.topic_name}] does not appear to be published yet", flush=True)
                raise BusError("Could not determine the type for the passed topic")
            if len(found[topic]) > 1:
                raise BusError(f"Cannot echo topic '{args.topic_name}', as it contains more than one type: "
                               f"[{', '.join(found[topic])}]")
            typename = found[topic][0]
        qos = _echo_qos(node, topic)

        def on_message(msg: Any) -> None:
            if stop.is_set():
                return
            sub = msg.payload if args.raw else msg
            if fields is not None and not args.raw:
                for name in fields:
                    if not hasattr(sub, name):
                        problems.append(f"Invalid field '{'.'.join(fields)}': "
                                        f"'{type(sub).__name__}' object has no attribute '{name}'")
                        stop.set()
                        return
                    sub = getattr(sub, name)
            with lock:
                if args.raw:
                    print(sub, end="\n---\n", flush=True)
                else:
                    print(message_to_yaml(sub, limit, args.flow_style), end="---\n", flush=True)
                if args.once:
                    stop.set()

        try:
            if args.raw:
                node.create_subscription(typename, topic, on_message, qos, raw=True)
            else:
                node.create_subscription(typename, topic, on_message, qos)
        except BusError as exc:
            if "unknown message type" in str(exc):
                raise BusError("The passed message type is invalid") from None
            raise
        stop.wait(args.timeout)
    if problems:
        raise BusError(problems[0])
    return 0
