"""rospy's logging: ``[INFO] [1700000000.123456]: text``; INFO/DEBUG on stdout, WARN/ERROR/FATAL on stderr; ``/rosout``.

As rospy: arguments are %-formatted into the text, DEBUG lines show only with
``init_node(..., log_level=rospy.DEBUG)``; ``_throttle(period, ...)`` and ``_once`` variants
are keyed by the calling line. ``ROSCONSOLE_FORMAT`` is followed (``${severity}``,
``${message}``, ``${time}``, ``${walltime}``, ``${node}``, ``${file}``, ``${line}``,
``${function}``, ``${logger}``, ``${thread}``); under ``/use_sim_time`` ``${time}`` is
``wall, sim``. Each line printed is also handed to the sink init_node installs (the
node's ``/rosout``), with the calling file, function and line.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from collections.abc import Callable
from typing import Any

from robotmodel.rospy import _time

__all__ = ["DEBUG", "ERROR", "FATAL", "INFO", "WARN", "logdebug", "logdebug_once", "logdebug_throttle", "logerr",
           "logerr_once", "logerr_throttle", "logfatal", "logfatal_once", "logfatal_throttle", "loginfo",
           "loginfo_once", "loginfo_throttle", "logwarn", "logwarn_once", "logwarn_throttle", "set_level",
           "set_sink"]

DEBUG = 1
INFO = 2
WARN = 4
ERROR = 8
FATAL = 16

_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}
_COLORS = {WARN: "\033[33m", ERROR: "\033[31m", FATAL: "\033[31m"}
_FORMAT = "[${severity}] [${time}]: ${message}"
_level = INFO
_lock = threading.Lock()
#: (level, text, file path, line, function) -> None: where lines go besides the console.
Sink = Callable[[int, str, str, int, str], None]
_sink: list[Sink] = []
_node_name = ["/unnamed"]


def set_level(level: int) -> None:
    """The lowest level printed (init_node's ``log_level``)."""
    global _level
    _level = level


def set_sink(sink: Sink | None, node_name: str = "/unnamed") -> None:
    """Hand every logged line to ``sink`` too (None: the console only); ``node_name`` is ``${node}``."""
    _sink[:] = [] if sink is None else [sink]
    _node_name[0] = node_name


def _line(level: int, text: str, path: str, lineno: int, function: str) -> str:
    wall = time.time()
    stamp = f"{wall:f}" if _time.is_wallclock() else f"{wall:f}, {_time.get_time():f}"
    fmt = os.environ.get("ROSCONSOLE_FORMAT", _FORMAT)
    if fmt == _FORMAT:
        return f"[{_NAMES[level]}] [{stamp}]: {text}\n"
    for tag, value in (("${severity}", _NAMES[level]), ("${message}", text), ("${walltime}", f"{wall:f}"),
                       ("${thread}", str(threading.get_ident())), ("${logger}", "rosout"), ("${file}", path),
                       ("${line}", str(lineno)), ("${function}", function), ("${node}", _node_name[0]),
                       ("${time}", stamp)):
        fmt = fmt.replace(tag, value)
    return fmt + "\n"


def _log(level: int, msg: Any, args: tuple[Any, ...], depth: int = 2) -> None:
    if level < _level:
        return
    text = str(msg) % args if args else str(msg)
    frame = sys._getframe(depth)
    path, lineno, function = frame.f_code.co_filename, frame.f_lineno, frame.f_code.co_name
    stream = sys.stdout if level <= INFO else sys.stderr
    line = _line(level, text, path, lineno, function)
    if level in _COLORS and stream.isatty():
        line = _COLORS[level] + line.rstrip("\n") + "\033[0m\n"
    with _lock:
        stream.write(line)
        stream.flush()
    for sink in _sink:
        sink(level, text, path, lineno, function)


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
    _log(level, msg, args, 3)


def _once(level: int, msg: Any, args: tuple[Any, ...]) -> None:
    key = (*_site(), level)
    with _lock:
        if key in _seen:
            return
        _seen.add(key)
    _log(level, msg, args, 3)


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
