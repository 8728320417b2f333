"""A real rospy JointState reader for tests/ros1, run with Debian's /usr/bin/python3.

    rospy_joint_echo.py TOPIC [TOPIC ...]

Prints ``ready`` once subscribed, then one line per message: ``TOPIC STAMP_NS JSON`` where JSON
is ``[name, position, velocity, effort]`` as rospy decodes them.
"""

from __future__ import annotations

import json
import sys
import threading

import rospy
from sensor_msgs.msg import JointState

_lock = threading.Lock()


def main() -> int:
    rospy.init_node("rospy_joint_echo", anonymous=True)
    for topic in rospy.myargv()[1:]:
        def on_message(msg: JointState, topic: str = topic) -> None:
            fields = [list(msg.name), list(msg.position), list(msg.velocity), list(msg.effort)]
            with _lock:
                sys.stdout.write(f"{topic} {msg.header.stamp.to_nsec()} {json.dumps(fields)}\n")
                sys.stdout.flush()

        rospy.Subscriber(topic, JointState, on_message)
    print("ready", flush=True)
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
