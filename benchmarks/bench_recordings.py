"""Loading TF from a recording: robotmodel.recording vs a plain rosbags read-and-deserialize loop.

Writes a bare MCAP (ros2 profile, CDR, zstd chunks, as ``robotmodel record`` writes) of
MINUTES minutes of /tf: FRAMES frames at RATE Hz, one TFMessage per tick holding every
frame (a 100-link chain), plus /tf_static. Then, each in a fresh process so that peak
RSS is its own, in the same run:

- robotmodel: ``load_buffer(file)`` into an unbounded Buffer, then a lookup as a check;
- rosbags: ``Reader(file).messages()`` + ``typestore.deserialize_cdr`` for every message,
  counting transforms (no storage at all: the floor of any rosbags-based loader).

Prints transforms/s (wall clock, and per CPU second, which the host's load moves less)
and peak RSS for both. Goals (issue): >= 1M transforms/s and
<= 1 GiB peak RSS for 10 minutes of 100 frames at 100 Hz (6M transforms).

    python benchmarks/bench_recordings.py [--minutes 10] [--frames 100] [--rate 100]
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

NS = 1_000_000_000


def write_recording(path: Path, minutes: float, frames: int, rate: int) -> int:
    """The MCAP file; returns the number of dynamic transforms in it."""
    from mcap.writer import CompressionType, Writer

    from robotmodel.msgs import TFRecord, encode_tf_records, typestore

    ts = typestore()
    ticks = int(minutes * 60 * rate)
    names = ["world"] + [f"link_{i}" for i in range(frames)]
    with path.open("wb") as f:
        w: Any = Writer(f, chunk_size=1 << 20, compression=CompressionType.ZSTD)
        w.start(profile="ros2", library="bench")
        sid = w.register_schema(name="tf2_msgs/msg/TFMessage", encoding="ros2msg",
                                data=ts.generate_msgdef("tf2_msgs/msg/TFMessage", ros_version=2)[0].encode())
        tf = w.register_channel(topic="/tf", message_encoding="cdr", schema_id=sid)
        tf_static = w.register_channel(topic="/tf_static", message_encoding="cdr", schema_id=sid)
        t0 = 1_700_000_000 * NS
        w.add_message(tf_static, log_time=t0, publish_time=t0, data=encode_tf_records(
            [TFRecord(names[-1], "camera", t0, (0.1, 0.0, 0.05, 0.0, 0.0, 0.0, 1.0))]))
        step = NS // rate
        # Every frame moves its own way (as joints do), so chunks compress as real /tf does, not as a copy.
        phases = [0.37 * i for i in range(frames)]
        for k in range(ticks):
            t = t0 + k * step
            records = []
            for i in range(frames):
                a = 0.5 * math.sin(k * 0.01 + phases[i])
                h = math.sin(a / 2)
                records.append(TFRecord(names[i], names[i + 1], t, (0.1 + 0.01 * a, 0.01 * i, 0.02 * h * h, h * 0.6,
                                                                    0.0, h * 0.8, math.cos(a / 2))))
            w.add_message(tf, log_time=t, publish_time=t, data=encode_tf_records(records))
        w.finish()
    return ticks * frames


def run_robotmodel(path: str) -> dict[str, float]:
    from robotmodel.recording import load_recording

    start = time.perf_counter()
    loaded = load_recording(path, progress=False)
    elapsed = time.perf_counter() - start
    buf = loaded.buffer
    mid = (loaded.start_ns + loaded.end_ns) // 2 + 1234
    buf.lookup_ns("world", "camera", mid)  # the loaded buffer answers
    return {"seconds": elapsed, "transforms": loaded.transforms}


def run_rosbags(path: str) -> dict[str, float]:
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    ts = get_typestore(Stores.ROS2_JAZZY)
    start = time.perf_counter()
    n = 0
    with Reader(path) as reader:
        for conn, _t, raw in reader.messages():
            msg: Any = ts.deserialize_cdr(raw, conn.msgtype)
            n += len(msg.transforms)
    return {"seconds": time.perf_counter() - start, "transforms": n}


def cpu_seconds() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def child(which: str, path: str) -> None:
    cpu = cpu_seconds()
    result = run_robotmodel(path) if which == "robotmodel" else run_rosbags(path)
    result["cpu_seconds"] = cpu_seconds() - cpu  # includes the check lookup; the host's load moves it less
    result["peak_rss_mib"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(json.dumps(result))


def measure(which: str, path: Path) -> dict[str, float]:
    out = subprocess.run([sys.executable, __file__, "--child", which, str(path)], check=True,
                         capture_output=True, text=True).stdout
    result: dict[str, float] = json.loads(out.strip().splitlines()[-1])
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--frames", type=int, default=100)
    parser.add_argument("--rate", type=int, default=100)
    parser.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(*args.child)
        return
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "tf.mcap"
        t = time.perf_counter()
        total = write_recording(path, args.minutes, args.frames, args.rate)
        print(f"recording: {args.minutes:g} min, {args.frames} frames at {args.rate} Hz = {total:,} transforms, "
              f"{path.stat().st_size / 2**20:.0f} MiB MCAP (written in {time.perf_counter() - t:.0f} s)")
        print(f"{'loader':<34}{'seconds':>9}{'transforms/s':>15}{'per CPU-s':>13}{'peak RSS MiB':>14}")
        for which, label in (("robotmodel", "robotmodel load_buffer"),
                             ("rosbags", "rosbags read + deserialize_cdr")):
            r = measure(which, path)
            print(f"{label:<34}{r['seconds']:>9.2f}{r['transforms'] / r['seconds']:>15,.0f}"
                  f"{r['transforms'] / r['cpu_seconds']:>13,.0f}{r['peak_rss_mib']:>14.0f}")


if __name__ == "__main__":
    main()
