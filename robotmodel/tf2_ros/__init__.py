"""tf2_ros on robotmodel's bus: ``from robotmodel import tf2_ros`` in place of ``import tf2_ros``.

The module layout is tf2_ros's (:mod:`~robotmodel.tf2_ros.buffer`,
:mod:`~robotmodel.tf2_ros.transform_listener`, :mod:`~robotmodel.tf2_ros.transform_broadcaster`,
:mod:`~robotmodel.tf2_ros.static_transform_broadcaster`), and the names tf2_ros exports are
here: :class:`Buffer`, :class:`TransformListener`, :class:`TransformBroadcaster`,
:class:`StaticTransformBroadcaster` and tf2's exceptions (:class:`TransformException`,
:class:`LookupException`, :class:`ConnectivityException`, :class:`ExtrapolationException`,
:class:`InvalidArgumentException`, :class:`TimeoutException`), distinct classes as in tf2_ros.

Both styles work: rospy's (``TransformListener(buffer)``, ``TransformBroadcaster()``, on the
node :func:`robotmodel.rospy.init_node` opened) and rclpy's (``TransformListener(buffer, node)``).

Porting notes (what differs from tf2_ros):

- ``lookup_transform(..., timeout)`` waits by sleeping until the transform's frames get
  data, not by polling; what it raises at the end is tf2_ros's (the lookup's own error).
- A process whose listener is alive still ends on Ctrl-C, SIGTERM or an uncaught
  exception (the bus's threads do not hold it).
- No ``BufferClient``/``BufferServer`` (the action-based buffer) and no
  ``tf2_geometry_msgs`` registration: :meth:`Buffer.transform` knows the geometry_msgs
  stamped types itself.
"""

from __future__ import annotations

from robotmodel.errors import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from robotmodel.tf2_ros.buffer import Buffer
from robotmodel.tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from robotmodel.tf2_ros.transform_broadcaster import TransformBroadcaster
from robotmodel.tf2_ros.transform_listener import TransformListener

__all__ = [
    "Buffer",
    "ConnectivityException",
    "ExtrapolationException",
    "InvalidArgumentException",
    "LookupException",
    "StaticTransformBroadcaster",
    "TimeoutException",
    "TransformBroadcaster",
    "TransformException",
    "TransformListener",
]
