"""rospy's ``/rosout``: each logged line as a log message from the node, as rospy sends it.

On ROS 1 it goes out on the ROS 1 node's own ``/rosout`` publisher as ``rosgraph_msgs/Log``
(level, the node's name, the text, the calling file's base name, function and line, the
node's topics), what ``rqt_console`` and ``rosout`` read. On the other wires it is ROS 2's
``rcl_interfaces/msg/Log`` on ``/rosout`` (levels 10..50, the logger name dotted, no topics),
what ROS 2's tools read. A failure to send is dropped, as rospy drops it: logging never raises.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robotmodel.rospy import _time

if TYPE_CHECKING:
    from robotmodel.bus import Node
    from robotmodel.rospy._log import Sink

__all__ = ["rosout_sink"]

_ROS2_LEVELS = {1: 10, 2: 20, 4: 30, 8: 40, 16: 50}


def rosout_sink(node: Node) -> Sink:
    """A log sink sending each line on ``node``'s ``/rosout``."""
    ros1 = getattr(node.handle, "ros1", None)
    if ros1 is not None and getattr(ros1, "rosout", None) is not None:
        return _ros1_sink(ros1)
    return _ros2_sink(node)


def _ros1_sink(ros1: Any) -> Sink:
    from robotmodel.ros1 import typestore

    types = typestore().types
    log, header, stamp = (types[t] for t in ("rosgraph_msgs/msg/Log", "std_msgs/msg/Header",
                                             "builtin_interfaces/msg/Time"))

    def send(level: int, text: str, path: str, line: int, function: str) -> None:
        sec, nanosec = divmod(_time.get_rostime().nanoseconds, 1_000_000_000)
        with contextlib.suppress(Exception):
            # The node's registrations, as rospy's topic manager lists them (read under its lock).
            with ros1._lock:
                topics = sorted({*ros1._publications, *ros1._subscriptions})
            ros1.rosout.publish(log(header(0, stamp(sec, nanosec), ""), level, ros1.name, text,
                                    Path(path).name, function, line, topics))

    return send


def _ros2_sink(node: Node) -> Sink:
    from robotmodel.bus import Durability, QoS
    from robotmodel.msgs import typestore

    types = typestore().types
    log, stamp = types["rcl_interfaces/msg/Log"], types["builtin_interfaces/msg/Time"]
    pub: Any = node.create_publisher("rcl_interfaces/msg/Log", "/rosout",
                                QoS(1000, durability=Durability.TRANSIENT_LOCAL))
    name = node.fully_qualified_name.strip("/").replace("/", ".")

    def send(level: int, text: str, path: str, line: int, function: str) -> None:
        sec, nanosec = divmod(_time.get_rostime().nanoseconds, 1_000_000_000)
        with contextlib.suppress(Exception):
            pub.publish(log(stamp(sec, nanosec), _ROS2_LEVELS[level], name, text, path, function, line))

    return send
