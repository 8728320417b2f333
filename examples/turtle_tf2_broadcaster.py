"""The ROS 2 tf2 tutorial's turtle broadcaster: ``/TURTLE/pose`` becomes world → TURTLE on /tf.

The tutorial's rclpy node with its imports changed; its ``turtlename`` parameter is
``--turtlename`` and rclpy's clock is the system clock.

Run: python examples/turtle_tf2_broadcaster.py --turtlename turtle1 [--duration S]
"""

from __future__ import annotations

import argparse
from typing import Any

from robotmodel.bus import Node
from robotmodel.msgs import TransformStamped
from robotmodel.signals import stop_on_signals
from robotmodel.tf_ros import TransformBroadcaster
from robotmodel.tf_transformations import quaternion_from_euler
from robotmodel.time import Duration, SystemClock

try:  # run from a checkout (python examples/...) or installed (python -m robotmodel.examples...)
    from turtlesim import POSE_TYPE, pose_class
except ImportError:
    from robotmodel.examples.turtlesim import POSE_TYPE, pose_class


class FramePublisher(Node):
    """Broadcasts each pose of one turtle as the transform world → turtle."""

    def __init__(self, turtlename: str) -> None:
        super().__init__(f"{turtlename}_tf2_frame_publisher")
        self.turtlename = turtlename
        self.clock = SystemClock()
        # Initialize the transform broadcaster
        self.tf_broadcaster = TransformBroadcaster(self)
        # Subscribe to a turtle{1}{2}/pose topic and call handle_turtle_pose
        # callback function on each message
        pose_class()
        self.subscription = self.create_subscription(POSE_TYPE, f"/{self.turtlename}/pose", self.handle_turtle_pose,
                                                     1)

    def handle_turtle_pose(self, msg: Any) -> None:
        """Broadcast world → turtle from one pose."""
        t = TransformStamped()
        # Read message content and assign it to corresponding tf variables
        t.header.stamp = self.clock.now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = self.turtlename
        # Turtle only exists in 2D, thus we get x and y translation
        # coordinates from the message and set the z coordinate to 0
        t.transform.translation.x = float(msg.x)
        t.transform.translation.y = float(msg.y)
        t.transform.translation.z = 0.0
        # For the same reason, turtle can only rotate around one axis
        # and this why we set rotation in x and y to 0 and obtain
        # rotation in z axis from the message
        q = quaternion_from_euler(0, 0, float(msg.theta))
        t.transform.rotation.x = q[0]
        t.transform.rotation.y = q[1]
        t.transform.rotation.z = q[2]
        t.transform.rotation.w = q[3]
        # Send the transformation
        self.tf_broadcaster.sendTransform(t)


def main() -> None:
    """Broadcast until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--turtlename", default="turtle", help="the turtle whose pose to broadcast")
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    with FramePublisher(args.turtlename):
        shutdown.wait(None if args.duration is None else Duration(seconds=args.duration).nanoseconds / 1e9)


if __name__ == "__main__":
    main()
