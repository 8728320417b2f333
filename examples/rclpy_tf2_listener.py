"""rclpy tf2 tutorial shape: a node that follows the frame ``carrot``, the three-exception try block in a timer.

An rclpy program with only its imports changed: with ``import rclpy``, ``from rclpy.node import
Node``, ``from tf2_ros import ...`` it is the same program on ROS 2. Twice a second it looks up
``carrot`` in the parameter ``target_frame``'s frame (default ``world``); started before any
broadcaster, the lookup raises LookupException, which the usual ``except (LookupException,
ConnectivityException, ExtrapolationException)`` catches and reports; then it prints the
carrot's position and its distance from the target frame's origin.

Run: python examples/rclpy_tf2_listener.py [--ros-args -p target_frame:=world]
"""

import math

from robotmodel import rclpy
from robotmodel.rclpy.executors import ExternalShutdownException
from robotmodel.rclpy.node import Node
from robotmodel.rclpy.time import Time
from robotmodel.tf2_ros import ConnectivityException, ExtrapolationException, LookupException
from robotmodel.tf2_ros.buffer import Buffer
from robotmodel.tf2_ros.transform_listener import TransformListener


class CarrotListener(Node):
    """Looks up the carrot from a timer."""

    def __init__(self) -> None:
        super().__init__("carrot_listener")
        self.target_frame = self.declare_parameter("target_frame", "world").value
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self) -> None:
        """Report where the carrot is, or why it cannot be found."""
        try:
            t = self.tf_buffer.lookup_transform(self.target_frame, "carrot", Time())
        except (LookupException, ConnectivityException, ExtrapolationException) as ex:
            self.get_logger().info(f"Could not transform {self.target_frame} to carrot: {type(ex).__name__}")
            return
        p = t.transform.translation
        self.get_logger().info(
            f"carrot at x={p.x:.3f} y={p.y:.3f}, {math.hypot(p.x, p.y):.3f} m from {self.target_frame} "
            f"(stamp {t.header.stamp.sec}.{t.header.stamp.nanosec:09d})")


def main() -> None:
    """Spin the listener until Ctrl-C or SIGTERM."""
    rclpy.init()
    node = CarrotListener()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
