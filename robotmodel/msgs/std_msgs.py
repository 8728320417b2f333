"""std_msgs messages: Header and String."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from robotmodel.msgs._base import RosMessage
from robotmodel.msgs.builtin_interfaces import Time

__all__ = ["Header", "String"]


@dataclass(slots=True, repr=False)
class Header(RosMessage):
    """std_msgs/msg/Header: the stamp and the frame a message's data is expressed in."""

    __msgtype__: ClassVar[str] = "std_msgs/msg/Header"

    stamp: Time = field(default_factory=Time)
    frame_id: str = ""


@dataclass(slots=True, repr=False)
class String(RosMessage):
    """std_msgs/msg/String."""

    __msgtype__: ClassVar[str] = "std_msgs/msg/String"

    data: str = ""
