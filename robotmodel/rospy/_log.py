"""rospy's console logging: ``[INFO] [1700000000.123456]: text``; INFO/DEBUG on stdout, WARN/ERROR/FATAL on stderr.

As rospy: arguments are %-formatted into the text, DEBUG lines show only with
``init_node(..., log_level=rospy.DEBUG)``. Not sent to ``/rosout`` (yet).
"""

from __future__ import annotations

import sys
import threading
import time
from typing import Any

__all__ = ["DEBUG", "ERROR", "FATAL", "INFO", "WARN", "logdebug", "logerr", "logfatal", "loginfo",
           "logwarn", "set_level"]

DEBUG = 1
INFO = 2
WARN = 4
ERROR = 8
FATAL = 16

_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}
_level = INFO
_lock = threading.Lock()


def set_level(level: int) -> None:
    """The lowest level printed (init_node's ``log_level``)."""
    global _level
    _level = level


def _log(level: int, msg: Any, args: tuple[Any, ...]) -> None:
    if level < _level:
        return
    text = str(msg) % args if args else str(msg)
    stream = sys.stdout if level <= INFO else sys.stderr
    line = f"[{_NAMES[level]}] [{time.time():f}]: {text}\n"
    with _lock:
        stream.write(line)
        stream.flush()


def logdebug(msg: Any, *args: Any, **kwargs: Any) -> None:
    """A DEBUG line (stdout; shown only at log_level DEBUG)."""
    _log(DEBUG, msg, args)


def loginfo(msg: Any, *args: Any, **kwargs: Any) -> None:
    """An INFO line on stdout."""
    _log(INFO, msg, args)


def logwarn(msg: Any, *args: Any, **kwargs: Any) -> None:
    """A WARN line on stderr."""
    _log(WARN, msg, args)


def logerr(msg: Any, *args: Any, **kwargs: Any) -> None:
    """An ERROR line on stderr."""
    _log(ERROR, msg, args)


def logfatal(msg: Any, *args: Any, **kwargs: Any) -> None:
    """A FATAL line on stderr."""
    _log(FATAL, msg, args)
