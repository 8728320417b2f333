"""rospy: odometry to TF, each ``odom`` message (nav_msgs/Odometry) re-sent as the transform it describes.

The transform is ``header.frame_id`` → ``child_frame_id`` at the message's stamp, from its
pose: what a robot's base driver broadcasts so that ``odom`` → ``base_link`` is on ``/tf``.
A rospy program with only its imports changed (``import rospy``, ``import tf2_ros``,
``from nav_msgs.msg import Odometry``, ``from geometry_msgs.msg import TransformStamped``);
tests/standins run it both ways, fed by rospy_diff_drive.py.

Run: python examples/rospy_odom_to_tf.py [odom:=/my/odom]
"""

from robotmodel.msgs.geometry_msgs.msg import TransformStamped
from robotmodel.msgs.nav_msgs.msg import Odometry

from robotmodel import rospy, tf2_ros


def handle_odometry(msg: Odometry) -> None:
    """Broadcast the transform one odometry message describes."""
    t = TransformStamped()
    t.header = msg.header
    t.child_frame_id = msg.child_frame_id
    t.transform.translation.x = msg.pose.pose.position.x
    t.transform.translation.y = msg.pose.pose.position.y
    t.transform.translation.z = msg.pose.pose.position.z
    t.transform.rotation = msg.pose.pose.orientation
    broadcaster.sendTransform(t)


if __name__ == "__main__":
    rospy.init_node("odom_to_tf")
    broadcaster = tf2_ros.TransformBroadcaster()
    rospy.Subscriber("odom", Odometry, handle_odometry, queue_size=10)
    rospy.spin()
