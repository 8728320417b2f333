"""sensor_msgs messages: JointState."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from robotmodel.msgs._base import RosMessage
from robotmodel.msgs.std_msgs import Header

__all__ = ["JointState"]


@dataclass(slots=True, repr=False)
class JointState(RosMessage):
    """sensor_msgs/msg/JointState: per-joint position, velocity and effort (each may be empty)."""

    __msgtype__: ClassVar[str] = "sensor_msgs/msg/JointState"

    header: Header = field(default_factory=Header)
    name: list[str] = field(default_factory=list)
    position: list[float] = field(default_factory=list)
    velocity: list[float] = field(default_factory=list)
    effort: list[float] = field(default_factory=list)
