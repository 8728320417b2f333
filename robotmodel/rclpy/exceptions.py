"""rclpy.exceptions: the errors rclpy's node and parameter API raise, with rclpy's texts."""

from __future__ import annotations

from typing import Any

from robotmodel.errors import RobotModelError

__all__ = [
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "InvalidServiceNameException",
    "InvalidTopicNameException",
    "NotInitializedException",
    "ParameterAlreadyDeclaredException",
    "ParameterException",
    "ParameterImmutableException",
    "ParameterNotDeclaredException",
    "ParameterUninitializedException",
]


class NotInitializedException(RobotModelError):
    """rclpy.init() has not been called (or the context is shut down)."""

    def __init__(self, *args: Any) -> None:
        super().__init__("rclpy.init() has not been called", *args)


class InvalidTopicNameException(RobotModelError):
    """A topic name rcl refuses."""


class InvalidServiceNameException(RobotModelError):
    """A service name rcl refuses."""


class ParameterException(RobotModelError):
    """Base of the parameter errors (rclpy's)."""

    def __init__(self, error_msg: str, parameters: Any, *args: Any) -> None:
        super().__init__(f"{error_msg}: {parameters}", *args)
        self.parameters = parameters


class ParameterNotDeclaredException(ParameterException):
    """A parameter used before it was declared."""

    def __init__(self, parameters: Any, *args: Any) -> None:
        super().__init__("Invalid access to undeclared parameter(s)", parameters, *args)


class ParameterAlreadyDeclaredException(ParameterException):
    """A parameter declared twice."""

    def __init__(self, parameters: Any, *args: Any) -> None:
        super().__init__("Parameter(s) already declared", parameters, *args)


class ParameterUninitializedException(ParameterException):
    """A statically typed parameter read before it got a value."""

    def __init__(self, parameter_name: str, *args: Any) -> None:
        super().__init__(f"The parameter '{parameter_name}' is not initialized", parameter_name, *args)


class InvalidParameterValueException(ParameterException):
    """A value a descriptor's rules or a set-parameters callback refused."""

    def __init__(self, parameter: str, value: Any, reason: str, *args: Any) -> None:
        super().__init__(f"Invalid parameter value ({value}) for parameter. Reason: {reason}", parameter, *args)
        self.reason = reason


class InvalidParameterTypeException(ParameterException):
    """A value of another type than the parameter's (static typing)."""

    def __init__(self, desired_parameter: Any, expected_type: str, *args: Any) -> None:
        super().__init__(f"Trying to set parameter '{desired_parameter.name}' to '{desired_parameter.value}' of type "
                         f"'{desired_parameter.type_.name}', expecting type '{expected_type}'",
                         desired_parameter.name, *args)


class ParameterImmutableException(ParameterException):
    """A read-only parameter set after its declaration."""

    def __init__(self, parameter_name: str, *args: Any) -> None:
        super().__init__(f"Attempted to modify read-only parameter '{parameter_name}'", parameter_name, *args)
