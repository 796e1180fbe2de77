"""Access to the generated chart kernels of one N, plain and numba-compiled.

``chart_module(n)`` imports ``charts.generated.rotor_n{n}`` (shipped for N = 3..6)
or, for other N, derives it on demand through ``charts.codegen.cache``.
``compiled(n)`` returns the same functions compiled with ``numba.njit(cache=True)``.
"""
from __future__ import annotations

import importlib
from functools import cache
from types import SimpleNamespace

import numba

from ..codegen.names import GENERATED_FUNCTIONS, SHIPPED_N, module_name

__all__ = ["chart_module", "compiled"]

MAX_N = 10


@cache
def chart_module(n: int):
    """The generated module for N rotors (canonical chart eliminating θ_{N−1})."""
    if n in SHIPPED_N:
        return importlib.import_module(f"charts.generated.{module_name(n)}")
    if not 3 <= n <= MAX_N:
        raise ValueError(f"N={n} is not supported: generated geometry exists for 3 <= N <= {MAX_N}")
    from ..codegen.cache import load_or_generate

    return load_or_generate(n)


#: Generated functions called inside numba kernels (``charts.flows.chart``): always compiled.
KERNEL_FUNCTIONS = ("geodesic_acceleration", "transport_rate")
#: A generated function called only from Python is left to CPython when its source is longer
#: than this: LLVM's compile time grows superlinearly with straight-line code (N = 7 Riemann,
#: 1585 lines: 277 s to compile, 0.44 ms per call in CPython), while every function of the
#: shipped N <= 6 (at most 934 lines) stays compiled as before.
JIT_MAX_LINES = 1000


def _lines(fn) -> int:
    import inspect
    return len(inspect.getsource(fn).splitlines())


@cache
def compiled(n: int) -> SimpleNamespace:
    """numba-compiled versions of the generated functions for N rotors (plain Python for
    the long ones that no kernel calls, see ``JIT_MAX_LINES``)."""
    mod = chart_module(n)
    out = {}
    for name in GENERATED_FUNCTIONS:
        fn = getattr(mod, name)
        jit = name in KERNEL_FUNCTIONS or _lines(fn) <= JIT_MAX_LINES
        out[name] = numba.njit(cache=True)(fn) if jit else fn
    return SimpleNamespace(**out)
