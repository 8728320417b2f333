"""Rate-limited warnings for what arrives off a wire (one bad peer must not flood the log)."""

from __future__ import annotations

import logging
import threading
import time

__all__ = ["Warner"]

log = logging.getLogger("robotmodel.bus")


class Warner:
    """At most one warning per reason every ``period`` seconds, counting those held back."""

    def __init__(self, period: float = 5.0) -> None:
        self._period = period
        self._last: dict[str, float] = {}
        self._held: dict[str, int] = {}
        self._lock = threading.Lock()

    def warn(self, reason: str, text: str) -> None:
        """Log ``text`` unless a warning for ``reason`` went out less than ``period`` ago."""
        now = time.monotonic()
        with self._lock:
            if now - self._last.get(reason, -1e9) < self._period:
                self._held[reason] = self._held.get(reason, 0) + 1
                return
            self._last[reason] = now
            held = self._held.pop(reason, 0)
        log.warning("%s%s", text, f" ({held} more since the last warning)" if held else "")
