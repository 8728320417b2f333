"""/tf between two ROS 1 nodes on one private roscore: robotmodel's ROS 1 wire next to rospy, same run.

Each pair is two processes on the same master (Debian's roscore on a free port, private
ROS_HOME): a subscriber, then a publisher of one-transform tf2_msgs/TFMessage on
/bench_tf (reliable keep-all, unbounded queue; subscriber with TCP_NODELAY).

- Latency: PINGS messages 2 ms apart; one-way = receive time - the send time in the stamp
  (one clock: same machine); p50 and p90.
- Throughput: N messages published as fast as the publisher can; the subscriber decodes
  each into a message object. Rate = N / (last receive - first send).
- CPU per message on each side (process time), steadier than wall clock under load.

Run: python benchmarks/bench_ros1.py [--quick]   (needs Debian's ROS 1: roscore, python3-rospy)
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import _harness

QUICK = "--quick" in sys.argv
PINGS = 300 if QUICK else 1_000
FLOOD = 5_000 if QUICK else 20_000
PEER = Path(__file__).resolve().with_name("ros1_peer.py")
PYTHONS = {"rospy": "/usr/bin/python3", "robotmodel": sys.executable}


def run_pair(impl: str, env: dict[str, str]) -> dict[str, Any]:
    """One subscriber and one publisher of ``impl``; their merged result lines."""
    python = PYTHONS[impl]
    return _harness.run_pair([python, str(PEER), impl, "sub", str(FLOOD)],
                             [python, str(PEER), impl, "pub", str(PINGS), str(FLOOD)], env)


def main() -> int:
    with _harness.private_roscore() as env:
        results = {impl: run_pair(impl, env) for impl in ("rospy", "robotmodel")}
    ours, theirs = results["robotmodel"], results["rospy"]
    print(f"{FLOOD} flood messages, {PINGS} pings, one-transform TFMessage")
    _harness.print_wire_table(ours, theirs, "rospy")
    print(f"received: robotmodel {ours['received']}/{FLOOD}, rospy {theirs['received']}/{FLOOD}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
