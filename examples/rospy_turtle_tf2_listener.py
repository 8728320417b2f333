"""rospy tf2 tutorial shape: turtle2 follows turtle1, steered from ``lookup_transform`` at 10 Hz.

Each tick looks up turtle1 in the follower's frame and publishes on ``TURTLE/cmd_vel``
``angular.z = 4·atan2(y, x)`` and ``linear.x = 0.5·√(x² + y²)``; a lookup that fails (the
three tf2 exceptions) skips the tick, as in the tutorial. There are no services here, so the
follower is not spawned by this program: start the simulator with it (``rospy_turtlesim.py
_turtles:=...``). A rospy program with only its imports changed (``import rospy``,
``import tf2_ros``, ``from geometry_msgs.msg import Twist``); tests/standins run it both ways.

Run: python examples/rospy_turtle_tf2_listener.py [_turtle:=turtle2]
"""

import math

from robotmodel.msgs.geometry_msgs.msg import Twist

from robotmodel import rospy, tf2_ros

if __name__ == "__main__":
    rospy.init_node("tf2_turtle_listener")
    tf_buffer = tf2_ros.Buffer()
    listener = tf2_ros.TransformListener(tf_buffer)
    turtle_name = rospy.get_param("~turtle", "turtle2")
    turtle_vel = rospy.Publisher(f"{turtle_name}/cmd_vel", Twist, queue_size=1)
    rate = rospy.Rate(10.0)
    while not rospy.is_shutdown():
        try:
            trans = tf_buffer.lookup_transform(turtle_name, "turtle1", rospy.Time())
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException):
            rate.sleep()
            continue
        msg = Twist()
        msg.angular.z = 4 * math.atan2(trans.transform.translation.y, trans.transform.translation.x)
        msg.linear.x = 0.5 * math.sqrt(trans.transform.translation.x ** 2 + trans.transform.translation.y ** 2)
        turtle_vel.publish(msg)
        rate.sleep()
