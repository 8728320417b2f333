"""tf2_msgs messages: TFMessage, the payload of ``/tf`` and ``/tf_static``."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from robotmodel.msgs._base import RosMessage
from robotmodel.msgs.geometry_msgs import TransformStamped

__all__ = ["TFMessage"]


@dataclass(slots=True, repr=False)
class TFMessage(RosMessage):
    """tf2_msgs/msg/TFMessage: a batch of transforms."""

    __msgtype__: ClassVar[str] = "tf2_msgs/msg/TFMessage"

    transforms: list[TransformStamped] = field(default_factory=list)
