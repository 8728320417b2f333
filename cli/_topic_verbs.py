"""``topic hz|bw|info|type|pub``'s parsers and handlers (``topic list|echo`` are in topic_cmd)."""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.cli._bus_args import add_bus_options
from robotmodel.cli._qos_args import add_qos_arguments, qos_of

__all__ = ["register_verbs"]


def register_verbs(verbs: Any) -> None:
    """Add the verbs to ``topic``'s subparsers."""
    hz = verbs.add_parser("hz", help="print the average publishing rate to screen",
                          description="Print the average publishing rate to screen.")
    hz.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    hz.add_argument("--window", "-w", type=int, default=10000, metavar="WINDOW",
                    help="window size, in # of messages, for calculating rate (default: 10000)")
    hz.add_argument("--filter", dest="filter_expr", default=None, metavar="EXPR",
                    help="only measure messages matching the specified Python expression (on m, the message)")
    hz.add_argument("--wall-time", dest="use_wtime", action="store_true",
                    help="calculates rate using wall time which can be helpful when clock is not published "
                         "during simulation")
    hz.add_argument("-s", "--use-sim-time", action="store_true", help="enable ROS simulation time (/clock)")
    hz.add_argument("--timeout", type=float, metavar="N", default=None, help="stop after N seconds")
    add_bus_options(hz)
    hz.set_defaults(func=run_hz)

    bw = verbs.add_parser("bw", help="display bandwidth used by topic",
                          description="Display bandwidth used by topic.")
    bw.add_argument("topic_name", help="name of the ROS topic to listen to (e.g. '/chatter')")
    bw.add_argument("--window", "-w", type=int, default=100, metavar="WINDOW",
                    help="maximum window size, in # of messages, for calculating rate (default: 100)")
    bw.add_argument("--timeout", type=float, metavar="N", default=None, help="stop after N seconds")
    add_bus_options(bw)
    bw.set_defaults(func=run_bw)

    info = verbs.add_parser("info", help="print information about a topic",
                            description="Print information about a topic.")
    info.add_argument("topic_name", help="name of the ROS topic to get info (e.g. '/chatter')")
    info.add_argument("--verbose", "-v", action="store_true",
                      help="prints detailed information like the node name, node namespace, topic type, "
                           "GUID and QoS Profile of the publishers and subscribers to this topic")
    add_bus_options(info)
    info.set_defaults(func=run_info)

    typ = verbs.add_parser("type", help="print a topic's type", description="Print a topic's type.")
    typ.add_argument("topic_name", help="name of the ROS topic to get type (e.g. '/chatter')")
    add_bus_options(typ)
    typ.set_defaults(func=run_type)

    pub = verbs.add_parser("pub", help="publish a message to a topic", description="Publish a message to a topic.")
    pub.add_argument("topic_name", help="name of the ROS topic to publish to (e.g. '/chatter')")
    pub.add_argument("message_type", help="type of the ROS message (e.g. 'std_msgs/msg/String')")
    source = pub.add_mutually_exclusive_group()
    source.add_argument("values", nargs="?", default="{}",
                        help="values to fill the message with in YAML format (e.g. 'data: Hello World'), "
                             "otherwise the message will be published with default values")
    source.add_argument("--stdin", action="store_true", help="read values from standard input")
    pub.add_argument("-r", "--rate", type=float, default=1.0, metavar="N",
                     help="publishing rate in Hz (default: 1)")
    pub.add_argument("-p", "--print", type=int, default=1, metavar="N", dest="print_nth",
                     help="only print every N-th published message (default: 1, 0: never)")
    count = pub.add_mutually_exclusive_group()
    count.add_argument("-1", "--once", action="store_true", help="publish one message and exit")
    count.add_argument("-t", "--times", type=int, default=0, metavar="TIMES",
                       help="publish this number of times and then exit")
    pub.add_argument("-w", "--wait-matching-subscriptions", type=int, default=None, metavar="N",
                     help="wait until finding the specified number of matching subscriptions "
                          "(default 1 with --once or --times, else 0)")
    pub.add_argument("--max-wait-time-secs", type=float, default=None, metavar="S",
                     help="the maximum wait time in seconds with --wait-matching-subscriptions (default: endless)")
    pub.add_argument("--keep-alive", type=float, default=0.1, metavar="N",
                     help="keep publishing node alive for N seconds after the last message (default: 0.1)")
    pub.add_argument("-n", "--node-name", default=None, help="name of the created publishing node")
    add_qos_arguments(pub, "publish", "default")
    pub.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                     help="zenoh endpoint to connect to instead of the local rendezvous (repeatable)")
    pub.set_defaults(func=run_pub)


def run_hz(args: argparse.Namespace) -> int:
    """Print the rate."""
    from robotmodel.topic import run_topic_hz

    return run_topic_hz(args.topic_name, window=args.window, filter_expr=args.filter_expr, wall_time=args.use_wtime,
                        use_sim_time=args.use_sim_time, connect=args.connect, spin_time=args.spin_time,
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
                         keep_alive=args.keep_alive, print_nth=args.print_nth, qos=qos_of(args),
                         max_wait_time_secs=args.max_wait_time_secs, node_name=args.node_name, stdin=args.stdin,
                         connect=args.connect)
