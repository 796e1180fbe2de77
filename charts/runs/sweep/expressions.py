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
#: Longest expression accepted (a mass pattern is a few terms; Python's parser recurses
#: once per operator and would fail at a few thousand).
MAX_LENGTH = 500

_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
        ast.Div: operator.truediv, ast.Pow: operator.pow, ast.USub: operator.neg,
        ast.UAdd: operator.pos}


class ExpressionError(ValueError):
    """An expression outside the allowed arithmetic; the message quotes it."""


def expression_symbols(expr: str) -> set:
    """The names used by ``expr``; :class:`ExpressionError` if it is not allowed arithmetic."""
    tree = _parse(expr)
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
        value = _evaluate(_parse(expr), env)
    except (ZeroDivisionError, OverflowError, TypeError, ValueError) as exc:
        raise ExpressionError(f"{expr!r} cannot be computed with {_values(expr, env)}: "
                              f"{exc}") from None
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ExpressionError(f"{expr!r} is {value!r} with {_values(expr, env)}: "
                              "not a finite real number")
    return float(value)


def _parse(expr: str) -> ast.Expression:
    if not isinstance(expr, str):
        raise ExpressionError(f"an expression is a string, got {type(expr).__name__}")
    if len(expr) > MAX_LENGTH:
        raise ExpressionError(f"{expr[:40]!r}… has {len(expr)} characters; an expression may "
                              f"have at most {MAX_LENGTH}")
    try:
        return ast.parse(expr, mode="eval")
    except (SyntaxError, RecursionError, MemoryError):
        raise ExpressionError(f"{expr[:60]!r} is not an arithmetic expression "
                              f"({ALLOWED})") from None


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
