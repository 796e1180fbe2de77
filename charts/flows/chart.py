"""The intrinsic equations in a chart: the geodesic equation (14) and parallel transport
(16), with Γ from the chart kernels of ``charts.geometry.kernels.geometry`` (generated for the
shipped N, structured otherwise).

Chart k's state is y = (q, v, p¹, …, pᵏ), shape ((2 + k)·(N − 1),):

    q̇ᵃ = vᵃ,   v̇ᵃ = −Γᵃ_bc vᵇ vᶜ   (eq 14),   ṗᵃ = −Γᵃ_bc vᵇ pᶜ   (eq 16)

Chart k is the canonical chart with θₖ moved last (``charts.geometry.atlas``), so one
compiled function per N (per kernel source) serves every chart and every member of the family
Σ aᵢ cos θᵢ = c: ``par`` begins with (N, local masses (N), local weights (N), level c) and ends
with a work area of 6(N − 1) floats (`local_parameters`, `WORK`): the last point q whose
σ = a sin q, κ = a cos q were evaluated and those σ, κ, and the same for the step's start
point.  `point_sincos` evaluates them once per point (libm at a step's start, `start_sincos`;
the angle-addition shift from there at the points inside the step), and the kernels' ``_sc``
variants, the health test and the loop's hooks (``charts.solvers.chart_formulation``) share
them.  The equations are written once, in `rates`, which
takes the two kernel functions as arguments; the structured kernels need no N, so their
right-hand side (`structured_rates`) is one function for every N, compiled once and cached on
disk.
"""
from __future__ import annotations

import math
from functools import cache
from types import FunctionType

import numpy as np
from ..jit import njit

from ..geometry import structured
from ..geometry.atlas import eliminated_angle_sc, local_masses, local_weights
from ..geometry.kernels import chart_module, module_digest, source
from ..geometry.primitives import SHIFT_MAX, shifted
from ..jit.packed import layout, value, view

__all__ = ["rates", "chart_rates", "structured_rates", "no_transport", "local_parameters", "point_sincos",
           "start_sincos", "work_area", "WORK", "HEAD", "HEAD_FIELDS"]

#: Floats per local coordinate of the work area at the end of ``par``: the last point q
#: evaluated and its σ, κ, then the step's start point q₀ and its σ₀, κ₀ (`point_sincos`).
WORK = 6
#: The head of ``par`` that `rates` reads (``charts.jit.packed.layout``): N, the chart's local
#: masses and weights (the eliminated rotor's last), the level; every ``par`` of a chart
#: begins with it (`local_parameters`, ``charts.solvers.chart_formulation.PAR``) and ends with
#: the work area.
HEAD_FIELDS = (("n", 0, 1), ("masses", 1, 0), ("weights", 1, 0), ("level", 0, 1))
HEAD = layout(*HEAD_FIELDS)
_N, _MASSES, _WEIGHTS, _LEVEL = (HEAD[k] for k in ("n", "masses", "weights", "level"))


def work_area(n: int) -> np.ndarray:
    """A fresh work area for N = ``n``: no point evaluated yet (NaN never equals a q)."""
    return np.full(WORK * (n - 1), np.nan)


def local_parameters(masses, weights, level, k: int) -> np.ndarray:
    """``par`` for `rates` in chart ``k``: (N, local masses, local weights, level, work area)."""
    n = len(masses)
    return np.concatenate([[n], local_masses(masses, k), local_weights(weights, k), [level],
                           work_area(n)])


@njit(cache=True, inline="always")
def _same_point(y, par, o, d):
    """True when q = y[:d] is the point stored at ``par[o:o + d]``."""
    same = True
    for a in range(d):
        same = same and par[o + a] == y[a]
    return same


@njit(cache=True, inline="always")
def point_sincos(y, par, d):
    """(σ, κ) = (w sin q, w cos q) of the chart point q = y[:d], local weights w = par[2+d:],
    as views of the work area at the end of ``par``, evaluated only when q is not the point
    they were last evaluated at.  Inside a step (the RK4 stages, DOP853's stages and dense
    samples) they are the step's start point's σ₀, κ₀ (`start_sincos`) shifted by
    δ = q − q₀ with the angle-addition formula (``charts.geometry.primitives.shifted``: exact
    to rounding for |δ| ≤ `SHIFT_MAX`, libm beyond it), as the tangent kernel's stages are."""
    o = par.size - WORK * d
    if not _same_point(y, par, o, d):
        b = o + 3 * d                      # the step's start point (NaN: none yet)
        for a in range(d):
            par[o + a] = y[a]
            dl = y[a] - par[b + a]
            if abs(dl) <= SHIFT_MAX:
                par[o + d + a], par[o + 2 * d + a] = shifted(par[b + d + a], par[b + 2 * d + a], dl)
            else:
                par[o + d + a] = par[2 + d + a] * math.sin(y[a])
                par[o + 2 * d + a] = par[2 + d + a] * math.cos(y[a])
    return par[o + d:o + 2 * d], par[o + 2 * d:o + 3 * d]


