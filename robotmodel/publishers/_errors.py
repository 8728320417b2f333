"""The publishers' error class (joins :mod:`robotmodel.errors`' tree under RobotModelError)."""

from __future__ import annotations

from robotmodel.errors import RobotModelError

__all__ = ["PublisherError"]


class PublisherError(RobotModelError, ValueError):
    """A state publisher was given a parameter outside its range (ROS's text where ROS has one)."""
