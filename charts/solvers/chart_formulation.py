"""Intrinsic formulation: the geodesic equation (14) and parallel transport (16) in charts.

Chart ``k`` (of N) eliminates θₖ; its local coordinates are q = θ without θₖ, and the
sign ``branch`` = ±1 of sin θₖ selects one of the two sheets (atlas: N charts × 2
branches).  State ``y = (q, v, p¹, …, pᵏ)``, shape ((1 + 1 + k)·(N − 1),):

    q̇ᵃ = vᵃ,   v̇ᵃ = −Γᵃ_bc vᵇ vᶜ   (eq 14),   ṗᵃ = −Γᵃ_bc vᵇ pᶜ   (eq 16)

with Γ from the chart kernels (``charts.flows.chart``: generated for the shipped N, structured
otherwise; canonical chart; chart k is the canonical one after moving θₖ last, which is why
the local masses are ``(m without mₖ, mₖ)``).

On the family Σ aᵢ cos θᵢ = c every |sin θᵢ| below is the weighted |aᵢ sin θᵢ| (the
components of ∇F; the paper's a = 1 gives the same numbers).

Switching (:func:`switch_rule`, one home with ``RotorSystem.best_chart``'s argmax;
:func:`leave_chart` on ambient values): after every accepted step the chart is left when
|sin θₖ| < τ · maxᵢ |sin θᵢ| for the chart with the largest |sin θᵢ| (ties: lowest index).
The new chart has ratio 1 ≥ τ, so the rule cannot flip back at once (hysteresis by
construction); the metric condition number in chart k is 1 + Σ_{α≠k} m_k sin²θ_α /
(m_α sin²θₖ) ≤ 1 + (N − 1)·max(m)/(τ² min(m)) at step boundaries; see docs/integrators.md
for the choice of τ = :data:`DEFAULT_TAU`.  The point, velocity and transported vectors go through their
ambient representation (θₖ = atan2(branch·√D / aₖ, −C / aₖ), D = aₖ² − C²,
C = Σ a_α cos q_α − c, ``charts.geometry.atlas.eliminated_angle``; uₖ = −Σ v_α a_α sin q_α /
(aₖ sin θₖ));
the switch happens at the step's end time and integration resumes from exactly there with
the same step-size controller state.  Every switch is logged as (t, from, to).

Parameters: ``par = (N, local masses (N), local weights (N), level, masses (N), weights (N),
offset of θₖ, τ, speed, project, cap fraction, work area (6(N − 1)))`` (the first 2 + 2N and
the work area are those of ``charts.flows.chart.rates``: the hooks below share its σ, κ of
the point through ``point_sincos`` and ``start_sincos``), ``ipar = (N, k vectors, chart, branch, switches logged)``.  ``offset`` is
the multiple of 2π that keeps the reconstructed θₖ continuous with the ambient angle.
"""
from __future__ import annotations

import math
from functools import cache

import numpy as np
from ..jit import njit

from ..flows.chart import HEAD_FIELDS, WORK, chart_rates, point_sincos, start_sincos, structured_rates, work_area
from ..jit.packed import layout, pack, put, value, view
from ..geometry.atlas import ambient_index, best_sine, eliminated_angle_sc, eliminated_component_sc
from ..geometry.projection import invariant_terms, rescale_speed
from .rk import NO_REFCOUNT, RHS_SIG
from .loop import (CAP_SIG, INV_SIG, OUT_SIG, POST_CHANGED, POST_LOG_FULL, POST_OK, POST_SIG,
                   Formulation)
from .status import CHART_MIN_RATIO, DOMAIN, DOMAIN_CAP_FRACTION, step_cap

__all__ = ["ChartFlow", "leave_chart", "switch_rule", "should_leave", "DEFAULT_TAU", "chart_condition_bound"]

#: Default switching threshold τ (docs/integrators.md, "Switching threshold"): τ ≥ 0.9 keeps
#: cond(g) ≤ 6 and the chart within a few times the ambient error; 0.9, 0.95 and 0.99 are
#: equivalent within that sweep's scatter, and 0.9 leaves a 10 % hysteresis margin.
DEFAULT_TAU = 0.9

