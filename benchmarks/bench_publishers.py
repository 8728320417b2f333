"""joint_states -> /tf through robot-state-publisher on Talos, next to the bus alone, in one run.

    python benchmarks/bench_publishers.py [--samples N] [--rates HZ ...] [--seconds S]

Two set-ups run at once on a private loopback bus (own rendezvous port), each in its own
ROS domain, each a separate process answering this one:

- **bus relay**: a process that takes each JointState off the bus undecoded and puts back
  a ready-made Talos-sized TFMessage (44 transforms, the same frame names) carrying the
  joint state's stamp. Two bus hops and nothing else: the bus's raw latency.
- **robot-state-publisher**: ``robotmodel robot-state-publisher talos_full_v2.urdf
  --publish-frequency 1000``, the real command: decode, 44 joint transforms, encode, publish.

For each, this process sends a 44-joint JointState (pre-encoded; only the stamp changes)
and reads the stamp of the /tf message that comes back:

- latency: one message at a time (ping-pong), the two set-ups in turn so that both see the
  same machine load; p50/p99 of send -> /tf received;
- rate: joint states paced at each rate for a few seconds (stamps 1 ms apart, so the
  1 kHz cap never throttles), counting what comes back; a rate is sustained when every
  message comes back and the sender kept the pace. Publishers block rather than drop.

Goals (issue): 1 kHz sustained on Talos; p50 through RSP at most 0.2 ms above the relay's.
"""

from __future__ import annotations

import argparse
import os
import signal
import socket
import struct
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np

TALOS = "talos_data/robots/talos_full_v2.urdf"
_STAMP = struct.Struct("<iI")
_NS = 1_000_000_000
T0 = 1_700_000_000 * _NS


def talos_path() -> Path:
    import sysconfig

    return Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix/share/example-robot-data/robots" / TALOS


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


# --------------------------------------------------------------------------- the relay process
def relay(robot: Path) -> None:
    from robotmodel.bus import QOS_TF, Node, QoS, Reliability
    from robotmodel.msgs import JointState, TFMessage, serialize
    from robotmodel.publishers import RobotStateLogic

    logic = RobotStateLogic(robot.read_text(), ignore_timestamp=True)
    names = list(logic.model.variables)
    template = bytearray(serialize(TFMessage(logic.joint_state(
        JointState(name=names, position=[0.0] * len(names)), 0) or [])))
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    with Node("bench_relay") as node:
        out = node.create_publisher(TFMessage, "/tf", QOS_TF)

        def on_state(raw: Any) -> None:
            # The joint state's stamp into the first transform's stamp; nothing decoded.
            template[8:16] = raw.payload[4:12]
            out.publish_raw(bytes(template))

        node.create_subscription(JointState, "joint_states", on_state, QoS(5, reliability=Reliability.BEST_EFFORT),
                                 raw=True)
        print("ready", flush=True)
        stop.wait()


# --------------------------------------------------------------------------- this process: the driver
class Driver:
    """Sends pre-encoded joint states on /joint_states and times the /tf messages that come back."""

    def __init__(self, names: list[str], domain_id: int) -> None:
        from robotmodel.bus import QOS_TF, Node, QoS
        from robotmodel.msgs import JointState, TFMessage, serialize

        self.node = Node("bench_driver", domain_id=domain_id)
        self.template = serialize(JointState(name=names, position=[0.1] * len(names)))
        self.pub = self.node.create_publisher(JointState, "/joint_states", QoS(100, block=True))
        self.sent: dict[int, int] = {}
        self.received: dict[int, int] = {}
        self.cond = threading.Condition()
        self.node.create_subscription(TFMessage, "/tf", self._on_tf, QOS_TF, raw=True)

    def _on_tf(self, raw: Any) -> None:
        now = time.perf_counter_ns()
        sec, nanosec = _STAMP.unpack_from(raw.payload, 8)
        with self.cond:
            self.received[sec * _NS + nanosec] = now
            self.cond.notify_all()

    def send(self, stamp_ns: int) -> None:
        payload = self.template[:4] + _STAMP.pack(*divmod(stamp_ns, _NS)) + self.template[12:]
        self.sent[stamp_ns] = time.perf_counter_ns()
        self.pub.publish_raw(payload)

    def wait(self, stamp_ns: int, timeout: float) -> bool:
        with self.cond:
            return self.cond.wait_for(lambda: stamp_ns in self.received, timeout)

    def reset(self) -> None:
        with self.cond:
            self.sent.clear()
            self.received.clear()

    def ping(self, stamp_ns: int) -> float | None:
        """One joint state, then wait for its /tf: microseconds, or None if it never came."""
        self.send(stamp_ns)
        if self.wait(stamp_ns, 2.0):
            return (self.received[stamp_ns] - self.sent[stamp_ns]) / 1e3
        return None

    def rate(self, hz: float, seconds: float, start_ns: int) -> tuple[int, int, float]:
        """Send at ``hz`` for ``seconds``; (sent, came back, achieved send rate)."""
        self.reset()
        count = int(hz * seconds)
        period = 1.0 / hz
        began = time.perf_counter()
        for k in range(count):
            target = began + k * period
            while True:
                left = target - time.perf_counter()
                if left <= 0:
                    break
                if left > 0.0015:
                    time.sleep(left - 0.001)
            self.send(start_ns + k * 1_000_000)
        achieved = count / (time.perf_counter() - began)
        last = start_ns + (count - 1) * 1_000_000
        self.wait(last, 3.0)
        deadline = time.monotonic() + 1.0
        with self.cond:
            while len(self.received) < count and time.monotonic() < deadline:
                self.cond.wait(0.05)
            got = len(self.received)
        return count, got, achieved

    def wait_for_peer(self, timeout: float = 30.0) -> None:
        if not self.pub.wait_for_subscriptions(1, timeout):
            raise SystemExit("no subscription on /joint_states")
        # Warm both ends (serializers, connections) until answers flow.
        deadline = time.monotonic() + timeout
        k = 0
        while time.monotonic() < deadline:
            stamp_ns = T0 - _NS + k * 1_000_000
            self.send(stamp_ns)
            if self.wait(stamp_ns, 0.2):
                return
            k += 1
        raise SystemExit("the peer never answered")

    def close(self) -> None:
        self.node.close()


