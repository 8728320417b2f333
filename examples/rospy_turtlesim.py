"""A tiny turtle simulator in rospy: turtles that take ``/NAME/cmd_vel`` and publish ``/NAME/pose``.

In the shape of ROS's turtlesim, without its window or services: the turtles are the private
parameter ``~turtles``, a list of ``[name, x, y, theta]`` (default: turtle1 in the middle of
the 11.09 m square, as turtlesim's). Each turtle, every 16 ms, turns by ``angular.z`` and moves
by ``linear.x`` along its heading (the command lapses after 1 s without a new one), stays
inside the square and publishes ``turtlesim/Pose``. A rospy program with only its imports
changed (``import rospy``, ``from turtlesim.msg import Pose``, ``from geometry_msgs.msg import
Twist``); tests/standins run it both ways.

Run: python examples/rospy_turtlesim.py _turtles:="[[turtle1, 5.544445, 5.544445, 0], [turtle2, 4, 2, 0]]"
"""

from __future__ import annotations

import math
import threading

from robotmodel.msgs.geometry_msgs.msg import Twist
from robotmodel.msgs.turtlesim.msg import Pose

from robotmodel import rospy

SIZE = 11.088889
PERIOD = 0.016
COMMAND_LIFETIME = 1.0


class Turtle:
    """One turtle: its pose, its last command and when that came, its topics."""

    def __init__(self, name: str, x: float, y: float, theta: float) -> None:
        self.pose = Pose(x=float(x), y=float(y), theta=float(theta))
        self.command = Twist()
        self.commanded: float | None = None
        self.lock = threading.Lock()
        self.publisher = rospy.Publisher(f"/{name}/pose", Pose, queue_size=1)
        self.subscriber = rospy.Subscriber(f"/{name}/cmd_vel", Twist, self.on_command, queue_size=1)

    def on_command(self, msg: Twist) -> None:
        """Take a new command (cmd_vel)."""
        with self.lock:
            self.command = msg
            self.commanded = rospy.get_time()

    def step(self, now: float) -> None:
        """Move one period under the live command and publish the pose."""
        with self.lock:
            live = self.commanded is not None and now - self.commanded <= COMMAND_LIFETIME
            linear = self.command.linear.x if live else 0.0
            angular = self.command.angular.z if live else 0.0
        p = self.pose
        p.theta = math.atan2(math.sin(p.theta + angular * PERIOD), math.cos(p.theta + angular * PERIOD))
        p.x = min(max(p.x + math.cos(p.theta) * linear * PERIOD, 0.0), SIZE)
        p.y = min(max(p.y + math.sin(p.theta) * linear * PERIOD, 0.0), SIZE)
        p.linear_velocity = linear
        p.angular_velocity = angular
        self.publisher.publish(p)


if __name__ == "__main__":
    rospy.init_node("turtlesim")
    turtles = [Turtle(*spec) for spec in rospy.get_param("~turtles", [["turtle1", 5.544445, 5.544445, 0.0]])]
    rospy.loginfo("turtles: %s", " ".join(spec[0] for spec in rospy.get_param("~turtles", [["turtle1"]])))
    rate = rospy.Rate(1.0 / PERIOD)
    while not rospy.is_shutdown():
        now = rospy.get_time()
        for turtle in turtles:
            turtle.step(now)
        rate.sleep()
