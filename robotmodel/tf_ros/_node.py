"""The bus node a broadcaster or listener runs on: the caller's, or one of its own.

tf2_ros's classes take an rclpy node. Here the node is optional: without one, the class
opens its own :class:`robotmodel.bus.Node` and closes it again in ``close()``; a node the
caller passed in is left open for the caller.
"""

from __future__ import annotations

import secrets
import string
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from robotmodel.bus import Node

__all__ = ["OwnedNode", "unique_name"]

_ALPHABET = string.digits + string.ascii_letters


def unique_name(prefix: str) -> str:
    """``prefix`` followed by 16 random letters and digits, as ROS 2 anonymizes node names."""
    return prefix + "".join(secrets.choice(_ALPHABET) for _ in range(16))


class OwnedNode:
    """A node plus whether this object must close it."""

    __slots__ = ("node", "owned")

    def __init__(self, node: Node | None, prefix: str, **options: Any) -> None:
        if node is None:
            # Imported here so that robotmodel.tf_ros can be imported without opening anything.
            from robotmodel.bus import Node

            node = Node(unique_name(prefix), **options)
            self.owned = True
        else:
            self.owned = False
        self.node: Node = node

    def close(self) -> None:
        """Close the node when it is ours; harmless twice."""
        if self.owned:
            self.owned = False
            self.node.close()
