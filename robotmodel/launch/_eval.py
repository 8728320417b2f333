"""``$(eval EXPR)``: a small, safe subset of Python expressions, interpreted node by node.

Launch files use ``$(eval)`` for arithmetic, comparisons, boolean logic and string tests
(``$(eval arg('gui') and not arg('headless'))``, ``$(eval "'$(var m)'.endswith('.xacro')")``).
The expression is never handed to :func:`eval`: only literals, names the caller provides,
operators, conditional expressions, calls to the caller's functions and a few safe methods
of str/list are interpreted. There are no builtins, imports or dunder attributes, and sizes
are bounded so that ``'a' * 10**12`` is refused rather than exhausting memory.
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["EvalError", "safe_eval"]

_MAX_LEN = 1 << 20
_MAX_POW = 256
_MAX_DEPTH = 100

_BINOPS: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
}
_CMPOPS: dict[type[ast.cmpop], Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
    ast.Is: operator.is_, ast.IsNot: operator.is_not,
}
_STR_METHODS = frozenset({
    "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace", "split", "join",
    "isdigit", "count", "find", "title", "capitalize",
})
_SAFE_FUNCS: dict[str, Callable[..., Any]] = {
    "int": int, "float": float, "str": str, "bool": bool, "len": len, "abs": abs, "min": min, "max": max,
    "round": round,
}


class EvalError(Exception):
    """The expression is malformed, unsupported, or failed; ``str()`` says why."""


def safe_eval(text: str, names: Mapping[str, Any], functions: Mapping[str, Callable[..., Any]]) -> Any:
    """Evaluate ``text`` with ``names`` as variables and ``functions`` (plus int/str/len...) callable."""
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise EvalError(f"invalid expression '{text.strip()}': {exc.msg}") from None
    except (RecursionError, MemoryError, ValueError) as exc:
        raise EvalError(f"invalid expression: {type(exc).__name__}") from None
    interp = _Interpreter(names, {**_SAFE_FUNCS, **functions})
    try:
        return interp.visit(tree.body)
    except EvalError:
        raise
    except Exception as exc:
        raise EvalError(f"'{text.strip()}' failed: {type(exc).__name__}: {exc}") from None


class _Interpreter:
    def __init__(self, names: Mapping[str, Any], functions: Mapping[str, Callable[..., Any]]) -> None:
        self.names = names
        self.functions = functions
        self.depth = 0

    def visit(self, node: ast.AST) -> Any:
        method = getattr(self, f"_{type(node).__name__.lower()}", None)
        if method is None:
            raise EvalError(f"'{ast.unparse(node)}' is not allowed in $(eval)")
        if self.depth >= _MAX_DEPTH:
            raise EvalError(f"expression nested too deep (over {_MAX_DEPTH} levels)")
        self.depth += 1
        try:
            return _bounded(method(node))
        finally:
            self.depth -= 1

    def _constant(self, node: ast.Constant) -> Any:
        return node.value

    def _name(self, node: ast.Name) -> Any:
        if node.id in self.names:
            return self.names[node.id]
        if node.id in ("True", "False", "None"):
            return {"True": True, "False": False, "None": None}[node.id]
        raise EvalError(f"name '{node.id}' is not defined")

    def _boolop(self, node: ast.BoolOp) -> Any:
        result: Any = None
        for value in node.values:
            result = self.visit(value)
            if isinstance(node.op, ast.And) and not result:
                return result
            if isinstance(node.op, ast.Or) and result:
                return result
        return result

    def _binop(self, node: ast.BinOp) -> Any:
        left, right = self.visit(node.left), self.visit(node.right)
        if isinstance(node.op, ast.Pow) and isinstance(right, int | float) and abs(right) > _MAX_POW:
            raise EvalError(f"exponent {right} too large")
        if isinstance(node.op, ast.Mult):
            for seq, count in ((left, right), (right, left)):
                if isinstance(seq, str | list | tuple) and isinstance(count, int) and len(seq) * count > _MAX_LEN:
                    raise EvalError("result too large")
        if isinstance(node.op, ast.Mod) and isinstance(left, str):
            # printf-style formatting can pad to any width ('%999999999s').
            raise EvalError(f"string formatting in '{ast.unparse(node)}' is not allowed in $(eval)")
        op = _BINOPS.get(type(node.op))
        if op is None:
            raise EvalError(f"operator in '{ast.unparse(node)}' is not allowed in $(eval)")
        return op(left, right)

    def _unaryop(self, node: ast.UnaryOp) -> Any:
        value = self.visit(node.operand)
        if isinstance(node.op, ast.Not):
            return not value
        if isinstance(node.op, ast.USub):
            return -value
        if isinstance(node.op, ast.UAdd):
            return +value
        raise EvalError(f"operator in '{ast.unparse(node)}' is not allowed in $(eval)")

    def _compare(self, node: ast.Compare) -> Any:
        left = self.visit(node.left)
        for op, comp in zip(node.ops, node.comparators, strict=True):
            right = self.visit(comp)
            if not _CMPOPS[type(op)](left, right):
                return False
            left = right
        return True

    def _ifexp(self, node: ast.IfExp) -> Any:
        return self.visit(node.body) if self.visit(node.test) else self.visit(node.orelse)

    def _attribute(self, node: ast.Attribute) -> Any:
        # Only constants and functions of the math module (ROS 2's $(eval) offers math).
        target = self.visit(node.value)
        if target is math and not node.attr.startswith("_"):
            return getattr(math, node.attr)
        raise EvalError(f"attribute '{ast.unparse(node)}' is not allowed in $(eval)")

    def _list(self, node: ast.List) -> Any:
        return [self.visit(e) for e in node.elts]

    def _tuple(self, node: ast.Tuple) -> Any:
        return tuple(self.visit(e) for e in node.elts)

    def _subscript(self, node: ast.Subscript) -> Any:
        return self.visit(node.value)[self.visit(node.slice)]

    def _slice(self, node: ast.Slice) -> Any:
        parts = (node.lower, node.upper, node.step)
        return slice(*(None if p is None else self.visit(p) for p in parts))

    def _call(self, node: ast.Call) -> Any:
        if node.keywords:
            raise EvalError(f"keyword arguments are not allowed in $(eval): '{ast.unparse(node)}'")
        args = [self.visit(a) for a in node.args]
        func = node.func
        if isinstance(func, ast.Name):
            if func.id not in self.functions:
                raise EvalError(f"function '{func.id}' is not available in $(eval)")
            return self.functions[func.id](*args)
        if isinstance(func, ast.Attribute):
            target = self.visit(func.value)
            if isinstance(target, str) and func.attr in _STR_METHODS:
                _check_method_size(target, func.attr, args)
                return getattr(target, func.attr)(*args)
            if target is math and not func.attr.startswith("_"):
                return getattr(math, func.attr)(*args)
        raise EvalError(f"call '{ast.unparse(node)}' is not allowed in $(eval)")


def _check_method_size(target: str, method: str, args: list[Any]) -> None:
    # Bound the result before computing it: replace and join can multiply their inputs' sizes.
    size = 0
    if method == "replace" and len(args) >= 2 and isinstance(args[1], str):
        size = len(target) * max(1, len(args[1]))
    elif method == "join" and args and isinstance(args[0], list | tuple):
        size = sum(len(str(x)) for x in args[0]) + len(target) * len(args[0])
    if size > _MAX_LEN:
        raise EvalError("result too large")


def _bounded(value: Any) -> Any:
    if isinstance(value, str | list | tuple) and len(value) > _MAX_LEN:
        raise EvalError("result too large")
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 4096:
        raise EvalError("result too large")
    return value
