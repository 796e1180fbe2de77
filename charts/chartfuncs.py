"""Access to the generated chart kernels of one N, plain and numba-compiled.

``chart_module(n)`` imports ``charts.generated.rotor_n{n}`` (shipped for N = 3..6)
or, for other N, derives it on demand through ``charts.ondemand``.
``compiled(n)`` returns the same functions compiled with ``numba.njit(cache=True)``.
"""
from __future__ import annotations

import importlib
from functools import cache
from types import SimpleNamespace

import numba

from .layout import GENERATED_FUNCTIONS, SHIPPED_N, module_name

__all__ = ["chart_module", "compiled"]

MAX_N = 10


@cache
def chart_module(n: int):
    """The generated module for N rotors (canonical chart eliminating θ_{N−1})."""
    if n in SHIPPED_N:
        return importlib.import_module(f"charts.generated.{module_name(n)}")
    if not 3 <= n <= MAX_N:
        raise ValueError(f"N={n} is not supported: generated geometry exists for 3 <= N <= {MAX_N}")
    from .ondemand import load_or_generate

    return load_or_generate(n)


@cache
def compiled(n: int) -> SimpleNamespace:
    """numba-compiled versions of the generated functions for N rotors."""
    mod = chart_module(n)
    return SimpleNamespace(**{name: numba.njit(cache=True)(getattr(mod, name))
                              for name in GENERATED_FUNCTIONS})
