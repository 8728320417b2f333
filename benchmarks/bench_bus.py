"""/tf over the bus between two processes, next to raw zenoh measured in the same run.

- Latency: ping-pong. This process publishes a one-transform TFMessage on /bench/ping
  (serialize, attachment, put); a second process decodes it and publishes it back on
  /bench/pong; this process decodes the reply. One-way = round trip / 2, so each way pays
  one encode and one decode. Raw zenoh: the same payload bytes bounced with plain
  ``put``/subscriber callbacks on the same two sessions. Target p50 <= 0.3 ms.
- Throughput: this process publishes N TFMessages (one transform each, each serialized)
  as fast as it can on a reliable keep-all publisher (rmw_zenoh blocks only for that
  profile, so nothing is dropped); the other process decodes and counts them.
  Rate = N / (last receive - first send). Raw zenoh:
  the same count of same-size payloads with ``put`` (BLOCK) to a counting callback.
  Two bus receivers: TFMessage objects, and ``TFRecords`` (parent, child, stamp, pose
  tuples: what a TF listener inserts into its buffer). Targets >= 100k TF messages/s and
  none lost.

Run: python benchmarks/bench_bus.py [--quick]
Both processes use a private loopback port and ROS domain, so a router or other bus users
on the machine are not disturbed.
"""

from __future__ import annotations

import os
import random
import socket
import statistics
import subprocess
import sys
import threading
import time
from typing import Any

QUICK = "--quick" in sys.argv
PINGS = 2_000 if QUICK else 10_000
FLOOD = 50_000 if QUICK else 200_000
RAW_PREFIX = "bench_raw"


def _tf_message() -> Any:
    from robotmodel.msgs import TFMessage, make_transform

    return TFMessage([make_transform("odom", "base_link", (1.0, 2.0, 0.0), (0.0, 0.0, 0.38268343, 0.92387953),
                                     stamp_ns=1_700_000_000_123_456_789)])


# ---------------------------------------------------------------- the other process


def _flood_qos(qos: Any, history: Any) -> Any:
    # Reliable keep-all is rmw_zenoh's one blocking profile (QOS_TF drops under overload, as
    # upstream's keep-last does); the raw zenoh peer below blocks too, so both lose nothing.
    return qos(0, history=history.KEEP_ALL)


def child() -> int:
    """Echo pings back and count floods; driven by lines on stdin."""
    import zenoh

    from robotmodel.bus import QOS_TF, History, Node, QoS, TFRecords
    from robotmodel.msgs import TFMessage

    flood_qos = _flood_qos(QoS, History)

    node = Node("bench_echo")
    session = node.context.backend.session  # type: ignore[attr-defined]
    pong = node.create_publisher(TFMessage, "/bench/pong", QOS_TF)
    node.create_subscription(TFMessage, "/bench/ping", pong.publish, QOS_TF)
    raw_pong = session.declare_publisher(f"{RAW_PREFIX}/pong", congestion_control=zenoh.CongestionControl.BLOCK)
    session.declare_subscriber(f"{RAW_PREFIX}/ping", lambda s: raw_pong.put(s.payload))

    state = {"n": 0, "target": 0, "last": 0}
    done = threading.Event()

    def count(_: Any) -> None:
        state["n"] += 1
        if state["n"] >= state["target"]:
            state["last"] = time.time_ns()
            done.set()

    node.create_subscription(TFMessage, "/bench/flood", count, flood_qos)
    node.create_subscription(TFRecords, "/bench/flood_records", count, flood_qos)
    session.declare_subscriber(f"{RAW_PREFIX}/flood", count)
    print("ready", flush=True)
    for line in sys.stdin:
        words = line.split()
        if words and words[0] == "arm":
            state.update(n=0, target=int(words[1]), last=0)
            done.clear()
            cpu = time.process_time()
            print("armed", flush=True)
            if not done.wait(60):
                state["last"] = time.time_ns()
            print("count", state["n"], state["last"], time.process_time() - cpu, flush=True)
    node.close()
    return 0


# ---------------------------------------------------------------- this process


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def ping_pong(send: Any, arrived: threading.Event, n: int) -> list[float]:
    """One-way times (us) from round trips."""
    times = []
    for _ in range(n):
        arrived.clear()
        t0 = time.perf_counter_ns()
        send()
        if not arrived.wait(2.0):
            raise RuntimeError("a ping was not answered within 2 s")
        times.append((time.perf_counter_ns() - t0) / 2000.0)
    return times


def flood(proc: subprocess.Popen[str], send: Any, n: int) -> tuple[int, float, float]:
    """(received, messages/s, receiver CPU seconds per message)."""
    assert proc.stdin and proc.stdout
    proc.stdin.write(f"arm {n}\n")
    proc.stdin.flush()
    assert proc.stdout.readline().strip() == "armed"
    time.sleep(0.2)
    t0 = time.time_ns()
    for _ in range(n):
        send()
    words = proc.stdout.readline().split()
    received, last, cpu = int(words[1]), int(words[2]), float(words[3])
    return received, received / ((last - t0) / 1e9), cpu / max(received, 1)


