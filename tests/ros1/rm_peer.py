"""A robotmodel ROS 1 node in its own process, for tests/ros1 (run with the project's Python).

    rm_peer.py NAME TOPIC TEXT    publish std_msgs/String "TEXT i" on TOPIC at 10 Hz until shut down

Prints ``ready <slave uri>`` once registered and ``shut down: <reason>`` after a ``shutdown``
call (``rosnode kill``) has closed the node, then exits 0.
"""

from __future__ import annotations

import sys

from robotmodel.ros1 import Ros1Node, typestore


def main() -> int:
    name, topic, text = sys.argv[1:4]
    string = typestore().types["std_msgs/msg/String"]
    node = Ros1Node(name)
    pub = node.advertise(topic, "std_msgs/String")
    print("ready", node.uri, flush=True)
    i = 0
    while not node.wait_for_shutdown(0.1):
        pub.publish(string(data=f"{text} {i}"))
        i += 1
    node.close()
    print("shut down:", node.shutdown_reason, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
