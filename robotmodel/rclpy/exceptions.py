"""rclpy.exceptions: the errors rclpy's node and parameter API raise, with rclpy's texts.

The classes live in :mod:`robotmodel.errors` (under :class:`~robotmodel.errors.RclpyError`).
"""

from __future__ import annotations

from robotmodel.errors import (
    InvalidParameterTypeException,
    InvalidParameterValueException,
    NotInitializedException,
    ParameterAlreadyDeclaredException,
    ParameterException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)

__all__ = [
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "NotInitializedException",
    "ParameterAlreadyDeclaredException",
    "ParameterException",
    "ParameterImmutableException",
    "ParameterNotDeclaredException",
    "ParameterUninitializedException",
]
