"""What ROS's tools print besides their data: rcutils log lines (and loggers printing them), C's number parsing.

The TF tools mimic ROS 2 programs, so their diagnostics look like rcutils' default console
output (``[SEVERITY] [sec.nanosec] [logger]: message``, all severities on stderr), and
their numbers are read the way ``std::stod``/``std::stof`` read them (a numeric prefix is
accepted; what follows is reported separately).
"""

from __future__ import annotations

import logging
import re
import sys
import time
from typing import TextIO

__all__ = ["SEVERITIES", "effective_level", "log_enabled", "log_line", "ros_console", "ros_log", "set_log_level",
           "strtod_prefix"]

#: rcutils' severities and their numbers.
SEVERITIES = {"UNSET": 0, "DEBUG": 10, "INFO": 20, "WARN": 30, "ERROR": 40, "FATAL": 50}
# Logger name -> level; "" is the default level, as rcutils' (``--log-level LEVEL``).
_levels: dict[str, int] = {"": SEVERITIES["INFO"]}


def set_log_level(logger: str, level: int | str) -> None:
    """Set a logger's level (``""``: the default of every logger not given one), as ``--log-level [name:=]LEVEL``."""
    if isinstance(level, str):
        key = level.strip().upper()
        level = SEVERITIES["WARN" if key == "WARNING" else key]
    _levels[logger] = int(level)


def effective_level(logger: str) -> int:
    """The level in force for ``logger``: its own, else its nearest dotted ancestor's, else the default."""
    name = logger
    while name:
        level = _levels.get(name)
        if level:
            return level
        name = name.rpartition(".")[0]
    return _levels[""]


def log_enabled(severity: str, logger: str) -> bool:
    """Whether a line of ``severity`` from ``logger`` prints under the levels set."""
    return SEVERITIES.get(severity, SEVERITIES["FATAL"]) >= effective_level(logger)

# strtod's grammar (decimal, hexadecimal, inf/infinity, nan with an optional tag), after
# optional leading white space. Compiled on first use: `robotmodel --help` never needs it.
_NUMBER_PATTERN = (
    r"""\s*[+-]?(?:
        0[xX](?:[0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)(?:[pP][+-]?[0-9]+)?
      | (?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?
      | [iI][nN][fF](?:[iI][nN][iI][tT][yY])?
      | [nN][aA][nN](?:\([0-9A-Za-z_]*\))?
    )"""
)
_number: re.Pattern[str] | None = None


def strtod_prefix(text: str) -> tuple[float, int] | None:
    """The number at the start of ``text`` and how many characters it used, as C's strtod reads it.

    None when no number starts the text (where ``std::stod`` throws ``invalid_argument``).
    """
    global _number
    if _number is None:
        _number = re.compile(_NUMBER_PATTERN, re.VERBOSE)
    found = _number.match(text)
    if found is None:
        return None
    literal = found.group(0).strip()
    body = literal.lstrip("+-")
    negative = literal.startswith("-")
    if body[:2].lower() == "0x":
        hex_body = body if "p" in body.lower() else body + "p0"
        value = float.fromhex(hex_body)
    elif body[:3].lower() == "nan":
        value = float("nan")
    else:
        value = float(body)
    return (-value if negative else value), found.end()


def log_line(severity: str, logger: str, message: str, now_ns: int | None = None) -> str:
    """One rcutils console line: ``[INFO] [1716697697.040514000] [tf2_echo]: message``."""
    ns = time.time_ns() if now_ns is None else now_ns
    return f"[{severity}] [{ns // 1_000_000_000}.{ns % 1_000_000_000:09d}] [{logger}]: {message}"


def ros_log(severity: str, logger: str, message: str, stream: TextIO | None = None) -> None:
    """Write :func:`log_line` to stderr (where rcutils sends every severity) and flush."""
    if not log_enabled(severity, logger):
        return
    out = sys.stderr if stream is None else stream
    print(log_line(severity, logger, message), file=out, flush=True)


# rcutils' severity names for Python's levels.
_SEVERITY = {logging.DEBUG: "DEBUG", logging.INFO: "INFO", logging.WARNING: "WARN", logging.ERROR: "ERROR",
             logging.CRITICAL: "FATAL"}


class _RcutilsHandler(logging.Handler):
    def emit(self, record: logging.LogRecord) -> None:
        try:
            severity = _SEVERITY.get(record.levelno, record.levelname)
            if not log_enabled(severity, record.name):
                return
            text = log_line(severity, record.name, record.getMessage(), int(record.created * 1e9))
            print(text, file=sys.stderr, flush=True)
        except Exception:
            self.handleError(record)


def ros_console(name: str) -> logging.Logger:
    """The logger ``name`` printing to stderr in rcutils' format, as a ROS 2 node's does.

    INFO and above unless ``--log-level`` said otherwise (:func:`set_log_level`).
    """
    logger = logging.getLogger(name)
    if not any(isinstance(h, _RcutilsHandler) for h in logger.handlers):
        logger.addHandler(_RcutilsHandler())
    logger.setLevel(logging.DEBUG)  # the handler decides, by the rcutils levels in force
    logger.propagate = False
    return logger
