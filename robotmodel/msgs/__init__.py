"""ROS 2 message classes, with their ROS type names, and CDR encoding through rosbags.

Each ROS package is a module, mirroring ``<pkg>.msg``: code written for rclpy carries
over by changing ``from geometry_msgs.msg import TransformStamped`` into
``from robotmodel.msgs.geometry_msgs.msg import TransformStamped`` (each package module is
also its own ``msg`` submodule; ``from robotmodel.msgs.geometry_msgs import TransformStamped``
is the same class, and what type checkers follow). Messages are mutable
dataclasses with ROS 2's defaults; each class names its ROS type in ``__msgtype__``
(``"geometry_msgs/msg/TransformStamped"``). The classes whose names are unique are
also exported here; ``Time``, ``Duration`` (builtin_interfaces) and ``Clock``
(rosgraph_msgs) only from their package modules, since :mod:`robotmodel.time` has
values of those names.

For the ``/tf`` hot path, :func:`decode_tf_records` and :func:`encode_tf_records` read and
write TFMessage bytes as :class:`TFRecord` tuples (parent, child, stamp_ns, pose) that
feed a buffer's message-free ``insert`` directly.

Field values are checked against their ROS types when a message is converted or
encoded (:func:`to_rosbags`, :func:`serialize`): out of range, a
:class:`~robotmodel.errors.MessageError` names the field.
"""

from __future__ import annotations

import sys

from robotmodel.msgs import (
    builtin_interfaces,
    geometry_msgs,
    nav_msgs,
    rosgraph_msgs,
    sensor_msgs,
    std_msgs,
    tf2_msgs,
    turtlesim,
)
from robotmodel.msgs._build import make_transform, stamp
from robotmodel.msgs._cdr import deserialize, serialize, type_hash
from robotmodel.msgs._convert import Message, from_rosbags, message_class, to_rosbags, typestore
from robotmodel.msgs._tfcodec import TFRecord, decode_tf_records, encode_tf_records
from robotmodel.msgs.geometry_msgs import (
    Point,
    PointStamped,
    Pose,
    PoseStamped,
    PoseWithCovariance,
    Quaternion,
    Transform,
    TransformStamped,
    Twist,
    TwistStamped,
    TwistWithCovariance,
    Vector3,
    Vector3Stamped,
)
from robotmodel.msgs.nav_msgs import Odometry
from robotmodel.msgs.sensor_msgs import JointState
from robotmodel.msgs.std_msgs import Header, String
from robotmodel.msgs.tf2_msgs import TFMessage

# ``from robotmodel.msgs.geometry_msgs.msg import Pose``, as ROS users write ``from geometry_msgs.msg import
# Pose``: each package module is its own ``msg`` submodule.
for _package in (builtin_interfaces, geometry_msgs, nav_msgs, rosgraph_msgs, sensor_msgs, std_msgs, tf2_msgs,
                 turtlesim):
    sys.modules[_package.__name__ + ".msg"] = _package
    vars(_package)["msg"] = _package

__all__ = [
    "Header",
    "JointState",
    "Message",
    "Odometry",
    "Point",
    "PointStamped",
    "Pose",
    "PoseStamped",
    "PoseWithCovariance",
    "Quaternion",
    "String",
    "TFMessage",
    "TFRecord",
    "Transform",
    "TransformStamped",
    "Twist",
    "TwistStamped",
    "TwistWithCovariance",
    "Vector3",
    "Vector3Stamped",
    "builtin_interfaces",
    "decode_tf_records",
    "deserialize",
    "encode_tf_records",
    "from_rosbags",
    "geometry_msgs",
    "make_transform",
    "message_class",
    "nav_msgs",
    "rosgraph_msgs",
    "sensor_msgs",
    "serialize",
    "stamp",
    "std_msgs",
    "tf2_msgs",
    "to_rosbags",
    "turtlesim",
    "type_hash",
    "typestore",
]
