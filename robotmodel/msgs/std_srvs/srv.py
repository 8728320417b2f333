"""std_srvs.srv: Empty, Trigger, SetBool."""

from __future__ import annotations

from typing import Any

from robotmodel.msgs._dynamic import service_class

__all__ = ["Empty", "SetBool", "Trigger"]

Empty: Any = service_class("std_srvs/srv/Empty")
SetBool: Any = service_class("std_srvs/srv/SetBool")
Trigger: Any = service_class("std_srvs/srv/Trigger")
