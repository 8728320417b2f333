"""A one-line progress bar on stderr for long reads (shown only after a second, at most 5 times a second)."""

from __future__ import annotations

import sys
import time
from typing import TextIO

__all__ = ["Progress"]

_DELAY_S = 1.0
_PERIOD_S = 0.2
_WIDTH = 30


class Progress:
    """``update(done)`` redraws ``label [#####     ]  42%  12,345 messages`` when due.

    ``enabled=None`` shows it only when ``stream`` is a terminal; short reads (under a
    second) never draw anything.
    """

    def __init__(self, label: str, total: int, enabled: bool | None = None, stream: TextIO | None = None,
                 delay_s: float = _DELAY_S) -> None:
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.label = label
        self.total = max(total, 1)
        self._start = time.monotonic()
        self._next = self._start + delay_s
        self._drawn = False

    def update(self, done: int) -> None:
        """Redraw if enabled and due: ``done`` of ``total`` messages read."""
        if not self.enabled:
            return
        now = time.monotonic()
        if now < self._next:
            return
        self._next = now + _PERIOD_S
        frac = min(done / self.total, 1.0)
        bar = "#" * int(frac * _WIDTH)
        self.stream.write(f"\r{self.label} [{bar:<{_WIDTH}}] {frac * 100:3.0f}%  {done:,} messages")
        self.stream.flush()
        self._drawn = True

    def close(self) -> None:
        """End the bar's line (if one was drawn)."""
        if self._drawn:
            self.stream.write("\n")
            self.stream.flush()
            self._drawn = False
