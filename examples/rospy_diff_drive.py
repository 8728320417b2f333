"""A diff-drive robot simulator in rospy: ``cmd_vel`` in, ``odom`` (nav_msgs/Odometry) out at 20 Hz.

The robot integrates its command exactly (an arc for a constant linear and angular speed)
from ``odom`` = base at the origin; until a ``cmd_vel`` arrives it drives the private
parameters ``~linear`` (m/s) and ``~angular`` (rad/s), so it can run alone. The odometry's
frames are ``~odom_frame`` (default ``odom``) and ``~base_frame`` (default ``base_link``).
A rospy program with only its imports changed (``import rospy``, ``from nav_msgs.msg import
Odometry``, ``from geometry_msgs.msg import Twist``); tests/standins run it both ways.

Run: python examples/rospy_diff_drive.py _linear:=0.5 _angular:=0.25
"""

from __future__ import annotations

import math
import threading

from robotmodel.msgs.geometry_msgs.msg import Twist
from robotmodel.msgs.nav_msgs.msg import Odometry

from robotmodel import rospy


class DiffDrive:
    """The robot's planar pose (x, y, yaw) in the odometry frame and its command."""

    def __init__(self, linear: float, angular: float) -> None:
        self.x = self.y = self.yaw = 0.0
        self.linear, self.angular = linear, angular
        self.lock = threading.Lock()

    def on_command(self, msg: Twist) -> None:
        """Take a new command (cmd_vel)."""
        with self.lock:
            self.linear, self.angular = msg.linear.x, msg.angular.z

    def advance(self, dt: float) -> tuple[float, float]:
        """Drive the command for ``dt`` seconds; the command driven."""
        with self.lock:
            v, w = self.linear, self.angular
        if abs(w) < 1e-9:
            self.x += v * dt * math.cos(self.yaw)
            self.y += v * dt * math.sin(self.yaw)
        else:
            # The exact arc: radius v/w about the centre to the robot's left.
            self.x += v / w * (math.sin(self.yaw + w * dt) - math.sin(self.yaw))
            self.y -= v / w * (math.cos(self.yaw + w * dt) - math.cos(self.yaw))
        self.yaw += w * dt
        return v, w


if __name__ == "__main__":
    rospy.init_node("diff_drive")
    robot = DiffDrive(float(rospy.get_param("~linear", 0.0)), float(rospy.get_param("~angular", 0.0)))
    odom_frame = rospy.get_param("~odom_frame", "odom")
    base_frame = rospy.get_param("~base_frame", "base_link")
    rospy.Subscriber("cmd_vel", Twist, robot.on_command, queue_size=1)
    odom_pub = rospy.Publisher("odom", Odometry, queue_size=10)
    rate = rospy.Rate(20.0)
    last = rospy.Time.now()
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        v, w = robot.advance((now - last).to_sec())
        last = now
        odom = Odometry()
        odom.header.stamp = now
        odom.header.frame_id = odom_frame
        odom.child_frame_id = base_frame
        odom.pose.pose.position.x = robot.x
        odom.pose.pose.position.y = robot.y
        odom.pose.pose.orientation.z = math.sin(robot.yaw / 2.0)
        odom.pose.pose.orientation.w = math.cos(robot.yaw / 2.0)
        odom.twist.twist.linear.x = v
        odom.twist.twist.angular.z = w
        odom_pub.publish(odom)
        rate.sleep()