#: The layout of ``par`` (``charts.jit.packed.layout``): the head that ``charts.flows.chart.rates``
#: reads (``HEAD_FIELDS``: N, the chart's local masses and weights, the level), the system's
#: masses and weights
#: in ambient order, the offset of θₖ, τ, the speed, the project flag, the cap fraction and
#: the work area of ``charts.flows.chart.point_sincos`` (6(N − 1), at the end).
PAR = layout(*HEAD_FIELDS, ("system_masses", 1, 0), ("system_weights", 1, 0), ("offset", 0, 1),
             ("tau", 0, 1), ("speed", 0, 1), ("project", 0, 1), ("cap", 0, 1),
             ("work", WORK, -WORK))
_LM, _LW, _LEVEL, _MASSES, _WEIGHTS = (PAR[k] for k in ("masses", "weights", "level",
                                                        "system_masses", "system_weights"))
_OFFSET, _TAU, _SPEED, _PROJECT, _CAP, _WORK = (PAR[k] for k in ("offset", "tau", "speed",
                                                                 "project", "cap", "work"))
#: ``ipar``: N, the number of transported vectors, the chart, its branch, switches logged.
I_N, I_VECTORS, I_CHART, I_BRANCH, I_LOGGED = range(5)


@njit(cache=True)
def should_leave(sin_k_abs, sin_max, tau):
    """The switching test: True when |sin θₖ| < τ·maxᵢ |sin θᵢ|."""
    return sin_k_abs < tau * sin_max


@njit(cache=True, inline="always")
def switch_rule(s_local, s_k, k, tau):
    """The switching rule, the one that runs (``_post``) and the one tested: (j, smax), j the
    chart to switch to from chart ``k`` or −1 to stay, smax = maxᵢ |aᵢ sin θᵢ|.

    ``s_local`` : aᵢ sin θᵢ of the local coordinates of chart k (local order), shape (N − 1,);
    ``s_k`` : aₖ sin θₖ of the eliminated rotor (signs are ignored).  Leave when
    :func:`should_leave` for the argmax ``charts.geometry.atlas.best_sine`` (lowest index on
    ties).  Pure: allocates nothing."""
    j, smax = best_sine(s_local, s_k, k)
    if should_leave(abs(s_k), smax, tau):
        return j, smax
    return np.int64(-1), smax   # not the literal: enter_chart would compile once more for it


@njit(cache=True)
def leave_chart(sin_abs, k, tau):
    """The chart to switch to from chart ``k``, or −1 to stay: :func:`switch_rule` on the
    ambient ``sin_abs`` = |aᵢ sin θᵢ| (weights a; the paper's |sin θᵢ|), shape (N,)."""
    n = sin_abs.size
    s_local = np.empty(n - 1)
    for a in range(n - 1):
        s_local[a] = sin_abs[ambient_index(a, k)]
    return switch_rule(s_local, sin_abs[k], k, tau)[0]


def chart_condition_bound(n, tau, masses=None):
    """Bound 1 + (N − 1)·max(m)/(τ² min(m)) on the 2-norm condition number of g in the chart
    in use, at step boundaries (where the rule is applied).  Inside the step that crosses the
    threshold |sin θₖ| can fall further, by at most the domain step cap (``charts.solvers.loop``)."""
    m = np.ones(n) if masses is None else np.asarray(masses, float)
    return 1.0 + (n - 1) * m.max() / (tau * tau * m.min())


@njit(cache=True, inline="always")
def _sin_k(wc, par, n, branch):
    """(cos θₖ, sin θₖ, D = (aₖ sin θₖ)²) of the chart point with κ = wc
    (``eliminated_angle_sc``)."""
    return eliminated_angle_sc(wc, n - 1, view(par, n, _LW), value(par, n, _LEVEL), branch)


@njit(cache=True, inline="always")
def _to_ambient_impl(y, par, ipar, row):
    n = ipar[I_N]
    d = n - 1
    nv = ipar[I_VECTORS]
    k = ipar[I_CHART]
    ws, wc = point_sincos(y, par, d)
    ck, sk, _ = _sin_k(wc, par, n, ipar[I_BRANCH])
    row[k] = math.atan2(sk, ck) + value(par, n, _OFFSET)
    w = view(par, n, _LW)
    for b in range(1 + nv):  # velocity and transported vectors
        row[(1 + b) * n + k] = eliminated_component_sc(ws, y, (1 + b) * d, d, w, sk)
    for a in range(d):
        i = ambient_index(a, k)
        row[i] = y[a]
        for b in range(1 + nv):
            row[(1 + b) * n + i] = y[(1 + b) * d + a]
    if value(par, n, _PROJECT) != 0.0:  # samples from the dense output get the energy too
        rescale_speed(row, n, n, view(par, n, _MASSES), value(par, n, _SPEED))
    return 0.0


