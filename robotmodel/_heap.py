"""Giving the C heap's freed memory back to the system after a large burst (glibc's malloc_trim).

A subscriber that has just handled an unusually large message (a listener given one /tf message
of 100k transforms) frees tens of MiB: the decoded records, and the wire's copy of the payload
with the buffers it was reassembled in. glibc keeps such freed heap memory mapped, so a
long-running tool would hold it for good. The payload, though, is still held by the wire while
the subscriber's callback runs: the subscriber calls :func:`release_after_sample`, and the wire
calls :func:`sample_released` once it has let go of the sample (the DDS wire, after the batch
the sample was taken in), or :func:`sample_releasing` as it is about to (zenoh's callback,
after which the Rust side drops the received buffers). Trimming on every message would cost a
heap walk and fresh page faults per message (a camera stream), so it happens only on request.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

__all__ = ["release_after_sample", "release_free_memory", "sample_released", "sample_releasing"]


_requested = threading.Event()
# Long enough for a wire's thread to return from the callback and drop the sample (microseconds
# on an idle machine); a trim that comes early only gives back less.
_SHORTLY_S = 0.2
_trim: list[Callable[[int], int] | None] = []  # found at the first trim: ctypes costs start-up time


def _malloc_trim() -> Callable[[int], int] | None:
    import ctypes

    try:
        # The process's own symbols (dlopen(NULL)): quick, unlike ctypes.util.find_library,
        # which runs ldconfig; malloc_trim is there when the C library is glibc.
        trim: Callable[[int], int] = ctypes.CDLL(None).malloc_trim
    except (OSError, AttributeError):  # not glibc: nothing to call
        return None
    return trim


def release_free_memory() -> None:
    """Return the C heap's free pages to the system now (a no-op without glibc)."""
    if not _trim:
        _trim.append(_malloc_trim())
    if _trim[0] is not None:
        _trim[0](0)


def release_after_sample() -> None:
    """Ask for :func:`release_free_memory` once the wire has let go of the sample being handled."""
    _requested.set()


def sample_released() -> None:
    """Called by a wire after dropping its references to delivered samples: trim if asked to."""
    if _requested.is_set():
        _requested.clear()
        release_free_memory()


def sample_releasing() -> None:
    """Called by a wire that lets go of the sample only after this returns: trim shortly after, if asked to.

    zenoh's callbacks are such: the Rust side drops the received buffers once the callback returns.
    """
    if _requested.is_set():
        _requested.clear()
        timer = threading.Timer(_SHORTLY_S, release_free_memory)
        timer.daemon = True  # never holds up the process's exit
        timer.start()
