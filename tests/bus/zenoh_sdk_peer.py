"""An rmw_zenoh client that is not ours: zenoh-ros2-sdk (PyPI), in its own process.

``python zenoh_sdk_peer.py ROLE PORT`` joins ROS_DOMAIN_ID's domain as a peer of the router at
tcp/127.0.0.1:PORT, as rmw_zenoh's sessions do, prints ``ready`` once, then one line per
event, and ends when stdin closes. Roles:

- ``talker``: node ``sdk_talker`` publishes std_msgs/String ``hello N`` on /chatter every
  50 ms and prints ``routers ZID...`` (sorted, maybe none) each time the set of routers its
  session is linked to changes.
- ``joint_listener``: node ``sdk_listener`` prints ``got NAMES POSITIONS`` (JSON) per
  sensor_msgs/JointState on /joint_states. The SDK reads message definitions from .msg files
  (fetched with git unless present): ROS's own texts are written for it here.
"""

from __future__ import annotations

import json
import sys
import tempfile
import threading
from pathlib import Path

from zenoh_ros2_sdk import ROS2Publisher, ROS2Subscriber, ZenohSession, get_registry

# The .msg texts of ROS 2 Jazzy (common_interfaces, rcl_interfaces), comments left out.
MSGS = {
    "sensor_msgs/msg/JointState": "std_msgs/Header header\nstring[] name\nfloat64[] position\n"
                                  "float64[] velocity\nfloat64[] effort\n",
    "std_msgs/msg/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
    "builtin_interfaces/msg/Time": "int32 sec\nuint32 nanosec\n",
}


def say(*parts: str) -> None:
    sys.stdout.write(" ".join(parts) + "\n")
    sys.stdout.flush()


def main(role: str, port: int) -> int:
    stop = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), stop.set()), daemon=True).start()
    session = ZenohSession.get_instance(router_port=port).session
    if role == "talker":
        pub = ROS2Publisher("/chatter", "std_msgs/msg/String", msg_definition="string data", node_name="sdk_talker",
                            router_port=port)
        say("ready")
        shown: list[str] | None = None
        count = 0
        while not stop.wait(0.05):
            count += 1
            pub.publish(data=f"hello {count}")
            routers = sorted(str(z) for z in session.info.routers_zid())
            if routers != shown:
                say("routers", *routers)
                shown = routers
        pub.close()
    elif role == "joint_listener":
        with tempfile.TemporaryDirectory() as msgs:
            for name, text in MSGS.items():
                path = Path(msgs, *name.split("/")).with_suffix(".msg")
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(text)
            get_registry(msgs)
            sub = ROS2Subscriber("/joint_states", "sensor_msgs/msg/JointState",
                                 lambda m: say("got", json.dumps([list(m.name), [float(p) for p in m.position]])),
                                 node_name="sdk_listener", router_port=port)
            say("ready")
            stop.wait()
            sub.close()
    else:
        raise SystemExit(f"unknown role {role}")
    session.close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
