"""``robotmodel topic list|echo|hz|bw|info|type|pub``: the bus's topics, as ``ros2 topic`` shows them.

The programs are :mod:`robotmodel.topic`'s ``run_topic_*``; ``rostopic`` is an alias.
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._node_args import add_node_arguments

__all__ = ["register"]

# robotmodel.topic's defaults (not imported: --help stays light).
_TRUNCATE_LENGTH = 128
_SPIN_TIME = 0.5


def _add_bus_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                        help="zenoh endpoint to connect to instead of the local rendezvous (repeatable)")
    parser.add_argument("--spin-time", type=float, default=_SPIN_TIME, metavar="S",
                        help=f"seconds to wait for discovery (default {_SPIN_TIME})")


def register(sub: Any) -> None:
    """Add the ``topic`` subcommand with its verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "topic", aliases=["rostopic"], help="list the topics on the bus, or print the messages of one (as ros2 topic)",
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
    echo.add_argument("--truncate-length", "-l", type=int, default=_TRUNCATE_LENGTH,
                      help=f"the length to truncate arrays, bytes and strings to (default: {_TRUNCATE_LENGTH})")
    echo.add_argument("--flow-style", action="store_true", help="print collections in the flow style")
    echo.add_argument("--raw", action="store_true", help="echo the raw binary representation")
    echo.add_argument("--once", action="store_true", help="print the first message received and then exit")
    echo.add_argument("--timeout", type=float, metavar="N", default=None,
                      help="set a timeout in seconds for waiting")
    _add_bus_options(echo)
    add_node_arguments(echo, "_robotmodel_topic_echo")  # a relative TOPIC_NAME resolves under --namespace
    echo.set_defaults(func=run_echo)
    _register_more(verbs)


def _register_more(verbs: Any) -> None:
    hz = verbs.add_parser("hz", help="print the average publishing rate to screen",
                          description="Print the average publishing rate to screen.")
    hz.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    hz.add_argument("--window", "-w", type=int, default=10000, metavar="WINDOW",
                    help="window size, in # of messages, for calculating rate (default: 10000)")
    hz.add_argument("--timeout", type=float, metavar="N", default=None, help="stop after N seconds")
    _add_bus_options(hz)
    hz.set_defaults(func=run_hz)

    bw = verbs.add_parser("bw", help="display bandwidth used by topic",
                          description="Display bandwidth used by topic.")
    bw.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    bw.add_argument("--window", "-w", type=int, default=100, metavar="WINDOW",
                    help="maximum window size, in # of messages, for calculating rate (default: 100)")
    bw.add_argument("--timeout", type=float, metavar="N", default=None, help="stop after N seconds")
    _add_bus_options(bw)
    bw.set_defaults(func=run_bw)

    info = verbs.add_parser("info", help="print information about a topic",
                            description="Print information about a topic.")
    info.add_argument("topic_name", help="name of the ROS topic to get info (e.g. '/chatter')")
    info.add_argument("--verbose", "-v", action="store_true",
                      help="prints detailed information like the node name, node namespace, topic type, "
                           "GUID and QoS Profile of the publishers and subscribers to this topic")
    _add_bus_options(info)
    info.set_defaults(func=run_info)

    typ = verbs.add_parser("type", help="print a topic's type", description="Print a topic's type.")
    typ.add_argument("topic_name", help="name of the ROS topic to get type (e.g. '/chatter')")
    _add_bus_options(typ)
    typ.set_defaults(func=run_type)

    pub = verbs.add_parser("pub", help="publish a message to a topic", description="Publish a message to a topic.")
    pub.add_argument("topic_name", help="name of the ROS topic to publish to (e.g. '/chatter')")
    pub.add_argument("message_type", help="type of the ROS message (e.g. 'std_msgs/msg/String')")
    pub.add_argument("values", nargs="?", default="",
                     help="values to fill the message with in YAML format (e.g. 'data: Hello World')")
    pub.add_argument("-r", "--rate", type=float, default=1.0, metavar="N",
                     help="publishing rate in Hz (default: 1)")
    pub.add_argument("-p", "--print", type=int, default=1, metavar="N", dest="print_nth",
                     help="only print every N-th published message (default: 1, 0: never)")
    pub.add_argument("-1", "--once", action="store_true", help="publish one message and exit")
    pub.add_argument("-t", "--times", type=int, default=0, metavar="TIMES",
                     help="publish this number of times and then exit")
    pub.add_argument("-w", "--wait-matching-subscriptions", type=int, default=None, metavar="N",
                     help="wait until finding the specified number of matching subscriptions "
                          "(default 1 with --once or --times, else 0)")
    pub.add_argument("--keep-alive", type=float, default=0.1, metavar="N",
                     help="keep publishing node alive for N seconds after the last message (default: 0.1)")
    pub.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                     help="zenoh endpoint to connect to instead of the local rendezvous (repeatable)")
    pub.set_defaults(func=run_pub)


def run_list(args: argparse.Namespace) -> int:
    """Print the topics."""
    from robotmodel.topic import run_topic_list

    return run_topic_list(show_types=args.show_types, count_topics=args.count_topics,
                          include_hidden_topics=args.include_hidden_topics, connect=args.connect,
                          spin_time=args.spin_time)


def run_echo(args: argparse.Namespace) -> int:
    """Print the topic's messages."""
    from robotmodel.topic import run_topic_echo

    return run_topic_echo(args.topic_name, args.message_type, field=args.field, full_length=args.full_length,
                          truncate_length=args.truncate_length, flow_style=args.flow_style, raw=args.raw,
                          once=args.once, timeout=args.timeout, connect=args.connect, spin_time=args.spin_time,
                          namespace=args.namespace, ros=args.ros)


def run_hz(args: argparse.Namespace) -> int:
    """Print the rate."""
    from robotmodel.topic import run_topic_hz

    return run_topic_hz(args.topic_name, window=args.window, connect=args.connect, spin_time=args.spin_time,
                        timeout=args.timeout)


def run_bw(args: argparse.Namespace) -> int:
    """Print the bandwidth."""
    from robotmodel.topic import run_topic_bw

    return run_topic_bw(args.topic_name, window=args.window, connect=args.connect, spin_time=args.spin_time,
                        timeout=args.timeout)


def run_info(args: argparse.Namespace) -> int:
    """Print the topic's type and endpoints."""
    from robotmodel.topic import run_topic_info

    return run_topic_info(args.topic_name, verbose=args.verbose, connect=args.connect, spin_time=args.spin_time)


def run_type(args: argparse.Namespace) -> int:
    """Print the topic's type."""
    from robotmodel.topic import run_topic_type

    return run_topic_type(args.topic_name, connect=args.connect, spin_time=args.spin_time)


def run_pub(args: argparse.Namespace) -> int:
    """Publish the message."""
    from robotmodel.topic import run_topic_pub

    return run_topic_pub(args.topic_name, args.message_type, args.values, rate=args.rate, once=args.once,
                         times=args.times, wait_matching_subscriptions=args.wait_matching_subscriptions,
                         keep_alive=args.keep_alive, print_nth=args.print_nth, connect=args.connect)
