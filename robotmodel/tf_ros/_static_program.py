"""``robotmodel static-transform-publisher`` (alias ``static_transform_publisher``).

Publishes one transform, latched on ``/tf_static``, until Ctrl-C or SIGTERM (exit 0), as
ROS 2 Jazzy's tf2_ros program does; ROS 1 tf's forms with a period republish on ``/tf``.
The argument forms and texts are in :mod:`robotmodel.cli._static_args`.
"""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from robotmodel.cli._bus_args import split_connect, stop_on_signals
from robotmodel.cli._ros_args import RosArgsError, split_ros_words, warn_ignored_params
from robotmodel.cli._rosfmt import ros_log
from robotmodel.cli._static_args import (
    USAGE,
    StaticArgsError,
    StaticTransformSpec,
    parse_static_args,
    startup_message,
    validation_errors,
)

__all__ = ["register", "run"]


def register(sub: Any) -> None:
    """Add the ``static-transform-publisher`` subcommand (it parses its own words, as ROS's does)."""
    parser: argparse.ArgumentParser = sub.add_parser(
        "static-transform-publisher", aliases=["static_transform_publisher"],
        prefix_chars="+", add_help=False,
        help="publish a static transform on /tf_static (tf2_ros's flags and positional forms)",
        description="--x X --y Y --z Z [--qx --qy --qz --qw | --roll --pitch --yaw] --frame-id F "
        "--child-frame-id C [--connect ENDPOINT] [--namespace NS] [--ros-args -r __ns:=/NS -r /tf_static:=TOPIC]; "
        "or x y z yaw pitch roll F C [period_ms]; or "
        "x y z qx qy qz qw F C [period_ms]",
    )
    parser.add_argument("words", nargs="*")
    parser.set_defaults(func=run)


def _transform(spec: StaticTransformSpec, stamp_ns: int) -> Any:
    from robotmodel.msgs import make_transform

    return make_transform(spec.frame_id, spec.child_frame_id, spec.translation, spec.rotation, stamp_ns)


def run(args: argparse.Namespace) -> int:
    """Parse, validate, publish, then wait for a stop signal."""
    try:
        words, namespace, ros = split_ros_words(args.words)
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
        print(USAGE, flush=True)
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
    from robotmodel.tf_ros import StaticTransformBroadcaster, TransformBroadcaster

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
