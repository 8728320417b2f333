"""The odometry pair (robot_controller + sensor_simulator) with robot_state_publisher on the diffbot.

The final pose is checked twice: exactly, against forward Euler recomputed here from the
twists and stamps the simulator put on /odom; and against the drive pattern's integral
computed here in closed form and by quadrature (the tolerance allows for a 10 Hz command
stream sampled at 20 Hz). The wheel frames robot_state_publisher publishes carry the wheel
angles (v ∓ ω·separation/2)/radius integrated from the same twists, with the diffbot's
wheel radius and separation read from its URDF here.
"""

from __future__ import annotations

import math
import re
import signal
import threading
import time

import numpy as np
import robotmodel.robots
from livebus import Proc

from robotmodel.bus import Node
from robotmodel.model import load
from robotmodel.msgs import Odometry
from robotmodel.tf import Buffer, Time
from robotmodel.tf_ros import TransformListener

SCALE = "5"


def _ideal_pose() -> tuple[float, float, float]:
    # 10 s at 0.5 m/s along x, 10 s turning at 0.5 rad/s, then v = w = 0.5 sin(tau) for 10 s.
    tau = np.linspace(0.0, 10.0, 400_001)
    v = 0.5 * np.sin(tau)
    theta = 5.0 + 0.5 * (1.0 - np.cos(tau))
    x = 5.0 + float(np.trapezoid(v * np.cos(theta), tau))
    y = float(np.trapezoid(v * np.sin(theta), tau))
    return x, y, float(theta[-1])


def _wheel_geometry() -> tuple[float, float]:
    desc = load(robotmodel.robots.path("diffbot.urdf.xacro"))
    joints = {j.name: j for j in desc.joints}
    left = np.asarray(joints["left_wheel_joint"].origin.xyz)
    right = np.asarray(joints["right_wheel_joint"].origin.xyz)
    wheel = next(link for link in desc.links if link.name == "left_wheel")
    return float(wheel.visuals[0].geometry.radius), float(np.linalg.norm(left - right))


def _final(sim: Proc) -> dict[str, float]:
    m = sim.wait_line(r"final pose: (.*)", timeout=30)
    return {k: float(v) for k, v in re.findall(r"(\w+)=(-?[\d.]+)", m.group(1))}


def test_final_pose_equals_the_integral(live):
    odoms: list[Odometry] = []
    lock = threading.Lock()

    def on_odom(msg: Odometry) -> None:
        with lock:
            odoms.append(msg)

    buffer = Buffer()
    with Node("odometry_check") as node, TransformListener(buffer, node):
        node.create_subscription(Odometry, "/odom", on_odom, 1000)
        rsp = live.robotmodel("robot-state-publisher", str(robotmodel.robots.path("diffbot.urdf.xacro")))
        # The simulator runs until told to stop, not for a fixed time: a controller slow to start on a
        # loaded machine would otherwise still be driving when the simulator's time ran out.
        sim = live.example("sensor_simulator.py", "--time-scale", SCALE)
        sim.wait_line("integrating")
        ctl = live.example("robot_controller.py", "--time-scale", SCALE, "--duration", "32")
        ctl.wait_line("stopped", timeout=60)
        assert ctl.popen.wait(30) == 0
        with lock:
            sent = len(odoms)
        # Stopped once an /odom after the controller's exit shows its last (zero) command integrated.
        deadline = time.monotonic() + 30
        while True:
            with lock:
                later = odoms[sent:]
            if any(m.twist.twist.linear.x == 0.0 and m.twist.twist.angular.z == 0.0 for m in later):
                break
            assert time.monotonic() < deadline, "the simulator never integrated the controller's stop"
            time.sleep(0.05)
        assert sim.stop(signal.SIGINT, timeout=30) == 0
        final = _final(sim)
        with lock:
            received = list(odoms)
        wheels = {n: buffer.lookup_transform("base_link", n, Time()) for n in ("left_wheel", "right_wheel")}
        base = buffer.lookup_transform("odom", "base_link", Time())
        rsp.stop()
    assert len(received) > 100
    # Exact: forward Euler over the received steps, from the first received pose.
    first = received[0]
    x, y = first.pose.pose.position.x, first.pose.pose.position.y
    q = first.pose.pose.orientation
    theta = 2 * math.atan2(q.z, q.w)
    assert abs(x) < 1e-12 and abs(y) < 1e-12 and abs(theta) < 1e-12  # nothing moved before it
    radius, separation = _wheel_geometry()
    assert (radius, separation) == (0.05, 0.34)
    left = right = 0.0
    prev = first.header.stamp.sec * 10**9 + first.header.stamp.nanosec
    max_dt = 0.0
    for msg in received[1:]:
        stamp = msg.header.stamp.sec * 10**9 + msg.header.stamp.nanosec
        dt = (stamp - prev) / 1e9
        max_dt = max(max_dt, dt)
        prev = stamp
        v, w = msg.twist.twist.linear.x, msg.twist.twist.angular.z
        x, y, theta = x + v * math.cos(theta) * dt, y + v * math.sin(theta) * dt, theta + w * dt
        left += (v - w * separation / 2) / radius * dt
        right += (v + w * separation / 2) / radius * dt
        assert abs(msg.pose.pose.position.x - x) < 1e-9 and abs(msg.pose.pose.position.y - y) < 1e-9
    assert abs(final["x"] - x) < 1e-6 and abs(final["y"] - y) < 1e-6 and abs(final["theta"] - theta) < 1e-6
    # The wheels' angles came from the first step on, when nothing moved yet.
    assert abs(final["left_wheel"] - left) < 1e-6 and abs(final["right_wheel"] - right) < 1e-6
    # Against the drive pattern's own integral.
    ix, iy, itheta = _ideal_pose()
    # The simulator samples a real-time command stream: each of the three switches of the pattern
    # lands up to one step late, and a step is longer when the machine stalls the simulator (at
    # 0.5 m/s and 0.5 rad/s that costs at most 0.5 per second of step per switch).
    tol = max(0.1, 3 * 0.5 * max_dt + 0.05)
    assert abs(x - ix) < tol and abs(y - iy) < tol and abs(theta - itheta) < tol, (x, y, theta, ix, iy, itheta, max_dt)
    # robot_state_publisher turned the wheels by the last joint state: a rotation about y.
    for name, angle in (("left_wheel", left), ("right_wheel", right)):
        r = wheels[name].transform.rotation
        assert abs(r.x) < 1e-9 and abs(r.z) < 1e-9
        turned = 2 * math.atan2(r.y, r.w)
        assert abs(math.remainder(turned - angle, 2 * math.pi)) < 1e-6, (name, turned, angle)
    # odom -> base_footprint (the simulator) -> base_link (0.05 up, the diffbot's fixed base_joint).
    t = base.transform.translation
    assert abs(t.x - x) < 1e-9 and abs(t.y - y) < 1e-9 and abs(t.z - 0.05) < 1e-12
