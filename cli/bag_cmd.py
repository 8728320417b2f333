"""``robotmodel bag info FILE`` (a recording's summary, as ``ros2 bag info``), ``bag play`` and ``bag record``.

ROS 1 ``.bag`` (with rosbag info's compression line), ROS 2 bag folders (db3 or MCAP),
bare MCAP and db3 files. The program is :func:`robotmodel.recording.run_bag_info`; ``bag record``
is ``robotmodel record`` (:func:`robotmodel.recording.run_record`); ``bag play`` is
:func:`robotmodel.recording.run_bag_play`.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from robotmodel.cli.record_cmd import add_record_arguments

if TYPE_CHECKING:
    from robotmodel.recording import PlayOptions

__all__ = ["play_options", "positive_float", "register"]

_DEFAULT = "default"  # --clock without HZ


def _hz(text: str) -> float | str:
    """--clock's HZ as a float; the no-value marker as it is (argparse passes a string const through type)."""
    return text if text == _DEFAULT else float(text)


def positive_float(text: str) -> float:
    """rosbag2's ``-d``'s type: a float above 0 (argparse names this function in its error)."""
    value = float(text)
    if value <= 0:
        raise ValueError(f"Value {value} is less than or equal to zero.")
    return value


def register(sub: Any) -> None:
    """Add the ``bag`` subcommand with its ``info``, ``play`` and ``record`` verbs."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "bag", aliases=["rosbag"], help="inspect, play or record a recording (as ros2 bag)",
        description="Inspect a recording: ROS 1 .bag, ROS 2 bag folder (db3 or MCAP), bare MCAP or db3.")
    verbs = parser.add_subparsers(dest="verb", metavar="VERB")
    verbs.required = True
    info = verbs.add_parser("info", help="print information about a bag",
                            description="Print a recording's files, size, storage, duration, start, end, message "
                                        "count and topics (type, count, serialization format), as ros2 bag info; "
                                        "a ROS 1 bag also gets rosbag info's compression line.")
    info.add_argument("bag_path", metavar="FILE", help="the recording (a .bag or .mcap/.db3 file, or a bag folder)")
    info.set_defaults(func=_info)
    record = verbs.add_parser("record", help="record topics from the bus into a bag (as robotmodel record)",
                              description="Record topics (default /tf /tf_static /joint_states /robot_description) "
                                          "into MCAP (rosbag2's ros2 profile, CDR) until Ctrl-C or SIGTERM; the same "
                                          "program as 'robotmodel record'.")
    add_record_arguments(record)
    play = verbs.add_parser("play", help="play a recording onto the bus (as ros2 bag play)",
                            description="Publish a recording's messages on the bus at their recorded pace, each "
                                        "topic with its recorded type and QoS (/tf_static and /robot_description "
                                        "transient local), optionally with /clock for nodes with use_sim_time; "
                                        "rosbag play's spellings (--hz, -s/--start) are accepted too.")
    play.add_argument("bag_path", metavar="FILE", help="the recording (a .bag or .mcap/.db3 file, or a bag folder)")
    play.add_argument("--clock", nargs="?", type=_hz, const=_DEFAULT, default=None, metavar="HZ",
                      help="publish /clock at HZ (default: rosbag2's 40) with the recording's time")
    play.add_argument("--hz", type=float, default=None, help=argparse.SUPPRESS)  # rosbag play --clock --hz=N
    play.add_argument("-r", "--rate", type=float, default=1.0, help="rate at which to play back (default 1.0)")
    play.add_argument("-l", "--loop", action="store_true", help="play the recording again and again")
    play.add_argument("--start-offset", "-s", "--start", dest="start_offset", type=float, default=0.0,
                      metavar="SECONDS", help="start this many seconds into the recording")
    play.add_argument("--topics", nargs="+", default=[], metavar="TOPIC",
                      help="play only these topics (default: all)")
    play.add_argument("--remap", "-m", nargs="+", default=[], metavar="OLD:=NEW",
                      help="list of topics to be remapped: in the form \"old_topic1:=new_topic1 "
                           "old_topic2:=new_topic2 etc.\"")
    play.add_argument("-d", "--delay", type=positive_float, default=0.0, metavar="SECONDS",
                      help="sleep duration before play (each loop), in seconds")
    play.add_argument("--connect", action="append", default=[], metavar="ENDPOINT",
                      help="zenoh endpoint to connect to (repeatable)")
    play.set_defaults(func=_play)


def play_options(args: argparse.Namespace) -> PlayOptions:
    """The :class:`robotmodel.recording.PlayOptions` that ``bag play``'s words say."""
    from robotmodel.recording import DEFAULT_CLOCK_HZ, PlayOptions, parse_topics

    clock = DEFAULT_CLOCK_HZ if args.clock == _DEFAULT else args.clock
    if args.hz is not None and clock is not None:
        clock = args.hz
    return PlayOptions(rate=args.rate, loop=args.loop, start_offset_ns=round(args.start_offset * 1e9),
                       topics=parse_topics(args.topics), clock_hz=clock, delay_ns=round(args.delay * 1e9),
                       remaps=tuple(args.remap))


def _play(args: argparse.Namespace) -> int:
    from robotmodel.recording import run_bag_play

    return run_bag_play(args.bag_path, play_options(args), connect=args.connect)


def _info(args: argparse.Namespace) -> int:
    from robotmodel.recording import run_bag_info

    return run_bag_info(args.bag_path)