def main() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    os.environ["ROBOTMODEL_ZENOH_PORT"] = str(port)
    os.environ["ROS_DOMAIN_ID"] = str(random.randint(150, 230))

    import zenoh

    from robotmodel.bus import QOS_TF, History, Node, QoS, codec_for
    from robotmodel.msgs import TFMessage

    flood_qos = _flood_qos(QoS, History)

    node = Node("bench_driver")  # first: holds the private port
    proc = subprocess.Popen([sys.executable, __file__, "--child"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            text=True, env=dict(os.environ))
    try:
        assert proc.stdout is not None
        assert proc.stdout.readline().strip() == "ready"
        session = node.context.backend.session  # type: ignore[attr-defined]
        msg = _tf_message()
        payload = codec_for(TFMessage).encode(msg)

        got = threading.Event()
        ping = node.create_publisher(TFMessage, "/bench/ping", QOS_TF)
        node.create_subscription(TFMessage, "/bench/pong", lambda m: got.set(), QOS_TF)
        raw_got = threading.Event()
        raw_ping = session.declare_publisher(f"{RAW_PREFIX}/ping", congestion_control=zenoh.CongestionControl.BLOCK)
        session.declare_subscriber(f"{RAW_PREFIX}/pong", lambda s: raw_got.set())
        if not ping.wait_for_subscriptions(1, 10):
            raise RuntimeError("the echo process did not subscribe")
        time.sleep(0.5)

        ping_pong(lambda: ping.publish(msg), got, 500)  # warm both sides
        ping_pong(lambda: raw_ping.put(payload), raw_got, 500)
        bus = ping_pong(lambda: ping.publish(msg), got, PINGS)
        raw = ping_pong(lambda: raw_ping.put(payload), raw_got, PINGS)

        flood_pub = node.create_publisher(TFMessage, "/bench/flood", flood_qos)
        records_pub = node.create_publisher(TFMessage, "/bench/flood_records", flood_qos)
        raw_flood = session.declare_publisher(f"{RAW_PREFIX}/flood", congestion_control=zenoh.CongestionControl.BLOCK)
        time.sleep(0.5)
        flood(proc, lambda: flood_pub.publish(msg), 2000)
        bus_n, bus_rate, bus_cpu = flood(proc, lambda: flood_pub.publish(msg), FLOOD)
        rec_n, rec_rate, rec_cpu = flood(proc, lambda: records_pub.publish(msg), FLOOD)
        raw_n, raw_rate, raw_cpu = flood(proc, lambda: raw_flood.put(payload), FLOOD)
        cpu0 = time.process_time()
        for _ in range(FLOOD // 4):
            flood_pub.publish(msg)
        pub_cpu = (time.process_time() - cpu0) / (FLOOD // 4)
    finally:
        if proc.stdin:
            proc.stdin.close()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
        node.close()

    p50, p99 = statistics.median(bus), percentile(bus, 0.99)
    r50, r99 = statistics.median(raw), percentile(raw, 0.99)
    print(f"/tf between two processes ({len(payload)}-byte TFMessage, 1 transform); {PINGS} pings, {FLOOD} floods")
    print(f"{'measurement':<30}{'bus':>14}{'raw zenoh':>14}{'bus/raw':>10}   target")
    print(f"{'latency one-way p50 (us)':<30}{p50:>14.1f}{r50:>14.1f}{p50 / r50:>10.2f}   <= 300 us")
    print(f"{'latency one-way p99 (us)':<30}{p99:>14.1f}{r99:>14.1f}{p99 / r99:>10.2f}")
    row = "{:<30}{:>14,.0f}{:>14,.0f}{:>10.2f}   {}"
    print(row.format("throughput (msgs/s)", bus_rate, raw_rate, bus_rate / raw_rate, ">= 100,000"))
    print(row.format("  received as TFRecords", rec_rate, raw_rate, rec_rate / raw_rate, ">= 100,000"))
    print(f"{'lost':<30}{FLOOD - bus_n:>14}{FLOOD - raw_n:>14}{'':>10}   0")
    print(f"{'  received as TFRecords':<30}{FLOOD - rec_n:>14}")
    # On a shared machine wall-clock rates follow the load; CPU per message is the code's own cost.
    cpu_row = "{:<30}{:>14.2f}{:>14.2f}{:>10.2f}"
    print(cpu_row.format("receiver CPU per msg (us)", bus_cpu * 1e6, raw_cpu * 1e6, bus_cpu / raw_cpu))
    print(cpu_row.format("  received as TFRecords", rec_cpu * 1e6, raw_cpu * 1e6, rec_cpu / raw_cpu))
    print(f"{'publisher CPU per msg (us)':<30}{pub_cpu * 1e6:>14.2f}")
    print(f"{'CPU-bound rate (msgs/s)':<30}{1 / max(bus_cpu, pub_cpu):>14,.0f}{'':>24}   >= 100,000")
    return 0


if __name__ == "__main__":
    sys.exit(child() if "--child" in sys.argv else main())
