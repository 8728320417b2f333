"""rospy's Publisher and Subscriber on the process's bus node.

As rospy: ``publish(msg)`` or ``publish(*fields, **fields)`` building the message;
``latch=True`` keeps the last message for late subscribers; ``queue_size`` is the
publisher's depth; a Subscriber's callback gets ``callback_args`` as its second argument
when given. Unlike rospy, both need :func:`init_node` first (rospy defers registration
instead). On the zenoh and DDS wires a subscriber is volatile, so a latched message
reaches only subscribers that exist when it is sent; ROS 1's latching is exact.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robotmodel.errors import ROSException, ROSInitException
from robotmodel.rospy import _core

__all__ = ["Publisher", "Subscriber"]

_NO_ARGS = object()


def _node() -> Any:
    node = _core.get_node()
    if node is None:
        raise ROSInitException("client code must call rospy.init_node() first")
    return node


class Publisher:
    """``Publisher(topic, data_class, queue_size=10, latch=False)``; ``publish(msg)``."""

    def __init__(self, name: str, data_class: type[Any], subscriber_listener: Any = None, tcp_nodelay: bool = False,
                 latch: bool = False, headers: Any = None, queue_size: int | None = None) -> None:
        from robotmodel.bus import Durability, QoS

        del subscriber_listener, tcp_nodelay, headers
        self.data_class = data_class
        self.type = getattr(data_class, "__msgtype__", str(data_class))
        depth = queue_size if queue_size else (1 if latch else 10)
        qos = QoS(depth, durability=Durability.TRANSIENT_LOCAL if latch else Durability.VOLATILE)
        node = _node()
        self._pub: Any = node.create_publisher(data_class, name, qos)
        self.name = str(node.resolve_topic_name(name))
        self.resolved_name = self.name

    def publish(self, *args: Any, **kwds: Any) -> None:
        """Publish ``msg``, or a message built from its fields (``publish(x=1.0, y=2.0)``)."""
        if len(args) == 1 and not kwds and isinstance(args[0], self.data_class):
            msg = args[0]
        else:
            try:
                msg = self.data_class(*args, **kwds)
            except TypeError as exc:
                raise ROSException(f"cannot publish to {self.name} [{self.type}]: {exc}") from None
        if _core.is_shutdown():
            raise ROSException("publish() to a closed topic")
        self._pub.publish(msg)

    def get_num_connections(self) -> int:
        """How many subscribers are connected."""
        return int(self._pub.get_subscription_count())

    def unregister(self) -> None:
        """Stop publishing."""
        self._pub.close()


class Subscriber:
    """``Subscriber(topic, data_class, callback, callback_args=None)``: ``callback(msg[, callback_args])``."""

    def __init__(self, name: str, data_class: type[Any], callback: Callable[..., Any] | None = None,
                 callback_args: Any = _NO_ARGS, queue_size: int | None = None, buff_size: int = 65536,
                 tcp_nodelay: bool = False) -> None:
        from robotmodel.bus import QoS

        del buff_size, tcp_nodelay
        self.data_class = data_class
        self.callback = callback
        self.callback_args = callback_args

        def deliver(msg: Any) -> None:
            if callback is None:
                return
            if callback_args is _NO_ARGS or callback_args is None:
                callback(msg)
            else:
                callback(msg, callback_args)

        node = _node()
        self._node = node
        self._sub: Any = node.create_subscription(data_class, name, deliver, QoS(queue_size or 10))
        _core._state.subscriptions.append(self._sub)
        self.name = str(node.resolve_topic_name(name))
        self.resolved_name = self.name

    def get_num_connections(self) -> int:
        """How many publishers the graph shows on the topic (rospy counts those connected)."""
        return int(self._node.count_publishers(self.name))

    def unregister(self) -> None:
        """Stop receiving."""
        self._sub.close()
