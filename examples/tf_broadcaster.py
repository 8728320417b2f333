"""The tf2 tutorial's broadcaster: camera_link 0.1 m ahead of and 0.2 m above base_link, at 50 Hz.

ROS 1's tutorial code (rospy + tf2_ros) with its imports changed; ``rospy.is_shutdown()``
becomes a flag set by Ctrl-C or SIGTERM, and ``rospy.Rate`` robotmodel's :class:`Rate`.

Run: python examples/tf_broadcaster.py [--duration S]
     python examples/tf_listener.py      (in another terminal)
"""

from __future__ import annotations

import argparse

from robotmodel.bus import Node
from robotmodel.msgs import TransformStamped
from robotmodel.signals import stop_on_signals
from robotmodel.tf_ros import TransformBroadcaster
from robotmodel.time import Duration, Rate, SystemClock


def main() -> None:
    """Broadcast base_link → camera_link until --duration seconds pass or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)

    br = TransformBroadcaster(Node("tf_broadcaster"))
    t = TransformStamped()
    rate = Rate(50.0, clock)
    print("[tf_broadcaster] broadcasting base_link -> camera_link at 50 Hz", flush=True)
    while not shutdown.is_set() and (end is None or clock.now() < end):
        t.header.stamp = clock.now().to_msg()
        t.header.frame_id = "base_link"
        t.child_frame_id = "camera_link"
        t.transform.translation.x = 0.1
        t.transform.translation.y = 0.0
        t.transform.translation.z = 0.2
        t.transform.rotation.x = 0.0
        t.transform.rotation.y = 0.0
        t.transform.rotation.z = 0.0
        t.transform.rotation.w = 1.0
        br.sendTransform(t)
        rate.sleep()
    br.close()
    br.node.close()


if __name__ == "__main__":
    main()