def latencies(drivers: list[Driver], samples: int) -> list[np.ndarray]:
    """Ping-pong samples taken in turn from each set-up, so that both see the same machine load."""
    out: list[list[float]] = [[] for _ in drivers]
    for k in range(samples):
        for i, driver in enumerate(drivers):
            value = driver.ping(T0 + 10 * _NS + k * 1_000_000)
            if value is not None:
                out[i].append(value)
    return [np.array(v) for v in out]


def start(argv: list[str], domain_id: int) -> subprocess.Popen[str]:
    env = dict(os.environ, ROS_DOMAIN_ID=str(domain_id))
    return subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def run(setups: list[tuple[str, list[str]]], names: list[str], args: argparse.Namespace) -> list[dict[str, Any]]:
    """Both set-ups run at once on one private port, each in its own ROS domain."""
    first_domain = 100 + os.getpid() % 50
    procs: list[subprocess.Popen[str]] = []
    drivers: list[Driver] = []
    try:
        for i, (_, argv) in enumerate(setups):
            procs.append(start(argv, first_domain + i))
            drivers.append(Driver(names, first_domain + i))
        for driver in drivers:
            driver.wait_for_peer()
        latencies(drivers, 200)  # warm-up
        lat = latencies(drivers, args.samples)
        results = []
        for (label, _), driver, samples in zip(setups, drivers, lat, strict=True):
            rates = [(hz, *driver.rate(hz, args.seconds, T0 + (100 + 100 * i) * _NS))
                     for i, hz in enumerate(args.rates)]
            results.append({"label": label, "latency": samples, "rates": rates})
        return results
    finally:
        for driver in drivers:
            driver.close()
        for proc in procs:
            proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()


def report(results: list[dict[str, Any]], samples: int) -> None:
    print(f"\njoint_states -> /tf round trip, Talos (44 moving joints), {samples} ping-pong samples each,")
    print("taken in turn from the two set-ups (both running):")
    print(f"  {'set-up':<24}{'p50 us':>10}{'p99 us':>10}{'lost':>6}")
    for r in results:
        lat = r["latency"]
        print(f"  {r['label']:<24}{np.percentile(lat, 50):>10.1f}{np.percentile(lat, 99):>10.1f}"
              f"{samples - len(lat):>6}")
    relay_p50 = np.percentile(results[0]["latency"], 50)
    rsp_p50 = np.percentile(results[1]["latency"], 50)
    relay_p99 = np.percentile(results[0]["latency"], 99)
    rsp_p99 = np.percentile(results[1]["latency"], 99)
    print(f"  added by robot-state-publisher: p50 {rsp_p50 - relay_p50:+.1f} us, p99 {rsp_p99 - relay_p99:+.1f} us "
          f"(goal: p50 <= +200 us)")
    print("\nsustained joint-state rate (every message back, pace kept):")
    print(f"  {'set-up':<24}{'rate Hz':>9}{'sent':>8}{'back':>8}{'pace Hz':>10}  verdict")
    for r in results:
        for hz, sent, got, achieved in r["rates"]:
            ok = got == sent and achieved >= 0.97 * hz
            print(f"  {r['label']:<24}{hz:>9.0f}{sent:>8}{got:>8}{achieved:>10.0f}  {'ok' if ok else 'NOT sustained'}")
        r["best"] = max([hz for hz, sent, got, achieved in r["rates"] if got == sent and achieved >= 0.97 * hz],
                        default=0)
    print(f"  highest sustained: relay {results[0]['best']:.0f} Hz, robot-state-publisher {results[1]['best']:.0f} Hz "
          "(goal: >= 1000 Hz)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--samples", type=int, default=2000)
    parser.add_argument("--rates", type=float, nargs="+", default=[500, 1000, 2000, 4000, 8000])
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--role", choices=["relay"], help=argparse.SUPPRESS)
    parser.add_argument("--robot", type=Path, default=None, help="URDF (default: example-robot-data's Talos)")
    args = parser.parse_args()
    robot = args.robot or talos_path()
    if args.role == "relay":
        relay(robot)
        return
    from robotmodel.kinematics import KinematicModel

    names = list(KinematicModel.load(robot).variables)
    setups = [
        ("bus relay", [sys.executable, __file__, "--role", "relay", "--robot", str(robot)]),
        ("robot-state-publisher", [sys.executable, "-m", "robotmodel.cli.main", "robot-state-publisher", str(robot),
                                   "--publish-frequency", "1000"]),
    ]
    # A private rendezvous port for this run; the two set-ups are told apart by domain.
    os.environ["ROBOTMODEL_ZENOH_PORT"] = str(free_port())
    os.environ.pop("ZENOH_SESSION_CONFIG_URI", None)
    results = run(setups, names, args)
    report(results, args.samples)


if __name__ == "__main__":
    main()
