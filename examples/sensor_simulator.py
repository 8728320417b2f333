"""The odometry tutorial's sensor simulator: /cmd_vel integrated into odometry at 20 Hz.

A differential-drive robot on the plane: each step integrates the latest /cmd_vel
over the time since the previous step (forward Euler; 0.05 s of the example's clock
when the loop keeps up) and publishes odom → base_footprint
on /tf, ``nav_msgs/Odometry`` on /odom (the pose, and the twist the step used), and the
wheel joints' angles on /joint_states, turned from the wheel speeds
(v ∓ ω·separation/2)/radius, so that robot_state_publisher spins the bundled diffbot's
wheels. The tutorial's rclpy node with its imports changed; a Rate loop replaces its timer.

Run: python examples/sensor_simulator.py [--duration S] [--time-scale X]
     robotmodel robot-state-publisher diffbot.urdf.xacro   (the wheels' TF)
"""

from __future__ import annotations

import argparse
import math
import threading

from robotmodel.bus import Node
from robotmodel.msgs import JointState, Odometry, TransformStamped, Twist
from robotmodel.signals import stop_on_signals
from robotmodel.tf_ros import TransformBroadcaster
from robotmodel.tf_transformations import quaternion_from_euler
from robotmodel.time import Duration, PlaybackClock, Rate, SystemClock

# The bundled diffbot's wheels (urdf/diffbot.urdf.xacro).
WHEEL_RADIUS = 0.05
WHEEL_SEPARATION = 0.34


class SensorSimulator:
    """Integrates the commanded velocity into the robot's pose and publishes what it measures."""

    def __init__(self, node: Node, clock: PlaybackClock, joint_states_topic: str = "/joint_states") -> None:
        self.clock = clock
        self.x = self.y = self.theta = 0.0
        self.left_wheel = self.right_wheel = 0.0
        self.cmd = Twist()
        self.last = clock.now()
        self.lock = threading.Lock()
        self.odom_pub = node.create_publisher(Odometry, "/odom", 10)
        self.joint_pub = node.create_publisher(JointState, joint_states_topic, 10)
        self.tf_broadcaster = TransformBroadcaster(node)
        self.subscription = node.create_subscription(Twist, "/cmd_vel", self.cmd_vel_callback, 10)

    def cmd_vel_callback(self, msg: Twist) -> None:
        """Keep the latest command."""
        with self.lock:
            self.cmd = msg

    def update(self) -> None:
        """One integration step with the latest command, then publish odometry, TF and wheel angles."""
        stamp = self.clock.now()
        # The time actually elapsed: a step the loop missed is not lost from the integral.
        dt = (stamp - self.last).nanoseconds / 1e9
        self.last = stamp
        with self.lock:
            v, w = self.cmd.linear.x, self.cmd.angular.z
        self.x += v * math.cos(self.theta) * dt
        self.y += v * math.sin(self.theta) * dt
        self.theta += w * dt
        left_speed = (v - w * WHEEL_SEPARATION / 2) / WHEEL_RADIUS
        right_speed = (v + w * WHEEL_SEPARATION / 2) / WHEEL_RADIUS
        self.left_wheel += left_speed * dt
        self.right_wheel += right_speed * dt
        now = stamp.to_msg()
        q = quaternion_from_euler(0.0, 0.0, self.theta)

        t = TransformStamped()
        t.header.stamp = now
        t.header.frame_id = "odom"
        t.child_frame_id = "base_footprint"
        t.transform.translation.x = self.x
        t.transform.translation.y = self.y
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.tf_broadcaster.send_transform(t)

        odom = Odometry()
        odom.header.stamp = now
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_footprint"
        odom.pose.pose.position.x = self.x
        odom.pose.pose.position.y = self.y
        odom.pose.pose.orientation = t.transform.rotation
        odom.twist.twist.linear.x = v
        odom.twist.twist.angular.z = w
        self.odom_pub.publish(odom)

        joints = JointState()
        joints.header.stamp = now
        joints.name = ["left_wheel_joint", "right_wheel_joint"]
        joints.position = [self.left_wheel, self.right_wheel]
        joints.velocity = [left_speed, right_speed]
        self.joint_pub.publish(joints)


def main() -> None:
    """Simulate until --duration seconds of the example's clock, or Ctrl-C; print the final pose."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=None, help="stop after S seconds (default: run on)")
    parser.add_argument("--time-scale", type=float, default=1.0, help="clock seconds per wall second")
    parser.add_argument("--joint-states-topic", default="/joint_states",
                        help="where the wheel angles go (default /joint_states)")
    args = parser.parse_args()
    stop = stop_on_signals()
    clock = PlaybackClock(SystemClock().now(), rate=args.time_scale)
    with Node("sensor_simulator") as node:
        sim = SensorSimulator(node, clock, args.joint_states_topic)
        print("[sensor_simulator] integrating /cmd_vel at 20 Hz", flush=True)
        end = None if args.duration is None else clock.now() + Duration(seconds=args.duration)
        rate = Rate(20.0, clock)
        while not stop.is_set() and (end is None or clock.now() < end):
            sim.update()
            rate.sleep()
        sim.tf_broadcaster.close()
    print(f"[sensor_simulator] final pose: x={sim.x:.6f} y={sim.y:.6f} theta={sim.theta:.6f} "
          f"left_wheel={sim.left_wheel:.6f} right_wheel={sim.right_wheel:.6f}", flush=True)


if __name__ == "__main__":
    main()
