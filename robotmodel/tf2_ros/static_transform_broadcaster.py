"""tf2_ros.static_transform_broadcaster: ``StaticTransformBroadcaster()`` or ``StaticTransformBroadcaster(node)``.

Latched on ``/tf_static``; each call republishes every child frame's latest transform, as
tf2_ros's. Without a node it uses rospy's (or opens its own before init_node).
"""

from __future__ import annotations

from typing import Any

from robotmodel.tf2_ros._node import bus_node
from robotmodel.tf_ros import StaticTransformBroadcaster as _Broadcaster

__all__ = ["StaticTransformBroadcaster"]


class StaticTransformBroadcaster(_Broadcaster):
    """Publishes transforms that never change on ``/tf_static``."""

    def __init__(self, node: Any = None, qos: Any = None, **options: Any) -> None:
        super().__init__(bus_node(node), qos, **options)
