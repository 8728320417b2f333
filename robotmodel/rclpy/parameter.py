"""rclpy.parameter: Parameter with its Type, and conversions to and from rcl_interfaces messages.

``Parameter('rate', value=20)`` infers INTEGER; ``Parameter('xs', Parameter.Type.DOUBLE_ARRAY,
[1.0])`` checks the value against the type, as rclpy does. ``type_`` is the parameter's
Type; arrays come back as lists (rclpy gives array.array for numbers; both compare equal to lists).
"""

from __future__ import annotations

from enum import IntEnum
from typing import Any

from robotmodel.msgs.rcl_interfaces.msg import Parameter as ParameterMsg
from robotmodel.msgs.rcl_interfaces.msg import ParameterValue

__all__ = ["Parameter", "get_parameter_value", "parameter_value_to_python"]


def _is_int(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


class _Type(IntEnum):
    NOT_SET = 0
    BOOL = 1
    INTEGER = 2
    DOUBLE = 3
    STRING = 4
    BYTE_ARRAY = 5
    BOOL_ARRAY = 6
    INTEGER_ARRAY = 7
    DOUBLE_ARRAY = 8
    STRING_ARRAY = 9

    @classmethod
    def from_parameter_value(cls, value: Any) -> _Type:
        """The type of a Python value, as rclpy infers it (ValueError/TypeError otherwise)."""
        if value is None:
            return cls.NOT_SET
        if isinstance(value, bool):
            return cls.BOOL
        if isinstance(value, int):
            return cls.INTEGER
        if isinstance(value, float):
            return cls.DOUBLE
        if isinstance(value, str):
            return cls.STRING
        if isinstance(value, bytes):
            return cls.BYTE_ARRAY
        if isinstance(value, (list, tuple)) or hasattr(value, "typecode"):
            items = list(value)
            if items and all(isinstance(v, bytes) for v in items):
                return cls.BYTE_ARRAY
            if items and all(isinstance(v, bool) for v in items):
                return cls.BOOL_ARRAY
            if items and all(_is_int(v) for v in items):
                return cls.INTEGER_ARRAY
            if items and all(isinstance(v, float) for v in items):
                return cls.DOUBLE_ARRAY
            if items and all(isinstance(v, str) for v in items):
                return cls.STRING_ARRAY
            raise TypeError("The given value is not a list of one of the allowed types "
                            f"'{value}'.")
        raise TypeError(f"The given value is not one of the allowed types '{value}'.")

    def check(self, value: Any) -> bool:
        """Whether ``value`` is of this type."""
        if self == _Type.NOT_SET:
            return value is None
        if value is None:
            return False
        if self in (_Type.BYTE_ARRAY, _Type.BOOL_ARRAY, _Type.INTEGER_ARRAY, _Type.DOUBLE_ARRAY,
                    _Type.STRING_ARRAY) and not isinstance(value, (str, bytes)) and len(list(value)) == 0:
            return True
        try:
            return _Type.from_parameter_value(value) == self
        except TypeError:
            return False


class Parameter:
    """A named, typed parameter value, as rclpy's."""

    Type = _Type

    def __init__(self, name: str, type_: _Type | None = None, value: Any = None) -> None:
        if type_ is None:
            type_ = _Type.from_parameter_value(value)
        if not isinstance(type_, _Type):
            raise TypeError("type must be an instance of Parameter.Type")
        if not type_.check(value):
            raise ValueError(f"Type '{type_}' and value '{value}' do not agree")
        self._name = name
        self._type = type_
        self._value = list(value) if isinstance(value, tuple) or hasattr(value, "typecode") else value

    @property
    def name(self) -> str:
        """The parameter's name."""
        return self._name

    @property
    def type_(self) -> _Type:
        """The parameter's Type."""
        return self._type

    @property
    def value(self) -> Any:
        """The value (None when NOT_SET)."""
        return self._value

    def get_parameter_value(self) -> Any:
        """The rcl_interfaces/ParameterValue message of the value."""
        return get_parameter_value(self._type, self._value)

    def to_parameter_msg(self) -> Any:
        """The rcl_interfaces/Parameter message."""
        return ParameterMsg(name=self._name, value=self.get_parameter_value())

    @classmethod
    def from_parameter_msg(cls, param_msg: Any) -> Parameter:
        """From an rcl_interfaces/Parameter message."""
        value = parameter_value_to_python(param_msg.value)
        return cls(param_msg.name, _Type(param_msg.value.type), value)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Parameter):
            return NotImplemented
        return (self._name, self._type, self._value) == (other._name, other._type, other._value)

    def __hash__(self) -> int:
        return hash((self._name, self._type))

    def __repr__(self) -> str:
        return f"Parameter(name={self._name!r}, type_={self._type.name}, value={self._value!r})"


_FIELDS = {_Type.BOOL: "bool_value", _Type.INTEGER: "integer_value", _Type.DOUBLE: "double_value",
           _Type.STRING: "string_value", _Type.BYTE_ARRAY: "byte_array_value", _Type.BOOL_ARRAY: "bool_array_value",
           _Type.INTEGER_ARRAY: "integer_array_value", _Type.DOUBLE_ARRAY: "double_array_value",
           _Type.STRING_ARRAY: "string_array_value"}


def get_parameter_value(type_: _Type | int, value: Any) -> Any:
    """The rcl_interfaces/ParameterValue message of a typed value."""
    kind = _Type(type_)
    msg = ParameterValue(type=int(kind))
    if kind == _Type.BYTE_ARRAY:
        value = [v[0] if isinstance(v, bytes) else int(v) for v in (value or [])]
    field = _FIELDS.get(kind)
    if field is not None:
        setattr(msg, field, list(value) if isinstance(value, (list, tuple)) else value)
    return msg


def parameter_value_to_python(parameter_value: Any) -> Any:
    """The Python value of an rcl_interfaces/ParameterValue (None for NOT_SET)."""
    kind = _Type(parameter_value.type)
    if kind == _Type.NOT_SET:
        return None
    value = getattr(parameter_value, _FIELDS[kind])
    if kind == _Type.BYTE_ARRAY:
        return [bytes([int(v)]) for v in value]
    return list(value) if kind >= _Type.BYTE_ARRAY else value
