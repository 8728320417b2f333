"""A node's parameters as rclpy keeps them: declared, typed, described, guarded by callbacks.

:class:`ParameterTable` is what :class:`robotmodel.rclpy.node.Node` and robotmodel's
robot_state_publisher share, and what the ROS 2 parameter services
(:mod:`._param_services`) serve. Its rules are rclpy's: a parameter is declared before use
(unless undeclared ones are allowed), with a value from the command line's overrides
winning over the declared default; a statically typed parameter keeps its type (a value of
another type is refused with rclcpp's "Wrong parameter type" reason); read-only ones refuse
every set after declaration; descriptors' integer and floating-point ranges are enforced;
pre-set callbacks may change the list, on-set callbacks may refuse it (all of it: sets are
atomic per call), post-set callbacks see what was set. Setting a parameter to NOT_SET
undeclares it (``ros2 param delete``) where its typing is dynamic; a statically typed one
refuses with rclpy's (or rclcpp's wrong-type) reason.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

from robotmodel.msgs.rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from robotmodel.rclpy.exceptions import (
    InvalidParameterTypeException,
    InvalidParameterValueException,
    ParameterAlreadyDeclaredException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from robotmodel.rclpy.parameter import Parameter

__all__ = ["ParameterTable"]

OnSet = Callable[[list[Parameter]], Any]
PreSet = Callable[[list[Parameter]], list[Parameter]]
PostSet = Callable[[list[Parameter]], None]


def _python_value(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value


class ParameterTable:
    """One node's parameters (see the module docstring); thread-safe."""

    def __init__(self, overrides: Mapping[str, Any] | None = None, allow_undeclared: bool = False,
                 rclcpp: bool = False) -> None:
        self.overrides = {k: _python_value(v) for k, v in (overrides or {}).items()}
        # A C++ node's (robot_state_publisher's) refusal of a wrong type reads as rclcpp's.
        self.rclcpp = rclcpp
        self.allow_undeclared = allow_undeclared
        self._params: dict[str, Parameter] = {}
        self._descriptors: dict[str, Any] = {}
        self._on_set: list[OnSet] = []
        self._pre_set: list[PreSet] = []
        self._post_set: list[PostSet] = []
        self._lock = threading.RLock()

    # -- declaring -------------------------------------------------------------------------------
    def declare(self, name: str, value: Any = None, descriptor: Any = None, ignore_override: bool = False) -> Parameter:
        """Declare ``name`` (a value, a ``Parameter.Type`` for an uninitialized typed one, or None)."""
        descriptor = descriptor if descriptor is not None else ParameterDescriptor()
        descriptor.name = name
        if isinstance(value, Parameter.Type):
            if value == Parameter.Type.NOT_SET:
                raise ValueError(f"Cannot declare parameter '{name}' as statically typed of type NOT_SET")
            descriptor.type = int(value)
            value = None
        elif value is not None and not descriptor.dynamic_typing:
            descriptor.type = int(Parameter.Type.from_parameter_value(value))
        if not ignore_override and name in self.overrides:
            value = self.overrides[name]
        with self._lock:
            if name in self._params:
                raise ParameterAlreadyDeclaredException([name])
        param = Parameter(name, value=value) if value is not None else Parameter(name, Parameter.Type.NOT_SET)
        if value is not None and descriptor.type and not descriptor.dynamic_typing \
                and int(param.type_) != descriptor.type:
            raise InvalidParameterTypeException(param, Parameter.Type(descriptor.type).name)
        reason = self._check_one(param, descriptor, declaring=True)
        if reason:
            raise InvalidParameterValueException(name, value, reason)
        result = self._apply([param], {name: descriptor}, declaring=True)
        if not result.successful:
            raise InvalidParameterValueException(name, value, result.reason)
        return param

    def undeclare(self, name: str) -> None:
        """Forget ``name`` (read-only ones cannot be undeclared)."""
        with self._lock:
            if name not in self._params:
                raise ParameterNotDeclaredException([name])
            if self._descriptors[name].read_only:
                raise ParameterImmutableException(name)
            del self._params[name], self._descriptors[name]

    # -- reading ---------------------------------------------------------------------------------
    def has(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        with self._lock:
            return name in self._params

    def get(self, name: str) -> Parameter:
        """The parameter (undeclared: NOT_SET if allowed, else ParameterNotDeclaredException)."""
        with self._lock:
            param = self._params.get(name)
            descriptor = self._descriptors.get(name)
        if param is None:
            if self.allow_undeclared:
                return Parameter(name, Parameter.Type.NOT_SET)
            raise ParameterNotDeclaredException(name)
        if param.type_ == Parameter.Type.NOT_SET and descriptor is not None and descriptor.type \
                and not descriptor.dynamic_typing:
            raise ParameterUninitializedException(name)
        return param

    def names(self) -> list[str]:
        """Every declared name, in declaration order (as rclpy lists them)."""
        with self._lock:
            return list(self._params)

    def descriptor(self, name: str) -> Any:
        """The descriptor of a declared parameter."""
        with self._lock:
            found = self._descriptors.get(name)
        if found is None:
            raise ParameterNotDeclaredException([name])
        return found

    def set_descriptor(self, name: str, descriptor: Any) -> Any:
        """Replace a declared parameter's descriptor (its name and type stay)."""
        with self._lock:
            old = self.descriptor(name)
            descriptor.name, descriptor.type = name, old.type
            self._descriptors[name] = descriptor
        return descriptor

    # -- setting ---------------------------------------------------------------------------------
    def set_atomically(self, params: Sequence[Parameter]) -> Any:
        """Set all or none; the SetParametersResult says which and why."""
        descriptors: dict[str, Any] = {}
        with self._lock:
            for param in params:
                found = self._descriptors.get(param.name)
                if found is None:
                    if not self.allow_undeclared:
                        raise ParameterNotDeclaredException([param.name])
                    found = ParameterDescriptor(name=param.name, dynamic_typing=True)
                descriptors[param.name] = found
        for param in params:
            reason = self._check_one(param, descriptors[param.name])
            if reason:
                return SetParametersResult(successful=False, reason=reason)
        return self._apply(list(params), descriptors)

    def set(self, params: Sequence[Parameter]) -> list[Any]:
        """Set each on its own (rclpy's ``set_parameters``): one result per parameter."""
        return [self.set_atomically([param]) for param in params]

    def _check_one(self, param: Parameter, descriptor: Any, declaring: bool = False) -> str:
        # rclpy's checks and reasons, in its order: read-only, type, then the ranges.
        if descriptor.read_only and not declaring:
            return f"Trying to set a read-only parameter: {param.name}."
        unset = param.type_ == Parameter.Type.NOT_SET
        if descriptor.dynamic_typing:
            descriptor.type = int(param.type_)
        elif unset and not declaring and self.has(param.name) and not self.rclcpp:
            return "Static parameter cannot be undeclared"
        # rclcpp has no undeclare rule of its own: NOT_SET is just another wrong type there.
        elif (not unset or (self.rclcpp and not declaring)) and int(param.type_) != descriptor.type:
            if self.rclcpp:
                return (f"Wrong parameter type, parameter {{{param.name}}} is of type "
                        f"{{{_RCLCPP_TYPES[descriptor.type]}}}, setting it to "
                        f"{{{_RCLCPP_TYPES[int(param.type_)]}}} is not allowed.")
            return (f"Wrong parameter type, expected 'Type.{Parameter.Type(descriptor.type).name}' "
                    f"got 'Type.{param.type_.name}'")
        value = param.value
        if param.type_ == Parameter.Type.INTEGER and descriptor.integer_range:
            return _integer_range(param.name, value, descriptor.integer_range[0])
        if param.type_ == Parameter.Type.DOUBLE and descriptor.floating_point_range:
            return _float_range(param.name, value, descriptor.floating_point_range[0])
        return ""

    def _apply(self, params: list[Parameter], descriptors: Mapping[str, Any], declaring: bool = False) -> Any:
        with self._lock:
            pre, on_set, post = list(self._pre_set), list(self._on_set), list(self._post_set)
        for pre_hook in pre:
            params = list(pre_hook(params))
        for callback in on_set:
            result = callback(params)
            if not result.successful:
                return result
        with self._lock:
            for param in params:
                if param.type_ == Parameter.Type.NOT_SET and not declaring:
                    # A set to NOT_SET undeclares, as rclpy and rclcpp do (ros2 param delete).
                    self._params.pop(param.name, None)
                    self._descriptors.pop(param.name, None)
                    continue
                self._params[param.name] = param
                if param.name in descriptors:
                    self._descriptors[param.name] = descriptors[param.name]
        for hook in post:
            hook(params)
        return SetParametersResult(successful=True)

    # -- callbacks -------------------------------------------------------------------------------
    def add_on_set(self, callback: OnSet) -> OnSet:
        """Ask ``callback(params) -> SetParametersResult`` before each set; newest first, as rclpy."""
        with self._lock:
            self._on_set.insert(0, callback)
        return callback

    def remove_on_set(self, callback: OnSet) -> None:
        """Stop asking ``callback``; ValueError when it was not added."""
        with self._lock:
            self._on_set.remove(callback)

    def add_pre_set(self, callback: PreSet) -> PreSet:
        """Let ``callback(params) -> params`` change what a set sets."""
        with self._lock:
            self._pre_set.append(callback)
        return callback

    def add_post_set(self, callback: PostSet) -> PostSet:
        """Tell ``callback(params)`` what was set."""
        with self._lock:
            self._post_set.append(callback)
        return callback

    def list(self, prefixes: Iterable[str], depth: int) -> tuple[list[str], list[str]]:
        """(names, prefixes) as the list_parameters service answers (depth 0: any depth)."""
        wanted = list(prefixes)
        names: list[str] = []
        found_prefixes: set[str] = set()
        for name in self.names():
            dots = name.count(".")
            if depth and dots >= depth:
                continue
            if wanted and not any(name == p or name.startswith(p + ".") for p in wanted):
                continue
            names.append(name)
            if dots:
                found_prefixes.add(name.rsplit(".", 1)[0])
        return names, sorted(found_prefixes)


def _integer_range(name: str, value: int, r: Any) -> str:
    low, high = min(r.from_value, r.to_value), max(r.from_value, r.to_value)
    if value in (low, high):
        return ""
    if not low < value < high:
        return f"Parameter {name} out of range. Min: {low}, Max: {high}, value: {value}"
    if r.step and (value - low) % r.step:
        return (f"The parameter value for {name} is not a valid step. "
                f"Min: {low}, max: {high}, value: {value}, step: {r.step}")
    return ""


def _float_range(name: str, value: float, r: Any) -> str:
    low, high = min(r.from_value, r.to_value), max(r.from_value, r.to_value)
    if math.isclose(value, low, rel_tol=_REL_TOL) or math.isclose(value, high, rel_tol=_REL_TOL):
        return ""
    if not low < value < high:
        return f"Parameter {name} out of range Min: {low}, Max: {high}, value: {value}"
    if r.step and not math.isclose(low + round((value - low) / r.step) * r.step, value, rel_tol=_REL_TOL):
        return (f"The parameter value for {name} is not close enough to a valid step. "
                f"Min: {low}, max: {high}, value: {value}, step: {r.step}")
    return ""


# rclcpp's names of the parameter types (rclcpp::to_string(ParameterType)).
_RCLCPP_TYPES = ["not set", "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
                 "double_array", "string_array"]
# rclpy's Node.PARAM_REL_TOL.
_REL_TOL = 1e-6

