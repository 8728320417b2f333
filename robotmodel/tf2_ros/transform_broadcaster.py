"""tf2_ros.transform_broadcaster: ``TransformBroadcaster()`` (rospy) or ``TransformBroadcaster(node)`` (rclpy).

``sendTransform(t)`` takes one TransformStamped or a list. Without a node it uses the
node :func:`robotmodel.rospy.init_node` opened (or opens its own before that).
"""

from __future__ import annotations

from typing import Any

from robotmodel.tf2_ros._node import bus_node
from robotmodel.tf_ros import TransformBroadcaster as _Broadcaster

__all__ = ["TransformBroadcaster"]


class TransformBroadcaster(_Broadcaster):
    """Publishes transforms on ``/tf``."""

    def __init__(self, node: Any = None, qos: Any = None, **options: Any) -> None:
        super().__init__(bus_node(node), qos, **options)