@njit(cache=True, inline="always")
def start_sincos(y, par, d):
    """`point_sincos` at a step's start point q = y[:d] (the loop's ``cap`` and ``post``
    hooks): libm, and q becomes the point that the step's later points shift from.  So the
    σ, κ of every point depend only on the step it belongs to, not on earlier steps (a run
    resumed at a step boundary continues bit for bit)."""
    o = par.size - WORK * d
    b = o + 3 * d
    if not _same_point(y, par, b, d):
        for a in range(d):
            sa = par[2 + d + a] * math.sin(y[a])
            ca = par[2 + d + a] * math.cos(y[a])
            par[o + a] = y[a]
            par[o + d + a] = sa
            par[o + 2 * d + a] = ca
            par[b + a] = y[a]
            par[b + d + a] = sa
            par[b + 2 * d + a] = ca
    return point_sincos(y, par, d)


@njit(cache=True, inline="always")
def rates(y, par, dy, ga, tr):
    """Eqs (14) + (16) at y into dy with the kernels ``ga`` (geodesic_acceleration_sc) and
    ``tr`` (transport_rate_sc) of the chart whose local masses and weights are
    ``par[1:1+N]``, ``par[1+N:1+2N]``, level ``par[1+2N]``, N = ``par[0]`` (σ, κ from
    `point_sincos`).  Returns S = Σ aᵢ² sin²θᵢ (as the ambient formulation), or −1 outside
    the chart (|C| >= aₖ, ``charts.geometry.atlas.eliminated_angle_sc``)."""
    n = int(value(par, 0, _N))   # (N comes first: its offset is 0)
    d = n - 1
    nv = (y.size - 2 * d) // d
    m = view(par, n, _MASSES)
    w = view(par, n, _WEIGHTS)
    c = value(par, n, _LEVEL)
    ws, wc = point_sincos(y, par, d)
    _, _, s2 = eliminated_angle_sc(wc, d, w, c, 1.0)
    health = -1.0
    if s2 > 0.0:  # (one exit: the views are released in one place, see rk.rk4_point)
        S = 0.0
        for a in range(d):
            S += ws[a] ** 2
        health = S + s2
        v = y[d:2 * d]
        ga(ws, wc, v, m, w, c, dy[d:2 * d])
        for a in range(d):
            dy[a] = y[d + a]
        for r in range(nv):
            o = (2 + r) * d
            tr(ws, wc, v, y[o:o + d], m, w, c, dy[o:o + d])
    else:
        for i in range(y.size):
            dy[i] = 0.0
    return health


def structured_rates(y, par, dy):
    """`rates` with the structured kernels: any N, one compilation (the caller's signature)."""
    return rates(y, par, dy, structured.geodesic_acceleration_sc, structured.transport_rate_sc)


@njit(cache=True, inline="always")
def no_transport(ws, wc, v, p, m, a, c, out):
    """The transport kernel of a right-hand side that carries no vectors (`chart_rates` with
    ``transport=False``): never called by a state without vectors; NaN in every rate of a
    vector, should one be given, which the loop's invariant monitor stops at."""
    for i in range(out.size):
        out[i] = math.nan


#: The generated kernels of one `_bound_rates` function: none here; each bound function reads
#: its own from its copy of this module's globals.
_ga = _tr = None


def _bound_rates(module, digest, transport):
    """`rates` bound to a generated module's kernels (``module`` as
    ``charts.geometry.kernels.chart_module`` gives it: its kernels numba functions inlined
    where called; the caller's signature), with `no_transport` for its transport kernel
    unless ``transport``.  numba caches a closure on disk under a key that hashes its cells:
    here only ``key`` = (``digest``, ``transport``), ``digest`` the module's source hash
    (``charts.geometry.kernels.module_digest``), so a regenerated module is compiled afresh
    and each module and variant has its own entry.  The kernels reach the function as its
    globals (``_ga``, ``_tr`` in a copy of this module's), not as cells: a numba function
    pickles differently in every process, and would make every process compile afresh."""
    key = (digest, bool(transport))

    def generated_rates(y, par, dy):
        key  # noqa: B018 - a cell of the closure, so a part of numba's cache key
        return rates(y, par, dy, _ga, _tr)

    names = dict(globals(), _ga=module.geodesic_acceleration_sc,
                 _tr=module.transport_rate_sc if transport else no_transport)
    return FunctionType(generated_rates.__code__, names, generated_rates.__name__, None,
                        generated_rates.__closure__)


@cache
def chart_rates(n: int, paper: bool = False, transport: bool = True):
    """The right-hand side ``rhs(y, par, dy) -> health`` of eqs (14) + (16) for N = ``n``
    (any chart and member: ``par`` selects them), to be compiled by the caller with its
    signature: `structured_rates` unless N's kernels are generated, else `rates` bound to the
    kernels of the generated module (``paper``: the paper's module,
    ``charts.geometry.kernels.chart_module``) — without eq (16) unless ``transport``: a run
    that transports no vector does not compile it (at N = 6, a third of a new N's
    compilation).  Both compilations are cached on disk, and `rates` inlines the kernels
    into them; the structured one, compiled once for every N, always has eq (16)."""
    if source(n) == "structured":
        return structured_rates
    mod = chart_module(n, paper)
    return _bound_rates(mod, module_digest(mod), transport)
