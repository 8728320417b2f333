"""The viewer's error class (part of the tree rooted at :class:`robotmodel.errors.RobotModelError`)."""

from __future__ import annotations

from robotmodel.errors import RobotModelError

__all__ = ["ViewerError"]


class ViewerError(RobotModelError):
    """The viewer could not do what was asked: no browser, a port in use, a page that did not load."""
