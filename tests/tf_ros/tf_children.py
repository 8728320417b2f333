"""Child processes for the live TF tests (run as ``python tf_children.py MODE ...``).

Each child talks on the bus chosen by its environment (ROBOTMODEL_ZENOH_PORT, ROS_DOMAIN_ID)
and reports on stdout, one line per event, flushed, so the test can wait for conditions.

Modes:
- ``broadcaster NAME T0_NS [GO]``: node NAME sends ``base -> moving`` at 100 Hz with stamps
  T0 + k * 10 ms (k = 0, 1, ...), pose :func:`pose_at`. Prints ``READY`` once its node is
  up; with GO it then waits for a line on stdin before sending. Prints ``SENT k`` every
  10th message. Stops on SIGTERM.
- ``interp T0_NS [TIMEOUT_S]``: a listener that prints ``WAITING``, then looks up ``base -> moving``
  at the latest time with a timeout (2 s by default) before any data exists, prints ``GOT <seconds>``,
  waits until stamps T0..T0+0.5 s are in, and prints one JSON line with lookups at
  times between received stamps.
- ``watch``: a listener printing ``STAMP <ns>`` for the newest ``base -> moving`` every
  50 ms (or ``NONE``); exits 0 on SIGTERM.
- ``garbage``: publishes an undecodable payload on /tf (with a valid attachment), prints ``SENT``.
"""

from __future__ import annotations

import json
import math
import sys
import threading
import time


def pose_at(t_ns: int, t0_ns: int) -> tuple[list[float], list[float]]:
    """The broadcaster's pose at stamp t: x linear, y a sine, a rotation about z linear in time."""
    s = (t_ns - t0_ns) / 1e9
    yaw = 0.8 * s
    return [0.5 * s, math.sin(3.0 * s), 1.0], [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]


def _stop_event() -> threading.Event:
    # As the tools: a handler that sets the event itself never runs when the kernel hands
    # SIGTERM to one of zenoh's threads while the main thread sleeps in stop.wait().
    from robotmodel.signals import stop_on_signals

    return stop_on_signals()


def broadcaster(name: str, t0_ns: int, wait_go: bool) -> None:
    from robotmodel.bus import Node
    from robotmodel.msgs import make_transform
    from robotmodel.tf_ros import TransformBroadcaster

    stop = _stop_event()
    with Node(name) as node, TransformBroadcaster(node) as br:
        print("READY", flush=True)
        if wait_go:
            sys.stdin.readline()
        start = time.monotonic()
        k = 0
        while not stop.is_set():
            stamp = t0_ns + k * 10_000_000
            translation, rotation = pose_at(stamp, t0_ns)
            br.send_transform(make_transform("base", "moving", translation, rotation, stamp))
            if k % 10 == 0:
                print(f"SENT {k}", flush=True)
            k += 1
            stop.wait(max(0.0, start + k * 0.01 - time.monotonic()))


def interp(t0_ns: int, timeout_s: float) -> None:
    from robotmodel.tf import Buffer, Duration, Time
    from robotmodel.tf_ros import TransformListener

    buffer = Buffer()
    with TransformListener(buffer):
        print("WAITING", flush=True)
        began = time.monotonic()
        buffer.lookup_transform("base", "moving", Time(), timeout=Duration(seconds=timeout_s))
        print(f"GOT {time.monotonic() - began:.3f}", flush=True)
        last = t0_ns + 50 * 10_000_000
        buffer.lookup_transform("base", "moving", Time(nanoseconds=last), timeout=Duration(seconds=10))
        results = []
        for k, frac in ((3, 0.37), (10, 0.5), (25, 0.01), (40, 0.99), (49, 0.75)):
            t = t0_ns + k * 10_000_000 + round(frac * 10_000_000)
            msg = buffer.lookup_transform("base", "moving", Time(nanoseconds=t))
            tr, q = msg.transform.translation, msg.transform.rotation
            stamp = msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec
            results.append({"t": t, "k": k, "stamp": stamp, "translation": [tr.x, tr.y, tr.z],
                            "rotation": [q.x, q.y, q.z, q.w]})
        print(json.dumps(results), flush=True)


def watch() -> None:
    from robotmodel.errors import TransformException
    from robotmodel.tf import Buffer, Time
    from robotmodel.tf_ros import TransformListener

    stop = _stop_event()
    buffer = Buffer()
    with TransformListener(buffer):
        print("LISTENING", flush=True)
        while not stop.wait(0.05):
            try:
                msg = buffer.lookup_transform("base", "moving", Time())
            except TransformException:
                print("NONE", flush=True)
                continue
            print(f"STAMP {msg.header.stamp.sec * 1_000_000_000 + msg.header.stamp.nanosec}", flush=True)


def garbage() -> None:
    from robotmodel.bus import Node
    from robotmodel.msgs import TFMessage

    with Node("garbage_maker") as node:
        pub = node.create_publisher(TFMessage, "/tf", 10)
        if not pub.wait_for_subscriptions(1, timeout=10.0):
            raise SystemExit("no subscriber on /tf")
        # A valid CDR header followed by bytes that are no TFMessage (a huge sequence length).
        for _ in range(5):
            pub.publish_raw(b"\x00\x01\x00\x00" + b"\xff\xff\xff\x7f" + b"garbage!")
            time.sleep(0.05)
        print("SENT", flush=True)
        time.sleep(0.5)


if __name__ == "__main__":
    mode, args = sys.argv[1], sys.argv[2:]
    if mode == "broadcaster":
        broadcaster(args[0], int(args[1]), len(args) > 2 and args[2] == "GO")
    elif mode == "interp":
        interp(int(args[0]), float(args[1]) if len(args) > 1 else 2.0)
    elif mode == "watch":
        watch()
    elif mode == "garbage":
        garbage()
    else:
        raise SystemExit(f"unknown mode {mode}")
