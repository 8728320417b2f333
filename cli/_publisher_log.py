"""Log records of the publisher commands as rcutils prints them: ``[WARN] [sec.nanosec] [node]: text``."""

from __future__ import annotations

import logging
import sys

from robotmodel.cli._rosfmt import log_line

__all__ = ["ros_console"]

# rcutils' severity names for Python's levels.
_SEVERITY = {logging.DEBUG: "DEBUG", logging.INFO: "INFO", logging.WARNING: "WARN", logging.ERROR: "ERROR",
             logging.CRITICAL: "FATAL"}


class _RcutilsHandler(logging.Handler):
    def emit(self, record: logging.LogRecord) -> None:
        try:
            severity = _SEVERITY.get(record.levelno, record.levelname)
            text = log_line(severity, record.name, record.getMessage(), int(record.created * 1e9))
            print(text, file=sys.stderr, flush=True)
        except Exception:
            self.handleError(record)


def ros_console(name: str) -> logging.Logger:
    """The logger ``name`` printing INFO and above to stderr in rcutils' format, as a ROS 2 node's does."""
    logger = logging.getLogger(name)
    if not any(isinstance(h, _RcutilsHandler) for h in logger.handlers):
        logger.addHandler(_RcutilsHandler())
    logger.setLevel(logging.INFO)
    logger.propagate = False
    return logger
