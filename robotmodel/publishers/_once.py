"""Say a recurring problem once: a publisher meets the same bad input many times a second."""

from __future__ import annotations

import logging
from collections.abc import Hashable

__all__ = ["WarnOnce"]


class WarnOnce:
    """Log a warning the first time each key is seen; later occurrences are only counted."""

    def __init__(self, log: logging.Logger) -> None:
        self.log = log
        self.counts: dict[Hashable, int] = {}

    def once(self, key: Hashable, message: str, *args: object, level: int = logging.WARNING) -> bool:
        """Log ``message % args`` if ``key`` is new; returns whether it was logged."""
        seen = self.counts.get(key, 0)
        self.counts[key] = seen + 1
        if seen:
            return False
        self.log.log(level, message, *args)
        return True

    def reset(self) -> None:
        """Forget what was said (a new robot description makes old warnings stale)."""
        self.counts.clear()
