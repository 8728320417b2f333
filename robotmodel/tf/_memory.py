"""Giving freed memory back to the system after a large burst of inserts."""

from __future__ import annotations

import ctypes
from collections.abc import Callable

__all__ = ["BIG_MESSAGE", "release_free_memory"]

#: Transforms in one message from which a listener gives freed memory back afterwards.
BIG_MESSAGE = 10_000


def _malloc_trim() -> Callable[[int], int] | None:
    try:
        # The process's own symbols (dlopen(NULL)): quick, unlike ctypes.util.find_library,
        # which runs ldconfig; malloc_trim is there when the C library is glibc.
        trim: Callable[[int], int] = ctypes.CDLL(None).malloc_trim
    except (OSError, AttributeError):  # not glibc: nothing to call
        return None
    return trim


_TRIM = _malloc_trim()


def release_free_memory() -> None:
    """Return the C heap's free pages to the system (glibc's malloc_trim; a no-op elsewhere).

    Decoding a message of 100k transforms allocates and frees tens of MiB (the payload, its
    records, the bus's buffers); glibc keeps such freed heap memory mapped, so without this a
    long-running tool would hold it for good.
    """
    if _TRIM is not None:
        _TRIM(0)
