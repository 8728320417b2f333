"""read_odom_bag.py: the recording it makes, read back here with rosbags, equals what it prints."""

from __future__ import annotations

import math
import re
import subprocess
import sys

from conftest import REPO
from rosbags.highlevel import AnyReader


def test_reads_back_the_odometry_it_recorded(tmp_path):
    bag = tmp_path / "odom.mcap"
    done = subprocess.run([sys.executable, str(REPO / "examples" / "read_odom_bag.py"), "--duration", "5",
                           "--output", str(bag)], capture_output=True, text=True, timeout=120, check=True)
    lines = done.stdout.splitlines()
    assert lines[0] == f"wrote 101 /odom messages to {bag}"
    printed = [re.fullmatch(r"/odom (\d+): x=(\S+) y=(\S+) yaw=(\S+)", line) for line in lines[1:]]
    assert all(printed) and len(printed) == 101
    with AnyReader([bag]) as reader:
        assert [c.topic for c in reader.connections] == ["/odom"]
        recorded = [(t, reader.deserialize(raw, c.msgtype)) for c, t, raw in reader.messages()]
    for m, (t, msg) in zip(printed, recorded, strict=True):
        assert int(m.group(1)) == t
        assert msg.header.stamp.sec * 10**9 + msg.header.stamp.nanosec == t
        assert float(m.group(2)) == msg.pose.pose.position.x and float(m.group(3)) == msg.pose.pose.position.y
        q = msg.pose.pose.orientation
        assert abs(float(m.group(4)) - 2 * math.atan2(q.z, q.w)) < 1e-12
        # The documented circle: radius 1 m, 0.5 rad/s, from the origin heading along x.
        s = (t - recorded[0][0]) / 1e9
        assert abs(msg.pose.pose.position.x - math.sin(0.5 * s)) < 1e-12
        assert abs(msg.pose.pose.position.y - (1 - math.cos(0.5 * s))) < 1e-12
        assert abs(math.remainder(float(m.group(4)) - 0.5 * s, 2 * math.pi)) < 1e-12
    # --bag reads another recording without writing one.
    again = subprocess.run([sys.executable, str(REPO / "examples" / "read_odom_bag.py"), "--bag", str(bag)],
                           capture_output=True, text=True, timeout=120, check=True)
    assert again.stdout.splitlines() == lines[1:]
