"""Where the arm's gripper is: world → gripper_palm_link looked up at 10 Hz and printed.

The tf2 tutorial's listener loop on the bundled arm, fed by robot_state_publisher.

Run: python examples/arm_gripper_listener.py [--duration S]
"""

from __future__ import annotations

import argparse

from robotmodel.bus import Node
from robotmodel.signals import stop_on_signals
from robotmodel.tf import Buffer, ConnectivityException, ExtrapolationException, LookupException, Time
from robotmodel.tf_ros import TransformListener
from robotmodel.tf_transformations import euler_from_quaternion
from robotmodel.time import Duration, Rate, SystemClock


def main() -> None:
    """Print the gripper's pose ten times a second until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)
    with Node("arm_gripper_listener") as node:
        tf_buffer = Buffer()
        listener = TransformListener(tf_buffer, node)
        rate = Rate(10.0, clock)
        last = None
        while not shutdown.is_set() and (end is None or clock.now() < end):
            try:
                trans = tf_buffer.lookup_transform("world", "gripper_palm_link", Time())
            except (LookupException, ConnectivityException, ExtrapolationException):
                rate.sleep()
                continue
            stamp = Time.from_msg(trans.header.stamp).nanoseconds
            if stamp != last:  # print each new pose once
                last = stamp
                p, q = trans.transform.translation, trans.transform.rotation
                roll, pitch, yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])
                print(f"[arm_gripper_listener] gripper_palm_link in world at {stamp}: "
                      f"xyz ({p.x!r}, {p.y!r}, {p.z!r}) xyzw ({q.x!r}, {q.y!r}, {q.z!r}, {q.w!r}) "
                      f"rpy ({roll:.3f}, {pitch:.3f}, {yaw:.3f})", flush=True)
            rate.sleep()
        listener.close()


if __name__ == "__main__":
    main()
