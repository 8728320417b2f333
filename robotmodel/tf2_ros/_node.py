"""Which bus node a tf2_ros class runs on: the one given (rclpy style) or rospy's (rospy style)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robotmodel.bus import Node

__all__ = ["bus_node"]


def bus_node(node: Any) -> Node | None:
    """The :class:`robotmodel.bus.Node` for ``node``; without one, the node :func:`robotmodel.rospy.init_node` opened.

    A node-like object (an rclpy stand-in) is unwrapped by its ``bus_node`` attribute. None
    means neither: the caller opens a node of its own, as robotmodel.tf_ros does.
    """
    from robotmodel.bus import Node

    if node is None:
        from robotmodel.rospy import get_node

        return get_node()
    if isinstance(node, Node):
        return node
    inner = getattr(node, "bus_node", None)
    if isinstance(inner, Node):
        return inner
    raise TypeError(f"not a node: {type(node).__name__} (give a robotmodel.bus.Node or one with .bus_node)")
