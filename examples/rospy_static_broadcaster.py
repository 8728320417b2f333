"""rospy tf2 tutorial shape: publish one static transform ``world`` → CHILD from the command line, then spin.

A rospy program with only its imports changed: with ``import rospy``, ``import tf2_ros`` and
``from geometry_msgs.msg import TransformStamped`` it is the same program on real ROS 1
(tests/standins run it both ways against real and robotmodel listeners). The rotation is
given as roll, pitch, yaw (radians, fixed axes X then Y then Z, as ROS's) and sent as the
quaternion they make. The transform is latched on ``/tf_static``: listeners that start later
still get it.

Run: python examples/rospy_static_broadcaster.py CHILD X Y Z ROLL PITCH YAW
"""

from __future__ import annotations

import math
import sys

from robotmodel.msgs.geometry_msgs.msg import TransformStamped

from robotmodel import rospy, tf2_ros


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """(x, y, z, w) of the rotation Rz(yaw)·Ry(pitch)·Rx(roll)."""
    cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


if __name__ == "__main__":
    args = rospy.myargv(argv=sys.argv)
    if len(args) != 8:
        rospy.logerr("usage: rospy_static_broadcaster.py child_frame x y z roll pitch yaw")
        sys.exit(1)
    if args[1] == "world":
        rospy.logerr("the child frame cannot be 'world'")
        sys.exit(1)
    rospy.init_node("static_tf2_broadcaster")
    broadcaster = tf2_ros.StaticTransformBroadcaster()
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = "world"
    t.child_frame_id = args[1]
    t.transform.translation.x = float(args[2])
    t.transform.translation.y = float(args[3])
    t.transform.translation.z = float(args[4])
    q = quaternion_from_rpy(float(args[5]), float(args[6]), float(args[7]))
    t.transform.rotation.x = q[0]
    t.transform.rotation.y = q[1]
    t.transform.rotation.z = q[2]
    t.transform.rotation.w = q[3]
    broadcaster.sendTransform(t)
    rospy.loginfo("spinning until shut down: world -> %s", args[1])
    rospy.spin()
