"""What every message class shares: rclpy's ``repr``."""

from __future__ import annotations

from dataclasses import fields
from typing import ClassVar

__all__ = ["RosMessage"]


class RosMessage:
    """Base of the message classes: ``__msgtype__`` and rclpy's repr.

    ``repr(Vector3())`` is ``geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0)``, as rclpy
    prints it, which also tells a stamp message from :class:`robotmodel.time.Time`.
    """

    __slots__ = ()
    __msgtype__: ClassVar[str]

    def __repr__(self) -> str:
        args = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in fields(self))  # type: ignore[arg-type]
        return f"{self.__msgtype__.replace('/', '.')}({args})"