def _to_ambient(y, par, ipar, row):
    return _to_ambient_impl(y, par, ipar, row)


@njit(cache=True)
def enter_chart(row, n, nv, j, masses, weights, y, par, ipar):
    """Chart ``j`` representation of the ambient ``row`` = (θ, u, p¹…pᵏ): fills ``y``,
    the local masses and weights and θⱼ offset in ``par``, and chart/branch in ``ipar``."""
    d = n - 1
    thj = row[j]
    sj = math.sin(thj)
    ipar[I_CHART] = j
    ipar[I_BRANCH] = 1 if sj >= 0.0 else -1
    put(par, n, _OFFSET, thj - math.atan2(sj, math.cos(thj)))
    lm, lw = view(par, n, _LM), view(par, n, _LW)
    for a in range(d):
        i = ambient_index(a, j)
        lm[a] = masses[i]
        lw[a] = weights[i]
        for b in range(2 + nv):
            y[b * d + a] = row[b * n + i]
    lm[d] = masses[j]
    lw[d] = weights[j]
    work = view(par, n, _WORK)
    for a in range(work.size):  # the work area: no point evaluated yet
        work[a] = np.nan


def _post(y, par, ipar, t, log):
    n = ipar[I_N]
    d = n - 1
    k = ipar[I_CHART]
    ws, wc = start_sincos(y, par, d)      # the next step's start
    _, sk, s2 = _sin_k(wc, par, n, ipar[I_BRANCH])
    if not s2 > 0.0:  # the step ended outside the chart (|C| >= aₖ): no θₖ, no uₖ
        return DOMAIN
    w = view(par, n, _LW)
    code = POST_OK
    if value(par, n, _PROJECT) != 0.0:  # rescale v to the initial speed (energy)
        lm = view(par, n, _LM)
        E = lm[d] * eliminated_component_sc(ws, y, d, d, w, sk) ** 2
        for a in range(d):
            E += lm[a] * y[d + a] ** 2
        f = value(par, n, _SPEED) / math.sqrt(E)
        for a in range(d):
            y[d + a] *= f
        code = POST_CHANGED
    gk = w[d] * sk
    j, smax = switch_rule(ws, gk, k, value(par, n, _TAU))
    if j < 0:
        if abs(gk) < CHART_MIN_RATIO * smax:  # kept (no switch) up to its edge: stop
            return DOMAIN
        return code
    nv = ipar[I_VECTORS]
    row = np.empty((2 + nv) * n)  # allocation only at a switch, never per step
    _to_ambient_impl(y, par, ipar, row)
    enter_chart(row, n, nv, j, view(par, n, _MASSES), view(par, n, _WEIGHTS), y, par, ipar)
    c = ipar[I_LOGGED]
    log[c, 0] = t
    log[c, 1] = k
    log[c, 2] = j
    ipar[I_LOGGED] = c + 1
    return POST_LOG_FULL if c + 1 >= log.shape[0] else POST_CHANGED


def _cap(y, par, ipar):
    n = ipar[I_N]
    d = n - 1
    ws, wc = start_sincos(y, par, d)      # the step's start
    _, sk, s2 = _sin_k(wc, par, n, ipar[I_BRANCH])
    if s2 <= 0.0:
        return 0.0
    w = view(par, n, _LW)
    S = s2
    U = eliminated_component_sc(ws, y, d, d, w, sk) ** 2
    for a in range(d):
        S += ws[a] ** 2
        U += y[d + a] ** 2
    if U == 0.0:
        return np.inf
    return min(step_cap(S, U, value(par, n, _CAP)), DOMAIN_CAP_FRACTION * abs(sk) / math.sqrt(U))


