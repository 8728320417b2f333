"""An rmw_zenoh client that is not ours: zenoh-ros2-sdk (PyPI), in its own process.

``python zenoh_sdk_peer.py PORT`` joins ROS_DOMAIN_ID's domain through the router at
tcp/127.0.0.1:PORT as a peer, as rmw_zenoh's sessions do, publishes std_msgs/String
``hello N`` on /chatter every 50 ms from node ``sdk_talker``, prints ``ready`` once, then
``routers ZID...`` (sorted, maybe none) each time the set of routers its session is linked to
changes. It ends when stdin closes.
"""

from __future__ import annotations

import sys
import threading
import time

from zenoh_ros2_sdk import ROS2Publisher, ZenohSession


def main(port: int) -> int:
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    pub = ROS2Publisher("/chatter", "std_msgs/msg/String", msg_definition="string data", node_name="sdk_talker",
                        router_port=port)
    session = ZenohSession.get_instance(router_port=port).session
    print("ready", flush=True)
    shown: list[str] | None = None
    count = 0
    while not stop.wait(0.05):
        count += 1
        pub.publish(data=f"hello {count}")
        routers = sorted(str(z) for z in session.info.routers_zid())
        if routers != shown:
            print("routers", *routers, flush=True)
            shown = routers
    pub.close()
    session.close()
    return 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1])))
