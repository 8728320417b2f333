"""rclpy.logging: named loggers writing rcutils' console lines to stderr.

``[INFO] [1716697697.040514000] [talker]: text``: every severity on stderr, as rcutils'
default console output. ``once``, ``throttle_duration_sec`` and ``skip_first`` are rclpy's
per-call-site filters (a call site is the calling file and line).
"""

from __future__ import annotations

import sys
import threading
import time
from enum import IntEnum
from typing import Any

from robotmodel.rcl import effective_level, log_line, set_log_level

__all__ = ["LoggingSeverity", "RcutilsLogger", "get_logger", "get_logging_severity_from_string"]


class LoggingSeverity(IntEnum):
    """rcutils' severities."""

    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


_NAMES = {LoggingSeverity.DEBUG: "DEBUG", LoggingSeverity.INFO: "INFO", LoggingSeverity.WARN: "WARN",
          LoggingSeverity.ERROR: "ERROR", LoggingSeverity.FATAL: "FATAL"}
_lock = threading.Lock()


def get_logging_severity_from_string(text: str) -> LoggingSeverity:
    """``'warn'`` -> LoggingSeverity.WARN (``WARNING`` too)."""
    key = text.strip().upper()
    return LoggingSeverity.WARN if key == "WARNING" else LoggingSeverity[key]


def set_default_level(level: LoggingSeverity | str) -> None:
    """The level of every logger not given one (``--log-level``)."""
    set_log_level("", get_logging_severity_from_string(level) if isinstance(level, str) else LoggingSeverity(level))


class RcutilsLogger:
    """A named logger: ``debug/info/warn/warning/error/fatal(message, **filters)``."""

    def __init__(self, name: str = "") -> None:
        self.name = name
        self._seen: dict[tuple[str, int], Any] = {}

    def get_child(self, name: str) -> RcutilsLogger:
        """The logger ``<this>.<name>``."""
        return RcutilsLogger(f"{self.name}.{name}" if self.name else name)

    def set_level(self, level: LoggingSeverity | int) -> None:
        """Set the level of this logger (``--log-level NAME:=LEVEL`` sets it too)."""
        set_log_level(self.name, LoggingSeverity(level))

    def get_effective_level(self) -> LoggingSeverity:
        """The level in force: its own, else its nearest ancestor's, else the default."""
        return LoggingSeverity(effective_level(self.name))

    def is_enabled_for(self, severity: LoggingSeverity | int) -> bool:
        """Whether a message of ``severity`` would print."""
        return severity >= self.get_effective_level()

    def log(self, message: Any, severity: LoggingSeverity | int, **kwargs: Any) -> bool:
        """Print ``message`` at ``severity`` unless a filter holds it back; True when printed."""
        severity = LoggingSeverity(severity)
        if not self.is_enabled_for(severity):
            return False
        frame = sys._getframe(2)
        site = (frame.f_code.co_filename, frame.f_lineno)
        now = time.monotonic()
        with _lock:
            state = self._seen.setdefault(site, {"count": 0, "last": None})
            state["count"] += 1
            if kwargs.get("once") and state["count"] > 1:
                return False
            if kwargs.get("skip_first") and state["count"] == 1:
                return False
            period = kwargs.get("throttle_duration_sec")
            if period is not None:
                if state["last"] is not None and now - state["last"] < float(period):
                    return False
                state["last"] = now
        print(log_line(_NAMES[severity], self.name, str(message)), file=sys.stderr, flush=True)
        return True

    def debug(self, message: Any, **kwargs: Any) -> bool:
        """Log at DEBUG."""
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message: Any, **kwargs: Any) -> bool:
        """Log at INFO."""
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message: Any, **kwargs: Any) -> bool:
        """Log at WARN."""
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    def warn(self, message: Any, **kwargs: Any) -> bool:
        """Log at WARN (rclpy's older spelling)."""
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    def error(self, message: Any, **kwargs: Any) -> bool:
        """Log at ERROR."""
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message: Any, **kwargs: Any) -> bool:
        """Log at FATAL."""
        return self.log(message, LoggingSeverity.FATAL, **kwargs)


def get_logger(name: str) -> RcutilsLogger:
    """The logger ``name``."""
    return RcutilsLogger(name)
