"""static_transform_publisher as a program (``robotmodel static-transform-publisher``).

Publishes one transform, latched on ``/tf_static``, until Ctrl-C or SIGTERM (exit 0), as
ROS 2 Jazzy's tf2_ros program does; ROS 1 tf's forms with a period republish on ``/tf``.
The argument forms and texts are in :mod:`robotmodel.tf_ros._static_args`.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from typing import Any

from robotmodel.errors import RosArgsError, StaticArgsError
from robotmodel.rcl import ros_log, split_ros_words, warn_ignored_params
from robotmodel.signals import stop_on_signals
from robotmodel.tf_ros._static_args import (
    HELP_MORE,
    USAGE,
    StaticTransformSpec,
    parse_static_args,
    startup_message,
    validation_errors,
)
from robotmodel.tf_ros._words import split_connect

__all__ = ["run_static_transform_publisher"]


def _transform(spec: StaticTransformSpec, stamp_ns: int) -> Any:
    from robotmodel.msgs import make_transform

    return make_transform(spec.frame_id, spec.child_frame_id, spec.translation, spec.rotation, stamp_ns)


def run_static_transform_publisher(words: Sequence[str]) -> int:
    """Run static_transform_publisher on ``words`` (after the program's name); returns the exit code.

    Parses ROS 2's and ROS 1's forms, validates, publishes, then waits for SIGINT/SIGTERM
    (installs handlers: main thread only). Bad words print ROS 2's text and give exit 1.
    """
    try:
        words, namespace, ros = split_ros_words(words)
    except RosArgsError as exc:
        print(f"robotmodel static-transform-publisher: error: {exc}", file=sys.stderr)
        return 2
    words, endpoints = split_connect(words)
    try:
        spec = parse_static_args(words, lambda text: ros_log("WARN", "", text))
    except StaticArgsError as exc:
        ros_log("ERROR", "", f"error parsing command line arguments: {exc}")
        print(USAGE, flush=True)
        return 1
    if spec.help:
        print(USAGE + HELP_MORE, flush=True)
        return 0

    from robotmodel.tf_ros._node import unique_name

    name = ros.node_name or unique_name("static_transform_publisher_")
    errors = validation_errors(spec, name)
    if errors:
        for line in errors:
            ros_log("ERROR", name, line)
        return 1

    stop = stop_on_signals()
    from robotmodel.bus import Node
    from robotmodel.tf_ros._broadcaster import StaticTransformBroadcaster, TransformBroadcaster

    # /tf and /tf_static are absolute: the namespace names the node only, as in ROS.
    warn_ignored_params(ros, namespace, name)
    with Node(name, namespace, connect=endpoints, remappings=ros.remaps) as node:
        if spec.period_ms is None:
            with StaticTransformBroadcaster(node) as static:
                static.send_transform(_transform(spec, time.time_ns()))
                ros_log("INFO", name, startup_message(spec))
                stop.wait()
            return 0
        # ROS 1 tf: republish on /tf every period, stamped one period ahead so that
        # listeners can interpolate up to the next message.
        period_ns = round(spec.period_ms * 1e6)
        with TransformBroadcaster(node) as dynamic:
            dynamic.send_transform(_transform(spec, time.time_ns() + period_ns))
            ros_log("INFO", name, startup_message(spec))
            while not stop.wait(period_ns / 1e9):
                dynamic.send_transform(_transform(spec, time.time_ns() + period_ns))
    return 0
