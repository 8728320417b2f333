"""rcl_interfaces.srv: the parameter services (``ListParameters.Request()`` ...)."""

from __future__ import annotations

from typing import Any

from robotmodel.msgs._dynamic import service_class

__all__ = ["DescribeParameters", "GetParameterTypes", "GetParameters", "ListParameters", "SetParameters",
           "SetParametersAtomically"]

DescribeParameters: Any = service_class("rcl_interfaces/srv/DescribeParameters")
GetParameterTypes: Any = service_class("rcl_interfaces/srv/GetParameterTypes")
GetParameters: Any = service_class("rcl_interfaces/srv/GetParameters")
ListParameters: Any = service_class("rcl_interfaces/srv/ListParameters")
SetParameters: Any = service_class("rcl_interfaces/srv/SetParameters")
SetParametersAtomically: Any = service_class("rcl_interfaces/srv/SetParametersAtomically")
