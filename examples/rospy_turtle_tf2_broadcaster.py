"""rospy tf2 tutorial shape: a turtle's pose (``/TURTLE/pose``) becomes the transform ``world`` → TURTLE.

A rospy program with only its imports changed (``import rospy``, ``import tf2_ros``,
``from turtlesim.msg import Pose``, ``from geometry_msgs.msg import TransformStamped``);
tests/standins run it both ways. The turtle is the private parameter ``~turtle``.

Run: python examples/rospy_turtle_tf2_broadcaster.py __name:=turtle1_tf2_broadcaster _turtle:=turtle1
"""

from __future__ import annotations

import math

from robotmodel.msgs.geometry_msgs.msg import TransformStamped
from robotmodel.msgs.turtlesim.msg import Pose

from robotmodel import rospy, tf2_ros


def handle_turtle_pose(msg: Pose, turtlename: str) -> None:
    """Broadcast world -> turtle from one pose."""
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = "world"
    t.child_frame_id = turtlename
    # A turtle lives in the plane: its pose is x, y and a turn about z.
    t.transform.translation.x = msg.x
    t.transform.translation.y = msg.y
    t.transform.translation.z = 0.0
    t.transform.rotation.z = math.sin(msg.theta / 2.0)
    t.transform.rotation.w = math.cos(msg.theta / 2.0)
    broadcaster.sendTransform(t)


if __name__ == "__main__":
    rospy.init_node("tf2_turtle_broadcaster")
    turtlename = rospy.get_param("~turtle")
    broadcaster = tf2_ros.TransformBroadcaster()
    rospy.Subscriber(f"/{turtlename}/pose", Pose, handle_turtle_pose, turtlename)
    rospy.spin()
