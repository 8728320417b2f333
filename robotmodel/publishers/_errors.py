"""The publishers' error class, defined in :mod:`robotmodel.errors` with the rest of the tree."""

from __future__ import annotations

from robotmodel.errors import PublisherError

__all__ = ["PublisherError"]
