"""A robotmodel ROS 1 node in its own process, for tests/ros1 (run with the project's Python).

    rm_peer.py NAME TOPIC TEXT [--bus]   publish std_msgs/String "TEXT i" on TOPIC at 10 Hz until shut down

Without ``--bus`` the node is a :class:`robotmodel.ros1.Ros1Node` (the wire itself); with it a
:class:`robotmodel.bus.Node` on the ROS 1 wire (the layer every tool uses; ROS_MASTER_URI).
Prints ``ready <slave uri>`` once registered and ``shut down: <reason>`` after a ``shutdown``
call (``rosnode kill``) has closed the node, then exits 0.
"""

from __future__ import annotations

import sys

from robotmodel.ros1 import Ros1Node, typestore


def _bus(name: str, topic: str, text: str) -> int:
    from robotmodel.bus import Node
    from robotmodel.signals import stop_on_signals

    string = typestore().types["std_msgs/msg/String"]
    stop = stop_on_signals()
    with Node(name.lstrip("/"), backend="ros1") as node:
        pub = node.create_publisher(string, topic, 10)
        print("ready", node.handle.ros1.uri, flush=True)  # type: ignore[attr-defined]
        i = 0
        while not stop.wait(0.1):
            pub.publish(string(data=f"{text} {i}"))
            i += 1
    return 0


def main() -> int:
    name, topic, text = sys.argv[1:4]
    if "--bus" in sys.argv[4:]:
        return _bus(name, topic, text)
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
