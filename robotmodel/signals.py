"""Stopping a long-running tool on SIGINT/SIGTERM, safely.

Two traps this avoids:

- A handler that sets a :class:`threading.Event` itself can deadlock: when the signal lands
  while the main thread is inside ``event.wait(timeout)`` holding the event's lock, the
  handler (run on that same thread) blocks on the lock forever.
- Python runs handlers only on the main thread, and only once it wakes. The kernel delivers
  a process-directed signal to any thread that does not block it (in a bus process, often
  one of zenoh's); the main thread, asleep in ``stop.wait()`` with no timeout, is then never
  interrupted and the handler never runs.

So the watcher thread is woken from C: the pipe is registered with
:func:`signal.set_wakeup_fd`, which CPython's own low-level handler writes to on whichever
thread the signal lands, and the watcher sets the event. The Python-level handler only
replaces the default action (and writes too, for a caller that swapped the wakeup fd out).
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterable
from types import FrameType

__all__ = ["request_stop", "stop_on_signals"]

# Every event stop_on_signals gave out in this process, for request_stop.
_events: list[threading.Event] = []
_events_lock = threading.Lock()


def stop_on_signals(event: threading.Event | None = None,
                    signals: Iterable[signal.Signals] = (signal.SIGINT, signal.SIGTERM)) -> threading.Event:
    """Install handlers (main thread only) that set ``event`` (a new one if None) and return it.

    The signals no longer raise ``KeyboardInterrupt`` or end the process: the caller waits on
    the event, stops cleanly and chooses its exit code, as ROS tools do. The caller may
    restore earlier handlers with :func:`signal.signal` when it is done. The process's
    wakeup fd (:func:`signal.set_wakeup_fd`) is taken by this call.
    """
    stop = event if event is not None else threading.Event()
    with _events_lock:
        _events.append(stop)
    wanted = {int(s) for s in signals}
    read_fd, write_fd = os.pipe()
    os.set_blocking(write_fd, False)

    def watch() -> None:
        while True:
            data = os.read(read_fd, 64)
            # Any signal with a Python handler is written to the wakeup fd; stop on ours only.
            if not data or wanted.intersection(data):
                stop.set()
                return

    def handler(signum: int, frame: FrameType | None) -> None:
        del frame
        with contextlib.suppress(OSError):  # a full pipe means a stop is already on its way
            os.write(write_fd, bytes([signum]))

    threading.Thread(target=watch, name="stop-on-signals", daemon=True).start()
    for sig in signals:
        signal.signal(sig, handler)
    signal.set_wakeup_fd(write_fd, warn_on_full_buffer=False)
    return stop


def request_stop() -> None:
    """Stop as a SIGINT/SIGTERM would: set every event :func:`stop_on_signals` gave out in this process.

    What rospy's ``signal_shutdown`` is to a rospy process: a ROS 1 node told to shut down by
    its master's world (``rosnode kill``, the slave API's ``shutdown``) ends the tool running it.
    """
    with _events_lock:
        events = list(_events)
    for event in events:
        event.set()
