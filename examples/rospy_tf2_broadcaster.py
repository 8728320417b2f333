"""rospy tf2 tutorial shape: broadcast a frame ``carrot`` circling its parent at 2 m, one turn per 10 s, at 10 Hz.

A rospy program with only its imports changed: with ``import rospy``, ``import tf2_ros`` and
``from geometry_msgs.msg import TransformStamped`` it is the same program on real ROS 1
(tests/standins run it both ways against a real listener). ``_parent:=frame`` sets the parent
(default ``world``).

Run: python examples/rospy_tf2_broadcaster.py      (ROS 1: with ROS_VERSION=1 and ROS_MASTER_URI set)
"""

import math

from robotmodel.msgs.geometry_msgs.msg import TransformStamped

from robotmodel import rospy, tf2_ros

if __name__ == "__main__":
    rospy.init_node("carrot_broadcaster")
    parent = rospy.get_param("~parent", "world")
    broadcaster = tf2_ros.TransformBroadcaster()
    t = TransformStamped()
    t.header.frame_id = parent
    t.child_frame_id = "carrot"
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        angle = now.to_sec() * math.pi / 5.0
        t.header.stamp = now
        t.transform.translation.x = 2.0 * math.cos(angle)
        t.transform.translation.y = 2.0 * math.sin(angle)
        t.transform.rotation.z = math.sin(angle / 2.0)
        t.transform.rotation.w = math.cos(angle / 2.0)
        broadcaster.sendTransform(t)
        rate.sleep()
    rospy.loginfo("carrot_broadcaster done")
