"""Access to the chart kernels of one N: generated (SymPy) or structured, plain and compiled.

``chart_module(n, paper)`` imports ``charts.generated.rotor_n{n}`` (the family
Σ aᵢ cos θᵢ = c; with ``paper``, ``rotor_n{n}_paper``, its member a = 1, c = 0 specialised
before code generation), shipped for N = 3..6, or for 7 <= N <= ``MAX_N`` derives it on demand
through ``charts.codegen.cache``.  ``compiled(n, paper)`` returns the same functions compiled
with ``numba.njit(cache=True)`` and numpy's error model.  The generated modules import
nothing but ``math``: the loader makes their kernels (``KERNEL_FUNCTIONS``) numba functions
inlined where called, so that compiled code (the other generated functions,
``charts.flows.chart``) inlines them.
``geometry(n, weights, level)`` is what the library uses: the compiled generated functions
for the shipped N (``GENERATED_N``; the paper's module for weights all 1 and level 0, so the
paper's numbers keep their bits), the structured ones (``charts.geometry.structured``, one
compilation for every N and every member) otherwise.
All take the same arguments, ``(q, ..., m, a, c, out)`` with local masses m and weights a
and the level c, and agree to rounding (tests/test_structured.py).
"""
from __future__ import annotations

import hashlib
import numbers
from functools import cache
from types import SimpleNamespace

import numba
import numpy as np
from numba.core.dispatcher import Dispatcher

from ..jit import njit

from ..codegen.names import GENERATED_FUNCTIONS, SHIPPED_N, module_name
from ..codegen.shipped import import_shipped

__all__ = ["chart_module", "module_digest", "compiled", "geometry", "source", "is_paper",
           "GENERATED_N", "MAX_N"]

#: Largest N whose generated module can be derived on demand (tests compare it with the
#: structured kernels; ``RotorSystem`` no longer needs it).
MAX_N = 10
#: N served by the generated code in ``geometry``: the shipped modules, compiled once and
#: cached like the structured kernels.  For N = 7..10 the derivation (SymPy) and compilation of
#: the generated module take 30–120 s in every process, the structured kernels none.
GENERATED_N = SHIPPED_N


def source(n: int) -> str:
    """'generated' or 'structured': where ``geometry(n)`` takes its functions from."""
    return "generated" if n in GENERATED_N else "structured"


def is_paper(weights=None, level=0.0) -> bool:
    """True for the paper's constraint Σ cos θᵢ = 0: weights None or all 1, level 0."""
    return (weights is None or bool(np.all(np.asarray(weights) == 1.0))) and level == 0.0


@cache
def chart_module(n: int, paper: bool = False):
    """The generated module for N rotors (canonical chart eliminating θ_{N−1}): the family,
    or with ``paper`` its member a = 1, c = 0; its kernels registered with numba."""
    if n in SHIPPED_N:
        mod = import_shipped(module_name(n, bool(paper)))
    elif 3 <= n <= MAX_N:
        from ..codegen.cache import load_or_generate

        mod = load_or_generate(n, bool(paper))
    else:
        raise ValueError(f"N={n} is not supported: generated geometry exists for 3 <= N <= {MAX_N}")
    for name in KERNEL_FUNCTIONS:
        # numba functions inlined at numba-IR level where called, as the hand-written kernels
        # are: by the module's own wrappers and by the chart right-hand side
        # (``charts.flows.chart``).  (Made callable by ``register_jitable`` instead, an
        # @overload, numba compiled each in full once more just to type a call: 0.96 + 0.62 s
        # of a new N's 3.1 s of chart code at N = 6.)
        fn = getattr(mod, name)
        if not isinstance(fn, Dispatcher):
            setattr(mod, name, numba.njit(inline="always")(fn))
    return mod


def module_digest(mod) -> str:
    """SHA-256 of a generated module's source file: what its compiled callers' on-disk caches
    are keyed by (``charts.flows.chart.chart_rates``)."""
    with open(mod.__file__, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


#: Generated functions called inside numba kernels (``charts.flows.chart``): always compiled.
KERNEL_FUNCTIONS = ("geodesic_acceleration_sc", "transport_rate_sc")
#: A generated function called only from Python is left to CPython when its source is longer
#: than this: LLVM's compile time grows superlinearly with straight-line code (N = 7 Riemann,
#: 1585 lines when every entry was stored as an N-d index: 277 s to compile, 0.44 ms per call
#: in CPython; stored through a flat view with the zeros filled, 829 lines and 2.3 s), while
#: every function of the shipped N <= 6 (at most 454 lines) stays compiled.
JIT_MAX_LINES = 1000


def _lines(fn) -> int:
    import inspect
    return len(inspect.getsource(fn).splitlines())


@cache
def compiled(n: int, paper: bool = False) -> SimpleNamespace:
    """numba-compiled versions of the generated functions for N rotors (``paper``: of the
    paper's module; plain Python for the long ones that no kernel calls, see
    ``JIT_MAX_LINES``)."""
    mod = chart_module(n, paper)
    out = {}
    for name in GENERATED_FUNCTIONS:
        fn = getattr(mod, name)
        fn = getattr(fn, "py_func", fn)           # the kernels: compiled here on their own too
        jit = name in KERNEL_FUNCTIONS or _lines(fn) <= JIT_MAX_LINES
        # the divisors (masses, D, G, sin²θₖ) are positive wherever a chart is used: the
        # public entry points check the chart's domain first (``RotorSystem._in_chart``)
        # or the result (``exact_curvatures``).  Without Python's zero-division checks the
        # kernels' arrays need no reference counting (one branch per division kept 8 atomic
        # operations per call), and the long functions compile in two thirds of the time
        # (N = 6 Riemann: 13 s against 19 s; the same bits).  (numba's disk cache does not
        # key on the error model: a cache written before keeps raising at a zero divisor.)
        out[name] = njit(cache=True, error_model="numpy")(fn) if jit else fn
    return SimpleNamespace(**out)


def geometry(n: int, weights=None, level=0.0) -> SimpleNamespace:
    """The compiled chart functions used for N rotors on Σ ``weights``ᵢ cos θᵢ = ``level``
    (see ``source``; the paper's module for weights None or all 1 and level 0), with the
    names of ``charts.codegen.names.GENERATED_FUNCTIONS`` and the arguments of the generated
    ones."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 3:
        raise ValueError(f"n must be an integer >= 3, got {n!r}")
    return _geometry(int(n), is_paper(weights, level))


@cache
def _geometry(n: int, paper: bool) -> SimpleNamespace:
    if source(n) == "generated":
        return compiled(n, paper)
    from . import structured

    return SimpleNamespace(**{name: getattr(structured, name) for name in structured.FUNCTIONS})
