"""A real rospy tf2_ros TransformBroadcaster for tests/ros1, run with Debian's /usr/bin/python3.

    rospy_tf_broadcaster.py NAME PARENT CHILD X Y Z

As node NAME, sends PARENT -> CHILD translated by (X, Y, Z) on /tf at 10 Hz, stamped now;
prints ``ready`` once its node is up.
"""

from __future__ import annotations

import sys

import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped


def main() -> int:
    name, parent, child, *xyz = rospy.myargv()[1:]
    rospy.init_node(name)
    broadcaster = tf2_ros.TransformBroadcaster()
    print("ready", flush=True)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        t = TransformStamped()
        t.header.stamp = rospy.Time.now()
        t.header.frame_id, t.child_frame_id = parent, child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = (float(v) for v in xyz)
        t.transform.rotation.w = 1.0
        broadcaster.sendTransform(t)
        rate.sleep()
    return 0


if __name__ == "__main__":
    sys.exit(main())
