"""robot_state_publisher and joint_state_publisher as library objects.

- :class:`RobotStatePublisher`: on a bus node, publishes robot_description and /tf_static
  (latched) and /tf for each JointState on joint_states, as ROS 2's robot_state_publisher.
- :class:`JointStatePublisher`: publishes JointState on joint_states at a rate for a robot
  from a file or from robot_description; :meth:`JointStatePublisher.set` moves joints.

As in ROS, ``joint_states``, ``robot_description`` and ``source_list`` topics are relative:
they resolve under the node's namespace (a ``Node("rsp", "/r1")`` gives ``/r1/joint_states``),
while ``/tf`` and ``/tf_static`` are absolute and shared by every namespace.
- :class:`RobotStateLogic`: robot_state_publisher's rules with no bus: a JointState in,
  the /tf transforms out; the /tf_static set; the rate cap, ``frame_prefix`` and
  ``ignore_timestamp``.
- :func:`run_robot_state_publisher`, :func:`run_joint_state_publisher`: the ROS programs
  (``robotmodel robot-state-publisher`` / ``joint-state-publisher``), ROS parameters
  included (:func:`jsp_settings` maps joint_state_publisher's); on ROS 1 without FILE the robot
  is ``robot_description`` on the parameter server (:func:`description_parameter`).
- :class:`JointStateLogic`: joint_state_publisher's joints, defaults, ``zeros``, mimic
  resolution and ``source_list`` merging, with no bus.
"""

from __future__ import annotations

from robotmodel.publishers._errors import PublisherError
from robotmodel.publishers._jsp import JointStatePublisher
from robotmodel.publishers._jsp_joints import DependentJoint, FreeJoint, JointLayout, read_layout
from robotmodel.publishers._jsp_state import JointStateLogic
from robotmodel.publishers._programs import (
    description_parameter,
    jsp_settings,
    run_joint_state_publisher,
    run_robot_state_publisher,
)
from robotmodel.publishers._rsp import RobotStatePublisher
from robotmodel.publishers._rsp_state import RobotStateLogic, check_publish_frequency

__all__ = [
    "DependentJoint",
    "FreeJoint",
    "JointLayout",
    "JointStateLogic",
    "JointStatePublisher",
    "PublisherError",
    "RobotStateLogic",
    "RobotStatePublisher",
    "check_publish_frequency",
    "description_parameter",
    "jsp_settings",
    "read_layout",
    "run_joint_state_publisher",
    "run_robot_state_publisher",
]
