"""A rospy program for tests/standins: Subscriber with callback_args, a latched Publisher fed by fields, spin.

Only the import lines differ between its real-rospy and robotmodel runs (see test_rospy_ros1.py).
"""

from robotmodel.msgs.std_msgs.msg import String

from robotmodel import rospy


def heard(msg, prefix):
    rospy.loginfo("%s %s", prefix, msg.data)


rospy.init_node("echo")
rospy.Subscriber("chatter", String, heard, callback_args="heard")
pub = rospy.Publisher("echoed", String, queue_size=10, latch=True)
pub.publish("started")
rospy.loginfo("ready")
rospy.spin()
print("spin returned", rospy.is_shutdown())
