"""A real rospy /rosout reader for tests/standins, run with Debian's /usr/bin/python3.

    rosout_probe.py NODE

Prints ``ready`` once subscribed, then for each rosgraph_msgs/Log from NODE:
``log LEVEL|MSG|FILE|FUNCTION|LINE|TOPIC,TOPIC,...`` (topics sorted).
"""

from __future__ import annotations

import sys

import rospy
from rosgraph_msgs.msg import Log


def main() -> int:
    node = rospy.myargv()[1]

    def heard(msg: Log) -> None:
        if msg.name == node:
            fields = (msg.level, msg.msg, msg.file, msg.function, msg.line, ",".join(sorted(msg.topics)))
            print("log " + "|".join(str(f) for f in fields), flush=True)

    rospy.init_node("rosout_probe", anonymous=True)
    rospy.Subscriber("/rosout", Log, heard, queue_size=100)
    print("ready", flush=True)
    rospy.spin()
    return 0


if __name__ == "__main__":
    sys.exit(main())
