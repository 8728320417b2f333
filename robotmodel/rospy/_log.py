"""rospy's console logging: ``[INFO] [1700000000.123456]: text``; INFO/DEBUG on stdout, WARN/ERROR/FATAL on stderr.

As rospy: arguments are %-formatted into the text, DEBUG lines show only with
``init_node(..., log_level=rospy.DEBUG)``; ``_throttle(period, ...)`` and ``_once`` variants
are keyed by the calling line. Not sent to ``/rosout`` (yet).
"""

from __future__ import annotations

import sys
import threading
import time
from typing import Any

__all__ = ["DEBUG", "ERROR", "FATAL", "INFO", "WARN", "logdebug", "logdebug_once", "logdebug_throttle", "logerr",
           "logerr_once", "logerr_throttle", "logfatal", "logfatal_once", "logfatal_throttle", "loginfo",
           "loginfo_once", "loginfo_throttle", "logwarn", "logwarn_once", "logwarn_throttle", "set_level"]

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


_last: dict[tuple[str, int, int], float] = {}
_seen: set[tuple[str, int, int]] = set()


def _site() -> tuple[str, int]:
    # The caller's caller: the line in user code that logs (rospy keys throttling by it too).
    frame = sys._getframe(3)
    return frame.f_code.co_filename, frame.f_lineno


def _throttled(level: int, period: float, msg: Any, args: tuple[Any, ...]) -> None:
    key = (*_site(), level)
    now = time.monotonic()
    with _lock:
        if key in _last and now - _last[key] < period:
            return
        _last[key] = now
    _log(level, msg, args)


def _once(level: int, msg: Any, args: tuple[Any, ...]) -> None:
    key = (*_site(), level)
    with _lock:
        if key in _seen:
            return
        _seen.add(key)
    _log(level, msg, args)


def logdebug_throttle(period: float, msg: Any, *args: Any) -> None:
    """Logdebug at most once per ``period`` seconds from this line."""
    _throttled(DEBUG, period, msg, args)


def loginfo_throttle(period: float, msg: Any, *args: Any) -> None:
    """Loginfo at most once per ``period`` seconds from this line."""
    _throttled(INFO, period, msg, args)


def logwarn_throttle(period: float, msg: Any, *args: Any) -> None:
    """Logwarn at most once per ``period`` seconds from this line."""
    _throttled(WARN, period, msg, args)


def logerr_throttle(period: float, msg: Any, *args: Any) -> None:
    """Logerr at most once per ``period`` seconds from this line."""
    _throttled(ERROR, period, msg, args)


def logfatal_throttle(period: float, msg: Any, *args: Any) -> None:
    """Logfatal at most once per ``period`` seconds from this line."""
    _throttled(FATAL, period, msg, args)


def logdebug_once(msg: Any, *args: Any) -> None:
    """Logdebug only the first time this line runs."""
    _once(DEBUG, msg, args)


def loginfo_once(msg: Any, *args: Any) -> None:
    """Loginfo only the first time this line runs."""
    _once(INFO, msg, args)


def logwarn_once(msg: Any, *args: Any) -> None:
    """Logwarn only the first time this line runs."""
    _once(WARN, msg, args)


def logerr_once(msg: Any, *args: Any) -> None:
    """Logerr only the first time this line runs."""
    _once(ERROR, msg, args)


def logfatal_once(msg: Any, *args: Any) -> None:
    """Logfatal only the first time this line runs."""
    _once(FATAL, msg, args)
