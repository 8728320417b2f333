"""example_interfaces.srv: AddTwoInts."""

from __future__ import annotations

from typing import Any

from robotmodel.msgs._dynamic import service_class

__all__ = ["AddTwoInts"]

AddTwoInts: Any = service_class("example_interfaces/srv/AddTwoInts")
