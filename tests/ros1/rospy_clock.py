"""A real rospy /clock publisher for tests/ros1 (what a simulator or ``rosbag play --clock`` is), Debian's Python.

    rospy_clock.py START SPEED

Publishes rosgraph_msgs/Clock every 10 ms of wall time: START seconds plus SPEED times the
wall time since it began. Prints ``ready`` once its publisher is up.
"""

from __future__ import annotations

import sys
import time

import rospy
from rosgraph_msgs.msg import Clock


def main() -> int:
    start, speed = (float(a) for a in rospy.myargv()[1:3])
    rospy.init_node("rospy_clock", anonymous=True)
    pub = rospy.Publisher("/clock", Clock, queue_size=10)
    print("ready", flush=True)
    began = time.monotonic()
    while not rospy.is_shutdown():
        pub.publish(Clock(clock=rospy.Time.from_sec(start + speed * (time.monotonic() - began))))
        time.sleep(0.01)
    return 0


if __name__ == "__main__":
    sys.exit(main())
