"""Stopping a long-running tool on SIGINT/SIGTERM, safely.

A handler that sets a :class:`threading.Event` itself can deadlock: when the signal lands
while the main thread is inside ``event.wait(timeout)`` holding the event's lock, the
handler (run on that same thread) blocks on the lock forever, and the process then ignores
every later signal. Here the handler only writes a byte to a pipe, which takes no lock, and
a watcher thread sets the event.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterable
from types import FrameType

__all__ = ["stop_on_signals"]


def stop_on_signals(event: threading.Event | None = None,
                    signals: Iterable[signal.Signals] = (signal.SIGINT, signal.SIGTERM)) -> threading.Event:
    """Install handlers (main thread only) that set ``event`` (a new one if None) and return it.

    The signals no longer raise ``KeyboardInterrupt`` or end the process: the caller waits on
    the event, stops cleanly and chooses its exit code, as ROS tools do. The caller may
    restore earlier handlers with :func:`signal.signal` when it is done.
    """
    stop = event if event is not None else threading.Event()
    read_fd, write_fd = os.pipe()

    def watch() -> None:
        os.read(read_fd, 1)
        stop.set()

    def handler(signum: int, frame: FrameType | None) -> None:
        del signum, frame
        with contextlib.suppress(OSError):  # a full pipe means a stop is already on its way
            os.write(write_fd, b"\0")

    threading.Thread(target=watch, name="stop-on-signals", daemon=True).start()
    for sig in signals:
        signal.signal(sig, handler)
    return stop
