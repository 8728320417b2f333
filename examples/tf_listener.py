"""The tf2 tutorial's listener: where camera_link is in base_link, printed at 10 Hz.

ROS 1's tutorial code with its imports changed: a lookup that fails with
LookupException, ConnectivityException or ExtrapolationException (nothing received yet,
frames not connected, data too old) waits for the next period and tries again.

Run: python examples/tf_listener.py [--duration S]
"""

from __future__ import annotations

import argparse

from robotmodel.bus import Node
from robotmodel.signals import stop_on_signals
from robotmodel.tf import Buffer, ConnectivityException, ExtrapolationException, LookupException, Time
from robotmodel.tf_ros import TransformListener
from robotmodel.time import Duration, Rate, SystemClock


def main() -> None:
    """Look camera_link up in base_link ten times a second until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)

    node = Node("tf_listener")
    tf_buffer = Buffer()
    listener = TransformListener(tf_buffer, node)
    rate = Rate(10.0, clock)
    while not shutdown.is_set() and (end is None or clock.now() < end):
        try:
            trans = tf_buffer.lookup_transform("base_link", "camera_link", Time())
        except (LookupException, ConnectivityException, ExtrapolationException):
            rate.sleep()
            continue
        p, q = trans.transform.translation, trans.transform.rotation
        stamp = Time.from_msg(trans.header.stamp).nanoseconds
        print(f"[tf_listener] camera_link in base_link at {stamp}: translation ({p.x:.3f}, {p.y:.3f}, {p.z:.3f}) "
              f"rotation ({q.x:.3f}, {q.y:.3f}, {q.z:.3f}, {q.w:.3f})", flush=True)
        rate.sleep()
    listener.close()
    node.close()


if __name__ == "__main__":
    main()
