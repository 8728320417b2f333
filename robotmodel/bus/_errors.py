"""The bus's error class, from :mod:`robotmodel.errors`' single tree."""

from __future__ import annotations

from robotmodel.errors import BusError

__all__ = ["BusError"]
