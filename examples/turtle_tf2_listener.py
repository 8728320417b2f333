"""The ROS 2 tf2 tutorial's turtle follower: turtle2 drives towards turtle1, once a second.

The tutorial's rclpy node with its imports changed: each tick it looks up turtle1 in
turtle2's frame and publishes angular.z = 1.0·atan2(y, x), linear.x = 0.5·√(x² + y²) on
``turtle2/cmd_vel``. The bus has no services, so instead of calling turtlesim's ``spawn``
it waits for turtle2's frame (start ``turtlesim.py --spawn turtle2 4 2 0``); a lookup
that fails is logged and retried at the next tick, as in the tutorial.

Run: python examples/turtle_tf2_listener.py [--target-frame turtle1] [--duration S]
"""

from __future__ import annotations

import argparse
import math

from robotmodel.bus import Node
from robotmodel.msgs import Twist
from robotmodel.signals import stop_on_signals
from robotmodel.tf import Buffer, Time, TransformException
from robotmodel.tf_ros import TransformListener
from robotmodel.time import Duration, Rate, SystemClock


class FrameListener(Node):
    """Steers turtle2 towards the target frame."""

    def __init__(self, target_frame: str) -> None:
        super().__init__("turtle_tf2_frame_listener")
        # Declare and acquire `target_frame` parameter
        self.target_frame = target_frame
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        # Create turtle2 velocity publisher
        self.publisher = self.create_publisher(Twist, "turtle2/cmd_vel", 1)

    def on_timer(self) -> None:
        """One command from one lookup."""
        # Store frame names in variables that will be used to
        # compute transformations
        from_frame_rel = self.target_frame
        to_frame_rel = "turtle2"
        # Look up for the transformation between target_frame and turtle2 frames
        # and send velocity commands for turtle2 to reach target_frame
        try:
            t = self.tf_buffer.lookup_transform(to_frame_rel, from_frame_rel, Time())
        except TransformException as ex:
            print(f"[turtle_tf2_frame_listener] Could not transform {to_frame_rel} to {from_frame_rel}: {ex}",
                  flush=True)
            return
        msg = Twist()
        scale_rotation_rate = 1.0
        msg.angular.z = scale_rotation_rate * math.atan2(t.transform.translation.y, t.transform.translation.x)
        scale_forward_speed = 0.5
        msg.linear.x = scale_forward_speed * math.sqrt(t.transform.translation.x ** 2 +
                                                       t.transform.translation.y ** 2)
        self.publisher.publish(msg)


def main() -> None:
    """Tick once a second until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--target-frame", default="turtle1", help="the frame to follow (default turtle1)")
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)
    node = FrameListener(args.target_frame)
    rate = Rate(1.0, clock)  # the tutorial's create_timer(1.0, self.on_timer)
    while not shutdown.is_set() and (end is None or clock.now() < end):
        rate.sleep()
        node.on_timer()
    node.tf_listener.close()
    node.destroy_node()


if __name__ == "__main__":
    main()
