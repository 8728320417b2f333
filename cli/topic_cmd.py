"""``robotmodel topic list|echo|hz|bw|info|type|pub``: the bus's topics, as ``ros2 topic`` shows them.

The programs are :mod:`robotmodel.topic`'s ``run_topic_*``; ``rostopic`` is an alias.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bus_args import add_bus_options
from robotmodel.cli._node_args import add_node_arguments
from robotmodel.cli._qos_args import add_qos_arguments, qos_of
from robotmodel.cli._topic_verbs import register_verbs

__all__ = ["register"]

# robotmodel.topic's default (not imported: --help stays light).
_TRUNCATE_LENGTH = 128


def register(sub: Any) -> None:
    """Add the ``topic`` subcommand with its verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "topic", aliases=["rostopic"], help="the topics on the bus: list, echo, hz, bw, info, type, pub (ros2 topic)",
        description="Inspect and publish the topics of the ROS graph, on any wire.")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True

    lst = verbs.add_parser("list", help="output a list of available topics",
                           description="Output a list of available topics.")
    lst.add_argument("-t", "--show-types", action="store_true", help="additionally show the topic type")
    lst.add_argument("-c", "--count-topics", action="store_true", help="only display the number of topics")
    lst.add_argument("--include-hidden-topics", action="store_true", help="consider hidden topics as well")
    add_bus_options(lst)
    lst.set_defaults(func=run_list)

    echo = verbs.add_parser("echo", help="output messages from a topic",
                            description="Output messages from a topic.")
    echo.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    echo.add_argument("message_type", nargs="?", help="type of the ROS message (e.g. 'std_msgs/msg/String')")
    echo.add_argument("--csv", action="store_true",
                      help="output all recursive fields separated by commas (e.g. for plotting); with "
                           "--include-message-info the message info's fields come first")
    echo.add_argument("--field", default=None,
                      help="echo a selected field of a message; use '.' to select sub-fields")
    echo.add_argument("--full-length", "-f", action="store_true",
                      help="output all elements of arrays, bytes and strings longer than --truncate-length")
    echo.add_argument("--truncate-length", "-l", type=_unsigned, default=_TRUNCATE_LENGTH,
                      help=f"the length to truncate arrays, bytes and strings to (default: {_TRUNCATE_LENGTH})")
    echo.add_argument("--no-arr", "--noarr", action="store_true", help="don't print array fields of messages")
    echo.add_argument("--no-str", "--nostr", action="store_true", help="don't print string fields of messages")
    echo.add_argument("--flow-style", action="store_true", help="print collections in the flow style")
    echo.add_argument("--no-lost-messages", action="store_true", help="don't report when a message is lost")
    echo.add_argument("--raw", action="store_true", help="echo the raw binary representation")
    echo.add_argument("--filter", dest="filter_expr", metavar="FILTER_EXPR",
                      help="Python expression to filter messages that are printed (builtins and m, the message)")
    echo.add_argument("--once", action="store_true", help="print the first message received and then exit")
    echo.add_argument("-n", dest="count", type=int, metavar="COUNT", help="rostopic's: print COUNT messages, then exit")
    echo.add_argument("--timeout", type=float, metavar="N", default=None,
                      help="set a timeout in seconds for waiting")
    echo.add_argument("--include-message-info", "-i", action="store_true", help="shows the associated message info")
    add_qos_arguments(echo, "subscribe", "sensor_data")
    add_bus_options(echo)
    add_node_arguments(echo, "_robotmodel_topic_echo")  # a relative TOPIC_NAME resolves under --namespace
    echo.set_defaults(func=run_echo)
    register_verbs(verbs)


def run_list(args: argparse.Namespace) -> int:
    """Print the topics."""
    from robotmodel.topic import run_topic_list

    return run_topic_list(show_types=args.show_types, count_topics=args.count_topics,
                          include_hidden_topics=args.include_hidden_topics, connect=args.connect,
                          spin_time=args.spin_time)


def run_echo(args: argparse.Namespace) -> int:
    """Print the topic's messages."""
    from robotmodel.topic import EchoFormat, qos_from_short_keys, run_topic_echo

    form = EchoFormat(field=args.field, full_length=args.full_length, truncate_length=args.truncate_length,
                      no_arr=args.no_arr, no_str=args.no_str, flow_style=args.flow_style, csv=args.csv,
                      include_message_info=args.include_message_info)
    overrides = (args.qos_reliability, args.qos_durability, args.qos_depth, args.qos_history, args.qos_liveliness,
                 args.qos_liveliness_lease_duration_seconds)
    return run_topic_echo(args.topic_name, args.message_type, form=form, raw=args.raw, once=args.once, count=args.count,
                          timeout=args.timeout, filter_expr=args.filter_expr,
                          qos=qos_of(args) if any(v is not None for v in overrides) else None,
                          qos_profile=qos_from_short_keys(args.qos_profile), connect=args.connect,
                          spin_time=args.spin_time, namespace=args.namespace, ros=args.ros)


def _unsigned(text: str) -> int:
    """ros2cli's unsigned_int: a non-negative integer."""
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError("value must be non-negative integer")
    return value
