"""tf2_ros.transform_listener: ``TransformListener(buffer)`` (rospy) or ``TransformListener(buffer, node)`` (rclpy).

Without a node it uses the node :func:`robotmodel.rospy.init_node` opened, as tf2_ros's
rospy listener does; before init_node (or in a program without rospy) it opens a node
of its own, closed by :meth:`close`. Everything else is :class:`robotmodel.tf_ros.TransformListener`.
"""

from __future__ import annotations

from typing import Any

from robotmodel.tf2_ros._node import bus_node
from robotmodel.tf_ros import TransformListener as _Listener

__all__ = ["TransformListener"]


class TransformListener(_Listener):
    """Fills ``buffer`` from ``/tf`` and ``/tf_static`` on the given node, or rospy's."""

    def __init__(self, buffer: Any, node: Any = None, *, spin_thread: bool = True, qos: Any = None,
                 static_qos: Any = None, **options: Any) -> None:
        super().__init__(buffer, bus_node(node), spin_thread=spin_thread, qos=qos, static_qos=static_qos,
                         **options)
