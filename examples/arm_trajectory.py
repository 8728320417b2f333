"""A joint trajectory played on the bundled arm: positions interpolated onto /joint_states at 50 Hz.

The trajectory is ``trajectory_msgs/JointTrajectory``'s content (joint names, then points
with positions and ``time_from_start``); between two points each joint moves linearly, as a
simple trajectory controller interpolates. After the last point the arm holds still.
robot_state_publisher turns the joint states into TF; ``arm_gripper_listener.py`` prints
where the gripper is.

Run: robotmodel robot-state-publisher arm.urdf.xacro     (the bundled arm; urdf/ in a checkout)
     python examples/arm_trajectory.py [--duration S]
     python examples/arm_gripper_listener.py
"""

from __future__ import annotations

import argparse
import bisect

from robotmodel.bus import Node
from robotmodel.msgs import JointState
from robotmodel.signals import stop_on_signals
from robotmodel.time import Duration, Rate, SystemClock

JOINT_NAMES = ["arm_base_joint", "arm_shoulder_joint", "arm_elbow_joint", "arm_wrist_pitch_joint",
               "arm_wrist_roll_joint", "arm_wrist_yaw_joint", "gripper_left_finger_joint"]
#: (time_from_start in seconds, positions in JOINT_NAMES order): reach out, turn, come back.
POINTS: list[tuple[float, list[float]]] = [
    (0.0, [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
    (2.0, [0.8, 0.5, -1.0, 0.6, 0.0, 0.0, 0.04]),
    (4.0, [-0.6, 0.9, -1.6, 0.9, 1.2, -0.5, 0.01]),
    (6.0, [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
]


def positions_at(t: float) -> list[float]:
    """The trajectory's positions ``t`` seconds after its start (held before and after)."""
    times = [p[0] for p in POINTS]
    if t <= times[0]:
        return list(POINTS[0][1])
    if t >= times[-1]:
        return list(POINTS[-1][1])
    k = bisect.bisect_right(times, t)
    (t0, q0), (t1, q1) = POINTS[k - 1], POINTS[k]
    f = (t - t0) / (t1 - t0)
    return [a + f * (b - a) for a, b in zip(q0, q1, strict=True)]


def main() -> None:
    """Play the trajectory, then hold, until --duration or Ctrl-C."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    args = parser.parse_args()
    shutdown = stop_on_signals()
    clock = SystemClock()
    with Node("arm_trajectory") as node:
        pub = node.create_publisher(JointState, "/joint_states", 10)
        pub.wait_for_subscriptions(1, timeout=10.0)  # robot_state_publisher
        start = clock.now()
        end = None if args.duration is None else start + Duration(seconds=args.duration)
        print(f"[arm_trajectory] trajectory started at {start.nanoseconds} ns: {len(POINTS)} points over "
              f"{POINTS[-1][0]:g} s", flush=True)
        rate = Rate(50.0, clock)
        while not shutdown.is_set() and (end is None or clock.now() < end):
            now = clock.now()
            msg = JointState()
            msg.header.stamp = now.to_msg()
            msg.name = list(JOINT_NAMES)
            msg.position = positions_at((now - start).nanoseconds / 1e9)
            pub.publish(msg)
            rate.sleep()


if __name__ == "__main__":
    main()
