"""One side of bench_ros1.py: a /tf publisher or subscriber, as rospy (Debian's Python) or robotmodel (ours).

    ros1_peer.py IMPL sub N          count N flood messages; print one JSON line of results
    ros1_peer.py IMPL pub PINGS N    PINGS paced messages (latency), then N as fast as possible

IMPL is ``rospy`` (run with /usr/bin/python3) or ``robotmodel`` (the project's Python, ROS 1
wire). Both publish one-transform tf2_msgs/TFMessage on /bench_tf with a reliable keep-all
(unbounded queue) publisher; the header stamp carries the send time (ns), the child frame
says the phase (``ping``/``flood``).
"""

from __future__ import annotations

import json
import sys
import time
from typing import Any

TOPIC = "/bench_tf"


def _rospy(role: str) -> tuple[Any, Any]:
    import rospy
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage

    rospy.init_node(f"bench_{role}", anonymous=False, disable_signals=True)

    def make(phase: str, ns: int) -> Any:
        t = TransformStamped()
        t.header.frame_id = "world"
        t.header.stamp = rospy.Time(ns // 1_000_000_000, ns % 1_000_000_000)
        t.child_frame_id = phase
        t.transform.translation.x = 1.0
        t.transform.rotation.w = 1.0
        return TFMessage(transforms=[t])

    if role == "pub":
        pub = rospy.Publisher(TOPIC, TFMessage, queue_size=None)
        return (pub.publish, lambda: pub.get_num_connections() > 0), make
    return lambda cb: rospy.Subscriber(TOPIC, TFMessage, cb, tcp_nodelay=True), None


def _robotmodel(role: str) -> tuple[Any, Any]:
    from robotmodel.bus import History, Node, QoS
    from robotmodel.msgs import TFMessage, make_transform

    node = Node(f"bench_{role}", backend="ros1")
    qos = QoS(0, history=History.KEEP_ALL)

    def make(phase: str, ns: int) -> Any:
        t = make_transform("world", phase, (1.0, 0.0, 0.0))
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(ns, 1_000_000_000)
        return TFMessage(transforms=[t])

    if role == "pub":
        pub = node.create_publisher(TFMessage, TOPIC, qos)
        return (pub.publish, pub.matched), make
    return lambda cb: node.create_subscription(TFMessage, TOPIC, cb, qos), None


def _stamp_ns(msg: Any) -> int:
    s = msg.transforms[0].header.stamp
    if hasattr(s, "secs"):
        return int(s.secs) * 1_000_000_000 + int(s.nsecs)
    return int(s.sec) * 1_000_000_000 + int(s.nanosec)


def main(argv: list[str]) -> int:
    impl, role, *args = argv
    side, make = (_rospy if impl == "rospy" else _robotmodel)(role)
    if role == "sub":
        flood = int(args[0])
        latencies: list[int] = []
        first = last = 0
        count = 0
        cpu0 = time.process_time()

        def on(msg: Any) -> None:
            nonlocal first, last, count
            now = time.time_ns()
            if msg.transforms[0].child_frame_id == "ping":
                latencies.append(now - _stamp_ns(msg))
                return
            if count == 0:
                first = _stamp_ns(msg)
            count += 1
            last = now

        side(on)
        print("ready", flush=True)
        deadline = time.monotonic() + 600
        while count < flood and time.monotonic() < deadline:
            time.sleep(0.05)
        latencies.sort()
        print(json.dumps({"received": count, "rate": count / max(last - first, 1) * 1e9,
                          "p50_us": latencies[len(latencies) // 2] / 1e3 if latencies else None,
                          "p90_us": latencies[len(latencies) * 9 // 10] / 1e3 if latencies else None,
                          "sub_cpu_us_per_msg": (time.process_time() - cpu0) * 1e6 / max(count, 1)}), flush=True)
        return 0
    publish, matched = side
    pings, flood = int(args[0]), int(args[1])
    while not matched():
        time.sleep(0.01)
    time.sleep(0.5)  # the connection's header exchange is done on both sides
    for _ in range(pings):
        publish(make("ping", time.time_ns()))
        time.sleep(0.002)
    time.sleep(0.2)
    cpu0 = time.process_time()
    for _ in range(flood):
        publish(make("flood", time.time_ns()))
    print(json.dumps({"pub_cpu_us_per_msg": (time.process_time() - cpu0) * 1e6 / flood}), flush=True)
    sys.stdin.read()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
