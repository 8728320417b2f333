"""One side of bench_dds.py: a transform publisher or subscriber on DDS, as rclpy (Fast DDS) or robotmodel (Cyclone).

    dds_peer.py IMPL sub N          count N flood messages; print one JSON line of results
    dds_peer.py IMPL pub PINGS N    PINGS paced messages (latency), then N as fast as possible

IMPL is ``rclpy`` (run with the Jazzy rclpy venv's Python, RMW_IMPLEMENTATION=rmw_fastrtps_cpp)
or ``robotmodel`` (the project's Python, the DDS wire). robotmodel publishes a one-transform
tf2_msgs/TFMessage, as on /tf; rclpy has no tf2_msgs (no wheel), so it publishes the same
transform as geometry_msgs/TransformStamped (TFMessage's CDR less its 4-byte sequence length).
Both use reliable keep-all endpoints on /bench_tf; the stamp carries the send time (ns), the
child frame says the phase (``ping``/``flood``).
"""

from __future__ import annotations

import json
import sys
import time
from typing import Any

TOPIC = "/bench_tf"
RETRIES = [0]


def _transform(msg: Any) -> Any:
    return msg.transforms[0] if hasattr(msg, "transforms") else msg


def _rclpy(role: str) -> tuple[Any, Any, Any]:
    import rclpy
    from geometry_msgs.msg import TransformStamped
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.node import Node
    from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

    rclpy.init()
    node = Node(f"bench_{role}")
    qos = QoSProfile(depth=1, history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)
    executor = SingleThreadedExecutor()
    executor.add_node(node)

    def make(phase: str, ns: int) -> Any:
        t = TransformStamped()
        t.header.frame_id = "world"
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(ns, 1_000_000_000)
        t.child_frame_id = phase
        t.transform.translation.x = 1.0
        t.transform.rotation.w = 1.0
        return t

    if role == "pub":
        from rclpy.impl.implementation_singleton import rclpy_implementation

        RCLError = rclpy_implementation.RCLError

        pub = node.create_publisher(TransformStamped, TOPIC, qos)

        def publish(msg: Any) -> None:
            # Fast DDS's keep-all writer gives up after its max_blocking_time (100 ms) when the
            # reader has not acknowledged a full history: the message is then offered again.
            while True:
                try:
                    pub.publish(msg)
                    return
                except RCLError:
                    RETRIES[0] += 1

        return publish, lambda: pub.get_subscription_count() > 0, make
    # The subscriber's callbacks run in the main thread's executor (rclpy's usual spin), see main().
    return lambda cb: node.create_subscription(TransformStamped, TOPIC, cb, qos), executor, None


class _Sleeper:
    """robotmodel's subscriber runs its callbacks on the bus's own thread: the main thread only waits."""

    @staticmethod
    def spin_once(timeout_sec: float) -> None:
        time.sleep(timeout_sec)


def _robotmodel(role: str) -> tuple[Any, Any, Any]:
    from robotmodel.bus import History, Node, QoS
    from robotmodel.msgs import TFMessage, make_transform

    node = Node(f"bench_{role}", backend="dds")
    qos = QoS(1, history=History.KEEP_ALL)

    def make(phase: str, ns: int) -> Any:
        t = make_transform("world", phase, (1.0, 0.0, 0.0))
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(ns, 1_000_000_000)
        return TFMessage(transforms=[t])

    if role == "pub":
        pub = node.create_publisher(TFMessage, TOPIC, qos)
        return pub.publish, pub.matched, make
    return lambda cb: node.create_subscription(TFMessage, TOPIC, cb, qos), _Sleeper(), None


def _stamp_ns(msg: Any) -> int:
    s = _transform(msg).header.stamp
    return int(s.sec) * 1_000_000_000 + int(s.nanosec)


def main(argv: list[str]) -> int:
    impl, role, *args = argv
    side, spinner, make = (_rclpy if impl == "rclpy" else _robotmodel)(role)
    if role == "sub":
        flood = int(args[0])
        latencies: list[int] = []
        first = last = 0
        count = 0
        cpu0 = time.process_time()

        def on(msg: Any) -> None:
            nonlocal first, last, count
            now = time.time_ns()
            if _transform(msg).child_frame_id == "ping":
                latencies.append(now - _stamp_ns(msg))
                return
            if count == 0:
                first = _stamp_ns(msg)
            count += 1
            last = now

        side(on)
        print("ready", flush=True)
        deadline = time.monotonic() + 120  # a stalled pair reports what arrived instead of hanging
        while count < flood and time.monotonic() < deadline:
            spinner.spin_once(timeout_sec=0.05)
        latencies.sort()
        print(json.dumps({"received": count, "rate": count / max(last - first, 1) * 1e9,
                          "p50_us": latencies[len(latencies) // 2] / 1e3 if latencies else None,
                          "p90_us": latencies[len(latencies) * 9 // 10] / 1e3 if latencies else None,
                          "pings": len(latencies),
                          "sub_cpu_us_per_msg": (time.process_time() - cpu0) * 1e6 / max(count, 1)}), flush=True)
        return 0
    publish, matched = side, spinner
    pings, flood = int(args[0]), int(args[1])
    while not matched():
        time.sleep(0.01)
    time.sleep(0.5)  # discovery settles on both sides (the reader has matched the writer too)
    for _ in range(pings):
        publish(make("ping", time.time_ns()))
        time.sleep(0.002)
    time.sleep(0.2)
    cpu0 = time.process_time()
    for _ in range(flood):
        publish(make("flood", time.time_ns()))
    print(json.dumps({"pub_cpu_us_per_msg": (time.process_time() - cpu0) * 1e6 / flood,
                      "publish_retries": RETRIES[0]}), flush=True)
    sys.stdin.read()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