def _invariants(y, par, ipar, inv):
    """(F, G, E) of the ambient state of y from the point's σ, κ (no libm: the step's end is
    the next step's start, `start_sincos`) and θₖ, uₖ as `_to_ambient_impl` reconstructs them
    (F and G vanish by construction, to rounding; E is the one the chart does not keep)."""
    n = ipar[I_N]
    d = n - 1
    ws, wc = point_sincos(y, par, d)
    ck, sk, _ = _sin_k(wc, par, n, ipar[I_BRANCH])
    w = view(par, n, _LW)
    lm = view(par, n, _LM)
    uk = eliminated_component_sc(ws, y, d, d, w, sk)
    F, G, E = invariant_terms(w[d] * sk, w[d] * ck, uk, lm[d])
    F -= value(par, n, _LEVEL)
    for a in range(d):
        f, g, e = invariant_terms(ws[a], wc[a], y[d + a], lm[a])
        F += f
        G += g
        E += e
    inv[0], inv[1], inv[2] = F, G, E
    return 0.0


def chart_rhs(n: int, paper: bool = False, transport: bool = True):
    """Eqs (14) + (16) for N = ``n`` (``charts.flows.chart``), compiled for the loop and
    cached on disk: the structured right-hand side once for every N, a generated one per N,
    per module (``paper``: the paper's Σ cos θ = 0, else the family) and with eq (16) or
    without it (``transport``: ``charts.flows.chart.chart_rates``)."""
    return _chart_rhs(int(n), bool(paper), bool(transport))   # one entry however it is called


@cache
def _chart_rhs(n, paper, transport):
    rates = chart_rates(n, paper, transport)
    if rates is structured_rates:
        return _structured_rhs()
    return njit(RHS_SIG, cache=True, error_model="numpy")(rates)


@cache
def _structured_rhs():
    return njit(RHS_SIG, cache=True, error_model="numpy")(structured_rates)


@cache
def _common_hooks():
    # (numpy's error model: no zero-division branches, so no reference counting of the
    # views; every divisor is checked nonzero first, or is a weight or a positive norm)
    opts = dict(cache=True, error_model="numpy")
    # (and, but for ``post``, which allocates at a switch, without reference counting)
    fast = dict(opts, **NO_REFCOUNT)
    return (njit(CAP_SIG, **fast)(_cap), njit(POST_SIG, **opts)(_post),
            njit(OUT_SIG, **fast)(_to_ambient), njit(INV_SIG, **fast)(_invariants))


class ChartFlow(Formulation):
    """Eqs (14) + (16) in the atlas of N charts × 2 branches, switching by :func:`leave_chart`."""

    name = "chart"

    def __init__(self, system, *, project: bool, tau: float = DEFAULT_TAU, chart=None, **kw):
        super().__init__(system, project=project, **kw)
        if not (isinstance(tau, (int, float, np.floating)) and 0.0 < tau < 1.0):
            raise ValueError(f"tau must be a number in (0, 1) (hysteresis needs tau < 1), got {tau!r}")
        self.tau = float(tau)
        if chart is not None and (isinstance(chart, bool) or not isinstance(chart, (int, np.integer))
                                  or not 0 <= chart < self.n):
            raise ValueError(f"chart must be None or an integer in 0..{self.n - 1}, got {chart!r}")
        self.chart = chart

    def hooks(self, method, vectors):
        rhs = chart_rhs(self.n, self.system.is_paper_family, transport=vectors > 0)
        return (rhs, None) + _common_hooks()

    def initial(self, theta, u, P):
        n = self.n
        sys = self.system
        k = sys.best_chart(theta) if self.chart is None else int(self.chart)
        nv = P.shape[0]
        row = np.concatenate([theta, u, P.ravel()])
        y = np.empty((2 + nv) * (n - 1))
        par = pack(PAR, n, n=n, level=sys.level, system_masses=sys.masses,
                   system_weights=sys.weights, tau=self.tau, speed=float(sys.speed(u)),
                   project=float(self.project), cap=self.cap_fraction, work=work_area(n))
        ipar = np.array([n, nv, 0, 1, 0], dtype=np.int64)   # I_N, I_VECTORS, I_CHART, I_BRANCH, I_LOGGED
        self.initial_switches = []
        j = leave_chart(np.abs(sys.weights * np.sin(theta)), k, self.tau)
        if j >= 0:  # a requested chart that the rule would leave: switch at t = 0
            self.initial_switches.append((0.0, k, j))
            k = j
        enter_chart(row, n, nv, k, sys.masses.copy(), sys.weights.copy(), y, par, ipar)
        return y, par, ipar

    def drain_log(self, log, ipar):
        recs = [(float(log[i, 0]), int(log[i, 1]), int(log[i, 2])) for i in range(ipar[I_LOGGED])]
        ipar[I_LOGGED] = 0
        return recs
