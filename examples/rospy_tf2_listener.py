"""rospy tf2 tutorial shape: follow the frame ``carrot``, the three-exception try block around a timed lookup.

A rospy program with only its imports changed: with ``import rospy`` and ``import tf2_ros`` it
is the same program on real ROS 1 (tests/standins run it both ways). Started before any
broadcaster, its first lookups wait 0.5 s and end in LookupException, which it catches and
reports, as tf2_ros's; then it prints where the carrot is, 10 times a second.

Run: python examples/rospy_tf2_listener.py         (ROS 1: with ROS_VERSION=1 and ROS_MASTER_URI set)
"""

from robotmodel import rospy, tf2_ros

if __name__ == "__main__":
    rospy.init_node("carrot_listener")
    target = rospy.get_param("~target", "world")
    buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(buffer)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            t = buffer.lookup_transform(target, "carrot", rospy.Time(), rospy.Duration(0.5))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException) as exc:
            rospy.loginfo("no carrot yet: %s", type(exc).__name__)
            rate.sleep()
            continue
        p, q = t.transform.translation, t.transform.rotation
        rospy.loginfo("carrot %.9f %.9f %.9f %.9f", p.x, p.y, q.z, q.w)
        rate.sleep()
    rospy.loginfo("carrot_listener done")
