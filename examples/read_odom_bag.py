"""The "read /odom from a bag" example, on a recording it first makes.

Part one writes ``odom.mcap`` (rosbag2's MCAP layout: the ros2 profile, CDR): a robot
driving a circle of 1 m radius at 0.5 rad/s, its ``nav_msgs/Odometry`` on /odom at 20 Hz
for --duration seconds. Part two is the seed's loop: open the bag, read the messages on
/odom, print each position and heading. Any bag works in part two, ROS 1 ``.bag`` and ROS 2
folders too (``--bag FILE`` skips part one): ``robotmodel demo`` leaves one with /odom.

Run: python examples/read_odom_bag.py [--duration S] [--output odom.mcap] [--bag FILE]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from robotmodel.msgs import Odometry, serialize
from robotmodel.recording import McapWriter, Recording
from robotmodel.tf_transformations import euler_from_quaternion, quaternion_from_euler

RADIUS = 1.0
TURN_RATE = 0.5  # rad/s
RATE_HZ = 20
START_NS = 1_700_000_000 * 10**9


def make_recording(path: Path, duration: float) -> int:
    """Write ``duration`` seconds of /odom on the circle; returns the number of messages."""
    with McapWriter(path) as writer:
        writer.add_topic("/odom", "nav_msgs/msg/Odometry")
        count = round(duration * RATE_HZ) + 1
        for k in range(count):
            t = k / RATE_HZ
            yaw = TURN_RATE * t
            msg = Odometry()
            stamp_ns = START_NS + k * 10**9 // RATE_HZ
            msg.header.stamp.sec, msg.header.stamp.nanosec = divmod(stamp_ns, 10**9)
            msg.header.frame_id = "odom"
            msg.child_frame_id = "base_footprint"
            msg.pose.pose.position.x = RADIUS * math.sin(yaw)
            msg.pose.pose.position.y = RADIUS * (1.0 - math.cos(yaw))
            q = quaternion_from_euler(0.0, 0.0, yaw)
            o = msg.pose.pose.orientation
            o.x, o.y, o.z, o.w = (float(v) for v in q)
            msg.twist.twist.linear.x = RADIUS * TURN_RATE
            msg.twist.twist.angular.z = TURN_RATE
            writer.write("/odom", stamp_ns, serialize(msg))
    return count


def main() -> None:
    """Make the recording (unless --bag), then read /odom back from it."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=10.0, help="seconds of odometry to record (default 10)")
    parser.add_argument("--output", default="odom.mcap", help="the recording to write (default odom.mcap)")
    parser.add_argument("--bag", help="read this recording instead of making one")
    args = parser.parse_args()
    path = Path(args.bag) if args.bag else Path(args.output)
    if not args.bag:
        written = make_recording(path, args.duration)
        print(f"wrote {written} /odom messages to {path}")

    bag = Recording(path)
    for topic, t, data in bag.messages(["/odom"]):
        msg = bag.deserialize(data, "nav_msgs/msg/Odometry")
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        _, _, yaw = euler_from_quaternion([q.x, q.y, q.z, q.w])
        print(f"{topic} {t}: x={p.x!r} y={p.y!r} yaw={yaw!r}")
    bag.close()


if __name__ == "__main__":
    main()
