"""rosgraph_msgs messages: Clock, the payload of ``/clock`` in simulation and playback."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from robotmodel.msgs._base import RosMessage
from robotmodel.msgs.builtin_interfaces import Time

__all__ = ["Clock"]


@dataclass(slots=True, repr=False)
class Clock(RosMessage):
    """rosgraph_msgs/msg/Clock: the current simulated time."""

    __msgtype__: ClassVar[str] = "rosgraph_msgs/msg/Clock"

    clock: Time = field(default_factory=Time)
