"""launch's boolean substitutions: ``'true'``/``'false'`` from other substitutions' text.

Each side is read as launch reads a condition (``true``/``1``, ``false``/``0``, any case);
anything else is launch's error.
"""

from __future__ import annotations

from typing import Any

from robotmodel.launch._pyctx import LaunchContext
from robotmodel.launch._pysubst import Substitution, SubstitutionFailure, _text, normalize, perform_all

__all__ = [
    "AndSubstitution",
    "EqualsSubstitution",
    "IfElseSubstitution",
    "NotEqualsSubstitution",
    "NotSubstitution",
    "OrSubstitution",
]


def _truth(text: str) -> bool:
    word = text.strip().lower()
    if word in ("true", "1"):
        return True
    if word in ("false", "0"):
        return False
    raise SubstitutionFailure(f"invalid condition expression, expected one of [true, 1, false, 0] but got '{word}'")


class NotSubstitution(Substitution):
    """``'true'``/``'false'``: the negation."""

    def __init__(self, value: Any) -> None:
        self.value = normalize(value)

    def perform(self, context: LaunchContext) -> str:
        """The negated truth."""
        return str(not _truth(perform_all(context, self.value))).lower()


class AndSubstitution(Substitution):
    """Both true."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize(left), normalize(right)

    def perform(self, context: LaunchContext) -> str:
        """The conjunction."""
        values = [_truth(perform_all(context, s)) for s in (self.left, self.right)]
        return str(all(values)).lower()


class OrSubstitution(AndSubstitution):
    """Either true."""

    def perform(self, context: LaunchContext) -> str:
        """The disjunction."""
        values = [_truth(perform_all(context, s)) for s in (self.left, self.right)]
        return str(any(values)).lower()


class EqualsSubstitution(Substitution):
    """``'true'`` when both sides' text is equal."""

    def __init__(self, left: Any, right: Any) -> None:
        self.left, self.right = normalize(_text(left)), normalize(_text(right))

    def perform(self, context: LaunchContext) -> str:
        """The comparison."""
        return str(perform_all(context, self.left) == perform_all(context, self.right)).lower()


class NotEqualsSubstitution(EqualsSubstitution):
    """``'true'`` when both sides' text differs."""

    def perform(self, context: LaunchContext) -> str:
        """The comparison."""
        return str(perform_all(context, self.left) != perform_all(context, self.right)).lower()


class IfElseSubstitution(Substitution):
    """``if_value`` when ``condition`` is true, else ``else_value``."""

    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        self.condition = normalize(condition)
        self.if_value, self.else_value = normalize(if_value), normalize(else_value)

    def perform(self, context: LaunchContext) -> str:
        """The chosen value."""
        chosen = self.if_value if _truth(perform_all(context, self.condition)) else self.else_value
        return perform_all(context, chosen)
