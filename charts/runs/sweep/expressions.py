"""The safe arithmetic of mass patterns: numbers, parameter names and ``+ - * / **``.

An expression such as ``"1/m"`` is parsed with :mod:`ast` and only those nodes are allowed,
so a sweep file can never run code.  :func:`expression_symbols` validates an expression
and names the parameters it uses; :func:`evaluate_expression` computes it.
"""
from __future__ import annotations

import ast
import math
import operator

__all__ = ["ExpressionError", "expression_symbols", "evaluate_expression", "ALLOWED"]

#: What an expression may contain (the wording of every error message).
ALLOWED = "numbers, parameter names, + - * / **"

_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
        ast.Div: operator.truediv, ast.Pow: operator.pow, ast.USub: operator.neg,
        ast.UAdd: operator.pos}


class ExpressionError(ValueError):
    """An expression outside the allowed arithmetic; the message quotes it."""


def expression_symbols(expr: str) -> set:
    """The names used by ``expr``; :class:`ExpressionError` if it is not allowed arithmetic."""
    try:
        tree = ast.parse(expr, mode="eval")
    except SyntaxError:
        raise ExpressionError(f"{expr!r} is not an arithmetic expression ({ALLOWED})") from None
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            names.add(node.id)
        elif not isinstance(node, (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Constant,
                                   ast.Load, *_OPS)):
            raise ExpressionError(f"{expr!r} uses {type(node).__name__}; allowed: {ALLOWED}")
    return names


def evaluate_expression(expr: str, env: dict) -> float:
    """The value of a validated expression, its names taken from ``env``;
    :class:`ExpressionError` quoting it when the arithmetic fails (division by zero, a
    result too large, complex or not finite)."""
    try:
        value = _evaluate(ast.parse(expr, mode="eval"), env)
    except (ZeroDivisionError, OverflowError, TypeError, ValueError) as exc:
        raise ExpressionError(f"{expr!r} cannot be computed with {_values(expr, env)}: "
                              f"{exc}") from None
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ExpressionError(f"{expr!r} is {value!r} with {_values(expr, env)}: "
                              "not a finite real number")
    return float(value)


def _values(expr: str, env: dict) -> str:
    names = sorted(expression_symbols(expr))
    return ", ".join(f"{k}={env.get(k)!r}" for k in names) or "no parameters"


def _evaluate(tree, env: dict):
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.Name):
            return float(env[node.id])
        if isinstance(node, ast.BinOp):
            return _OPS[type(node.op)](ev(node.left), ev(node.right))
        return _OPS[type(node.op)](ev(node.operand))
    return ev(tree)
