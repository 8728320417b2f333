"""rclpy tf2 tutorial shape: a node that broadcasts the frame ``carrot`` circling ``world``, from a timer.

An rclpy program with only its imports changed: with ``import rclpy``, ``from rclpy.node import
Node``, ``from tf2_ros import TransformBroadcaster`` and ``from geometry_msgs.msg import
TransformStamped`` it is the same program on ROS 2. Every 0.1 s of the node's clock it sends
``world`` -> ``carrot``: on a circle of the parameter ``radius`` (default 2.0 m, set it with
``--ros-args -p radius:=3.0`` or ``ros2 param set /carrot_broadcaster radius 1.5`` while it
runs), one turn per 10 s: angle = stamp * pi / 5 (stamp in seconds), yaw = angle.

Run: python examples/rclpy_tf2_broadcaster.py [--ros-args -p radius:=3.0]
"""

import math

from robotmodel.msgs.geometry_msgs.msg import TransformStamped

from robotmodel import rclpy
from robotmodel.rclpy.executors import ExternalShutdownException
from robotmodel.rclpy.node import Node
from robotmodel.tf2_ros import TransformBroadcaster


class CarrotBroadcaster(Node):
    """Sends world -> carrot from a timer."""

    def __init__(self) -> None:
        super().__init__("carrot_broadcaster")
        self.declare_parameter("radius", 2.0)
        self.broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self) -> None:
        """Send the carrot where it is now."""
        now = self.get_clock().now()
        angle = now.nanoseconds / 1e9 * math.pi / 5.0
        radius = self.get_parameter("radius").value
        t = TransformStamped()
        t.header.stamp = now.to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = "carrot"
        t.transform.translation.x = radius * math.cos(angle)
        t.transform.translation.y = radius * math.sin(angle)
        t.transform.rotation.z = math.sin(angle / 2.0)
        t.transform.rotation.w = math.cos(angle / 2.0)
        self.broadcaster.sendTransform(t)


def main() -> None:
    """Spin the broadcaster until Ctrl-C or SIGTERM."""
    rclpy.init()
    node = CarrotBroadcaster()
    node.get_logger().info(f"broadcasting carrot at radius {node.get_parameter('radius').value}")
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
