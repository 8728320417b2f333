"""Say a recurring problem once: a publisher meets the same bad input many times a second."""

from __future__ import annotations

import logging
import time
from collections.abc import Hashable

__all__ = ["Every", "WarnOnce"]


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


class Every:
    """Log at most one warning per ``period`` seconds, saying how many were held back."""

    def __init__(self, log: logging.Logger, period: float = 5.0) -> None:
        self.log = log
        self.period = period
        self._last = -1e9
        self._held = 0

    def warn(self, message: str, *args: object) -> None:
        """Log ``message % args`` unless one was logged less than ``period`` seconds ago."""
        now = time.monotonic()
        if now - self._last < self.period:
            self._held += 1
            return
        self._last = now
        held, self._held = self._held, 0
        suffix = f" ({held} more since the last warning)" if held else ""
        self.log.warning(message + suffix, *args)
