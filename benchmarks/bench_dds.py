"""/tf between two processes on DDS: robotmodel's DDS wire (Cyclone DDS) next to Jazzy's rclpy on Fast DDS, same run.

Each pair is two processes in one private ROS_DOMAIN_ID, discovery on loopback: a subscriber,
then a publisher of one transform on /bench_tf (reliable keep-all on both sides; robotmodel
as tf2_msgs/TFMessage, rclpy as geometry_msgs/TransformStamped since tf2_msgs has no wheel).
Each subscriber decodes every message into a message object.

- Latency: PINGS messages 2 ms apart; one-way = receive time - the send time in the stamp
  (one clock: same machine); p50 and p90.
- Throughput: N messages published as fast as the publisher can; rate = N / (last receive -
  first send).
- CPU per message on each side (process time), steadier than wall clock under load.

Run: python benchmarks/bench_dds.py [--quick]   (needs the rclpy venv: .ci/rclpy-venv, or
ROBOTMODEL_RCLPY_PYTHON naming its interpreter)
"""

from __future__ import annotations

import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import _harness

QUICK = "--quick" in sys.argv
PINGS = 300 if QUICK else 1_000
FLOOD = 5_000 if QUICK else 20_000
HERE = Path(__file__).resolve().parent
PEER = HERE / "dds_peer.py"
RCLPY = Path(os.environ.get("ROBOTMODEL_RCLPY_PYTHON", str(HERE.parent / ".venv-rclpy" / "bin" / "python")))
PYTHONS = {"rclpy": str(RCLPY), "robotmodel": sys.executable}
RMWS = {"rclpy": "rmw_fastrtps_cpp", "robotmodel": "rmw_cyclonedds_cpp"}
# The peers' stderr goes to this file (BENCH_DDS_STDERR), else nowhere.
_ERRORS_TO = os.environ.get("BENCH_DDS_STDERR")
ERRORS: Any = Path(_ERRORS_TO).open("a") if _ERRORS_TO else subprocess.DEVNULL  # noqa: SIM115


def run_pair(impl: str, home: str) -> dict[str, Any]:
    """One subscriber and one publisher of ``impl`` in a domain of their own; their merged result lines."""
    env = dict(os.environ, RMW_IMPLEMENTATION=RMWS[impl], ROS_DOMAIN_ID=str(random.randint(120, 200)),
               ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST", ROS_HOME=home, ROS_LOG_DIR=f"{home}/log",
               PYTHONUNBUFFERED="1")
    for key in ("ROS_STATIC_PEERS", "ROS_LOCALHOST_ONLY", "ROS_VERSION", "ROS_MASTER_URI"):
        env.pop(key, None)
    if impl == "rclpy":
        env = {k: v for k, v in env.items() if not k.startswith(("PYTHON", "VIRTUAL_ENV"))} | {"PYTHONUNBUFFERED": "1"}
    python = PYTHONS[impl]
    return _harness.run_pair([python, str(PEER), impl, "sub", str(FLOOD)],
                             [python, str(PEER), impl, "pub", str(PINGS), str(FLOOD)], env, ERRORS)


def main() -> int:
    if not RCLPY.exists():
        print(f"bench_dds: no rclpy at {RCLPY} (run .ci/rclpy-venv or set ROBOTMODEL_RCLPY_PYTHON)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as home:
        results = {impl: run_pair(impl, home) for impl in ("rclpy", "robotmodel")}
    ours, theirs = results["robotmodel"], results["rclpy"]
    print(f"{FLOOD} flood messages, {PINGS} pings, one transform (robotmodel: TFMessage on Cyclone DDS; "
          f"rclpy: TransformStamped on Fast DDS)")
    _harness.print_wire_table(ours, theirs, "rclpy")
    print(f"received: robotmodel {ours['received']}/{FLOOD} (+{ours['pings']}/{PINGS} pings), "
          f"rclpy {theirs['received']}/{FLOOD} (+{theirs['pings']}/{PINGS} pings); "
          f"rclpy publishes retried after Fast DDS's 100 ms block: {theirs['publish_retries']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
