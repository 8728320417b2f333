"""The robot as published on ``robot_description`` (std_msgs/String, latched): rviz's way to get it.

robot_state_publisher without FILE or parameter, and the viewer without a robot, both wait
here for the first description that parses, and take each later one that differs.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

__all__ = ["DescriptionTopic"]


class DescriptionTopic:
    """The latest ``robot_description`` text on the bus, and an event for each new one."""

    def __init__(self, node: Any) -> None:
        from robotmodel.bus import QOS_LATCHED
        from robotmodel.msgs import String

        self.text: str | None = None
        self.changed = threading.Event()
        self._lock = threading.Lock()
        self.sub = node.create_subscription(String, "robot_description", self._on_message, QOS_LATCHED)

    def _on_message(self, msg: Any) -> None:
        with self._lock:
            if msg.data != self.text:
                self.text = msg.data
                self.changed.set()

    def take(self) -> str | None:
        """The text if it changed since the last call, else None."""
        with self._lock:
            if not self.changed.is_set():
                return None
            self.changed.clear()
            return self.text

    def wait(self, parse: Callable[[str], Any], *stops: threading.Event) -> Any:
        """The first new description ``parse`` accepts (it returns None to skip one); None once a stop is set."""
        while not any(s.is_set() for s in stops):
            if self.changed.wait(0.1):
                text = self.take()
                desc = parse(text) if text is not None else None
                if desc is not None:
                    return desc
        return None

    def close(self) -> None:
        """Stop listening."""
        self.sub.close()
