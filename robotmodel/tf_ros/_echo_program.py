"""tf2_echo as a program: ``tf2_echo SOURCE TARGET [RATE]`` prints a transform as it arrives.

With ``--bag FILE [--time T | --every DT]`` it answers from a recording instead of the
bus, in the same format (see :mod:`robotmodel.tf_ros._bag_echo`).

Prints TARGET's pose in SOURCE (``lookupTransform(SOURCE, TARGET, latest)``) every
1/RATE seconds (default 1 Hz) in tf2_echo's format; until the frames are connected it logs
tf2_echo's throttled ``Waiting for transform ...`` line. Ctrl-C or SIGTERM end it (exit 0).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from typing import Any

from robotmodel.errors import EchoArgsError, RosArgsError
from robotmodel.rcl import logger_name, node_params, ros_log, split_ros_words, warn_ignored_params
from robotmodel.signals import stop_on_signals
from robotmodel.tf_ros._echo_args import HELP_MORE, USAGE, failure_text, format_echo, parse_echo_args, waiting_message
from robotmodel.tf_ros._words import split_bag_words, split_connect

__all__ = ["can_transform_reason", "run_tf2_echo"]

_NODE = "tf2_echo"


def can_transform_reason(buffer: Any, target: str, source: str) -> str:
    """Empty when ``target <- source`` can be looked up at the latest time, else tf2's canTransform text."""
    if target == source:
        return ""
    known = set(buffer.all_frame_names())
    for arg, frame in (("target_frame", target), ("source_frame", source)):
        if not frame:
            why = "in tf2 frame_ids cannot be empty"
        elif frame.startswith("/"):
            why = "in tf2 frame_ids cannot start with a '/'"
        elif frame not in known:
            why = "frame does not exist"
        else:
            continue
        return f'Invalid frame ID "{frame}" passed to canTransform argument {arg} - {why}'
    ok, reason = buffer.can_transform_ns(target, source, 0)
    return "" if ok else str(reason)


def _pause(stop: Any, clock: Any, period: float) -> None:
    """One period of ``clock``'s time (a sim clock's pace, as ros::Rate keeps it), ended early by ``stop``.

    A jump back of the clock (a looping bag) ends it too, as ros::Time's sleep does: the time
    slept to would otherwise not come again.
    """
    from robotmodel.time import Duration, SystemClock

    if isinstance(clock, SystemClock):
        stop.wait(period)
        return
    start = clock.now()
    until = start + Duration(seconds=period)
    while not stop.is_set() and not clock.sleep_until(until, Duration(seconds=0.1)) and clock.now() >= start:
        pass


def run_tf2_echo(words: Sequence[str]) -> int:
    """Run tf2_echo on ``words`` (the words after the program's name); returns the exit code.

    Listens on the bus, waits for the frames, then prints the transform at the given rate
    until SIGINT/SIGTERM (installs handlers: main thread only). With ``--bag FILE`` it reads
    the recording instead. Bad words print tf2_echo's text and give its exit code.
    """
    try:
        words, namespace, ros = split_ros_words(words, _NODE)
    except RosArgsError as exc:
        print(f"robotmodel tf2-echo: error: {exc}", file=sys.stderr)
        return 2
    words, endpoints = split_connect(words)
    if words and words[0] in ("-h", "--help"):
        print(USAGE + HELP_MORE, end="", flush=True)
        return 0
    try:
        words, bag_options = split_bag_words(words)
    except EchoArgsError as exc:
        print(exc, file=sys.stderr)
        return exc.code
    if bag_options and "bag" not in bag_options:
        print("robotmodel tf2-echo: error: --time, --every and --urdf need --bag FILE", file=sys.stderr)
        return 2
    try:
        echo = parse_echo_args(words)
    except EchoArgsError as exc:
        print(str(exc), end="" if exc.to_stdout else "\n", file=sys.stdout if exc.to_stdout else sys.stderr,
              flush=True)
        return int(exc.code)
    if bag_options:
        from robotmodel.tf_ros._bag_echo import run_bag_echo

        return int(run_bag_echo(echo, bag_options))

    stop = stop_on_signals()
    from robotmodel.bus import Node, node_clock
    from robotmodel.errors import TransformException
    from robotmodel.tf import Buffer, Time
    from robotmodel.tf_ros._jump import clear_on_jump_back
    from robotmodel.tf_ros._listener import TransformListener

    period = 1.0 / echo.rate_hz
    source, target = echo.source_frame, echo.target_frame
    buffer = Buffer()
    # /tf and /tf_static are absolute: the namespace names the node only, as in ROS.
    name = ros.node_name or _NODE
    warn_ignored_params(ros, namespace, name, used=("use_sim_time",))
    use_sim_time = node_params(ros, namespace, name).get("use_sim_time") is True
    with Node(name, namespace, connect=endpoints, remappings=ros.remaps) as node, \
            TransformListener(buffer, node):
        # ROS time: /clock with use_sim_time (ROS 1's /use_sim_time, ROS 2's parameter), as tf2_echo's rate sleeps
        clock = node_clock(node, use_sim_time)
        # tf2_echo's tf2_ros::Buffer has the node's clock: a jump back (a looping bag) clears it.
        clear_on_jump_back(buffer, clock, logger_name(namespace, name), ros1=node.context.backend.name == "ros1")
        last_log = -1.0
        while not stop.is_set():
            reason = can_transform_reason(buffer, source, target)
            if not reason:
                break
            now = time.monotonic()
            if last_log < 0 or now - last_log >= 1.0:
                ros_log("INFO", _NODE, waiting_message(source, target, reason))
                last_log = now
            _pause(stop, clock, period)
        printed = False
        while not stop.is_set():
            try:
                t = buffer.lookup_transform(source, target, Time())
            except TransformException as exc:
                text = failure_text(clock.now().nanoseconds / 1e9, str(exc), buffer.all_frames_as_string(), printed)
            else:
                tr, rot, stamp = t.transform.translation, t.transform.rotation, t.header.stamp
                text = format_echo(stamp.sec, stamp.nanosec, (tr.x, tr.y, tr.z), (rot.x, rot.y, rot.z, rot.w))
                printed = True
            sys.stdout.write(text)
            sys.stdout.flush()
            _pause(stop, clock, period)
    return 0

