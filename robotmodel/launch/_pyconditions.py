"""launch's conditions (``launch.conditions``): whether an action runs.

A condition expression is true for ``true``/``1`` and false for ``false``/``0`` (any case,
stripped), anything else is launch's error; ``LaunchConfigurationEquals`` compares a
configuration's text (both unset counts as equal).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robotmodel.launch._pyctx import LaunchContext
from robotmodel.launch._pysubst import Substitution, _text, normalize, perform_all

__all__ = [
    "Condition",
    "IfCondition",
    "InvalidConditionExpressionError",
    "LaunchConfigurationEquals",
    "LaunchConfigurationNotEquals",
    "UnlessCondition",
    "evaluate_condition_expression",
]


class InvalidConditionExpressionError(ValueError):
    """launch's error for a condition that is neither true/1 nor false/0."""


class Condition:
    """A predicate deciding whether an action runs."""

    def __init__(self, *, predicate: Callable[[LaunchContext], bool] | None = None) -> None:
        self._predicate = predicate

    def evaluate(self, context: LaunchContext) -> bool:
        """Whether the action runs."""
        return bool(self._predicate(context)) if self._predicate is not None else True


def evaluate_condition_expression(context: LaunchContext, expression: list[Substitution]) -> bool:
    """True for 'true'/'1', False for 'false'/'0' (any case, stripped); anything else is an error."""
    text = perform_all(context, expression).strip().lower()
    if text in ("true", "1"):
        return True
    if text in ("false", "0"):
        return False
    raise InvalidConditionExpressionError(
        f"invalid condition expression, expected one of [true, 1, false, 0] but got '{text}', expanded from "
        f"'{' + '.join(str(s) for s in expression)}'")


class IfCondition(Condition):
    """Runs the action when the expression is true."""

    def __init__(self, predicate_expression: Any) -> None:
        subs = normalize(_text(predicate_expression))
        super().__init__(predicate=lambda c: evaluate_condition_expression(c, subs))


class UnlessCondition(Condition):
    """Runs the action when the expression is false."""

    def __init__(self, predicate_expression: Any) -> None:
        subs = normalize(_text(predicate_expression))
        super().__init__(predicate=lambda c: not evaluate_condition_expression(c, subs))


class LaunchConfigurationEquals(Condition):
    """Runs the action when a configuration equals ``expected_value`` (both unset counts as equal)."""

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        expected = None if expected_value is None else normalize(_text(expected_value))

        def equal(context: LaunchContext) -> bool:
            want = None if expected is None else perform_all(context, expected)
            return context.launch_configurations.get(launch_configuration_name) == want

        super().__init__(predicate=equal)


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """Runs the action unless a configuration equals ``expected_value``."""

    def evaluate(self, context: LaunchContext) -> bool:
        """The negation."""
        return not super().evaluate(context)
