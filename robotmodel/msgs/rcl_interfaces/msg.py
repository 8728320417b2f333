"""rcl_interfaces.msg: the parameter messages, as dataclasses with ROS's defaults and constants."""

from __future__ import annotations

from typing import Any

from robotmodel.msgs._dynamic import message_class

__all__ = [
    "FloatingPointRange",
    "IntegerRange",
    "ListParametersResult",
    "Parameter",
    "ParameterDescriptor",
    "ParameterEvent",
    "ParameterType",
    "ParameterValue",
    "SetParametersResult",
]

FloatingPointRange: Any = message_class("rcl_interfaces/msg/FloatingPointRange")
IntegerRange: Any = message_class("rcl_interfaces/msg/IntegerRange")
ListParametersResult: Any = message_class("rcl_interfaces/msg/ListParametersResult")
Parameter: Any = message_class("rcl_interfaces/msg/Parameter")
ParameterDescriptor: Any = message_class("rcl_interfaces/msg/ParameterDescriptor")
ParameterEvent: Any = message_class("rcl_interfaces/msg/ParameterEvent")
ParameterType: Any = message_class("rcl_interfaces/msg/ParameterType")
ParameterValue: Any = message_class("rcl_interfaces/msg/ParameterValue")
SetParametersResult: Any = message_class("rcl_interfaces/msg/SetParametersResult")
