"""A real rospy JointState publisher for tests/ros1, run with Debian's /usr/bin/python3.

    rospy_joint_states.py TOPIC NAME=VALUE [NAME=VALUE ...]

Publishes those positions on TOPIC at 10 Hz, stamped now, printing ``ready`` once its node is up.
"""

from __future__ import annotations

import sys

import rospy
from sensor_msgs.msg import JointState


def main() -> int:
    argv = rospy.myargv()[1:]
    topic, words = argv[0], argv[1:]
    names = [w.partition("=")[0] for w in words]
    positions = [float(w.partition("=")[2]) for w in words]
    rospy.init_node("rospy_joint_states", anonymous=True)
    pub = rospy.Publisher(topic, JointState, queue_size=10)
    print("ready", flush=True)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        msg = JointState(name=names, position=positions)
        msg.header.stamp = rospy.Time.now()
        pub.publish(msg)
        rate.sleep()
    return 0


if __name__ == "__main__":
    sys.exit(main())
