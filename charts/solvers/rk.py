"""Explicit Runge–Kutta steppers, numba-compiled and generic over the right-hand side.

Every right-hand side used with these steppers has the signature ``f(y, par, dy) -> health``
(:data:`RHS_SIG`): it writes dy/dt for the state ``y``, shape (n,), into ``dy``, shape (n,),
reads its parameters from the float array ``par`` and returns a scalar *health* that the
formulations use to flag trouble (distance² to a singular point, or < 0 outside a chart).
The steppers return the smallest health seen over their stages.

* :func:`rk4_stages` — the one body of the classical fourth-order method (the paper's
  integrator), each driver's layout in its hooks; :func:`rk4_step` — it for a right-hand side.
* :func:`dop853_step`, :func:`dop853_dense`, :func:`dense_eval`, :func:`initial_step`,
  :func:`step_factor` — the adaptive eighth-order method DOP853 of Hairer, Nørsett & Wanner
  with its 5th/3rd-order blended error estimate and 7th-order dense output, exactly as in
  SciPy's ``scipy/integrate/_ivp/rk.py::DOP853``.

All steppers write into caller-given work arrays and allocate nothing.

The DOP853 coefficients are in ``charts.solvers.dop853_coefficients`` (a verbatim copy of
SciPy's).
"""
from __future__ import annotations

import math

import numpy as np
from numba import types
from ..jit import njit
from numba.core.cpu import CPUTargetOptions

from .dop853_coefficients import A, B, D, E3, E5, INTERPOLATOR_POWER, N_STAGES, N_STAGES_EXTENDED

__all__ = [
    "NO_REFCOUNT",
    "RHS_SIG", "RHS_TYPE", "RK4_NODES", "RK4_WEIGHTS", "rk4_node", "rk4_point", "stage_point",
    "rk4_sum",
    "rk4_combine", "rk4_stages",
    "rk4_step", "dop853_step", "dop853_dense", "hermite_dense", "dense_eval", "initial_step", "step_factor",
    "N_STAGES", "N_STAGES_EXTENDED", "INTERPOLATOR_POWER",
]

#: Signature of every right-hand side: ``health = f(y, par, dy)``.
RHS_SIG = types.float64(types.float64[::1], types.float64[::1], types.float64[::1])
#: numba first-class function type of a right-hand side (lets drivers be cached).
RHS_TYPE = types.FunctionType(RHS_SIG)

#: numba options for a kernel compiled without the runtime's reference counting (numba's
#: ``_nrt`` target option; none where a numba version lacks it): each array view and each
#: call with arrays otherwise costs an atomic increment/decrement pair, ≈ 8 % of a chart
#: RK4 step (docs/performance.md).  Only for kernels that neither allocate nor return an
#: array (numba refuses to compile an allocation without it), whose arrays all belong to
#: their caller.
NO_REFCOUNT = {"_nrt": False} if hasattr(CPUTargetOptions, "_nrt") else {}

#: Step-size controller constants, as in SciPy's ``rk.py``.
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: The error estimate of DOP853 is of order 7, so the step scales as err^(-1/8).
ERROR_EXPONENT = -1.0 / 8.0


#: The classical RK4 tableau (the paper's integrator): stage nodes and weights.
RK4_NODES = (0.0, 0.5, 0.5, 1.0)
RK4_WEIGHTS = (1.0 / 6.0, 2.0 / 6.0, 2.0 / 6.0, 1.0 / 6.0)


@njit(cache=True, inline="always")
def rk4_node(st):
    """``RK4_NODES[st]`` as arithmetic (a run-time index into a tuple is slow in Numba)."""
    return 0.0 if st == 0 else (0.5 if st < 3 else 1.0)


@njit(cache=True, inline="always")
def rk4_point(z, K, o, a, L, zt):
    """The point of an RK4 stage: zt = z + a·K[o:o+L] with a = c_st·h and o the offset of the
    previous stage in K (stage 0's point is z itself).  Branch-free: inlined into the hot
    kernels, a branch here would keep Numba's reference counting in their loops
    (docs/performance.md).  Offsets may be unsigned (no negative-index wraparound)."""
    for i in range(L):
        zt[i] = stage_point(z[i], a, K[o + i])


@njit(cache=True, inline="always")
def stage_point(z, a, k):
    """One element of `rk4_point`: z + a·k."""
    return z + a * k


@njit(cache=True, inline="always")
def rk4_sum(z, h6, k0, k1, k2, k3):
    """One element of `rk4_combine`: z + h6·(k₀ + 2k₁ + 2k₂ + k₃), h6 = h/6."""
    return z + h6 * (k0 + 2.0 * k1 + 2.0 * k2 + k3)


@njit(cache=True, inline="always")
def rk4_combine(z, K, h, L, out):
    """out = z + h/6·(K₀ + 2K₁ + 2K₂ + K₃) (the weights `RK4_WEIGHTS`; out may be z: in
    place); K flat, stage j at offset j·L."""
    h6 = RK4_WEIGHTS[0] * h
    L2 = L + L
    L3 = L2 + L
    for i in range(L):
        out[i] = rk4_sum(z[i], h6, K[i], K[L + i], K[L2 + i], K[L3 + i])


@njit(cache=True, inline="always")
def rk4_stages(work, eqs, h, start, point, rate, combine):
    """The one body of a classical RK4 step of size h (`RK4_NODES`, `RK4_WEIGHTS`): every
    RK4 step of charts is this loop with its driver's hooks for its layout (compile-time
    arguments, inlined: each driver compiles the loop with its own hooks):

    * ``start(work, eqs) -> (health, first)``: the step's start; first = 1 where it computed
      the rates of stage 0 at the start point itself, 0 where ``point`` makes stage 0's
      point (a copy: the rates then compile once, not twice);
    * ``point(work, st, a)``: the point of stage st, z + a·K_{st−1} with a = c_st·h
      (`rk4_point`, or its lanes' form);
    * ``rate(work, eqs, st, hmin) -> hmin``: the rates of stage st at that point, and the
      smallest health so far (numba's ``min`` does not compile for the GPU: the stacked
      flows' hooks keep none);
    * ``combine(work, h)``: the new point from the four stages (`rk4_combine`).

    ``work``: the driver's arrays and sizes (a tuple); ``eqs``: its equations (a right-hand
    side, or a vectors' hook), handed to ``start`` and ``rate``.  Returns the smallest
    health.  Stage 0 in ``start`` keeps the loop free of a branch on the stage: with counted
    arrays one kept an atomic reference-count pair per array and stage (178 of the 209 ns of
    a chart step with a trivial right-hand side, N = 5; docs/performance.md); the stacked
    flows, whose arrays are borrowed, branch in ``point`` instead.  The drivers: `rk4_step` (a
    right-hand side), ``charts.solvers.tangent.stacked_rk4_step`` (every stacked flow, CPU
    and GPU), the lanes' step of ``charts.solvers.lanes``, the frame steps of
    ``charts.analyses.curvature`` and a mechanism's tangent flow
    (``charts.mechanism.tangent_flow``)."""
    hmin, first = start(work, eqs)
    for st in range(first, 4):
        point(work, st, rk4_node(st) * h)
        hmin = rate(work, eqs, st, hmin)
    combine(work, h)
    return hmin


@njit(cache=True, inline="always")
def _rhs_start(work, f):
    """`rk4_stages`' stage 0 for a right-hand side ``f``: f(y) into K[0]."""
    y, par, K, Kf, ytmp, ynew, n = work
    return f(y, par, K[0]), 1


@njit(cache=True, inline="always")
def _rhs_point(work, st, a):
    """`rk4_stages`' stage point for a right-hand side: ytmp = y + a·K[st − 1]."""
    y, par, K, Kf, ytmp, ynew, n = work
    rk4_point(y, Kf, np.uint64(st - 1) * n, a, n, ytmp)


@njit(cache=True, inline="always")
def _rhs_rate(work, f, st, hmin):
    """`rk4_stages`' stage rate for a right-hand side ``f``: f(ytmp) into K[st]."""
    y, par, K, Kf, ytmp, ynew, n = work
    return min(hmin, f(ytmp, par, K[st]))


@njit(cache=True, inline="always")
def _rhs_combine(work, h):
    """`rk4_stages`' end for a right-hand side: ynew from y and the stages."""
    y, par, K, Kf, ytmp, ynew, n = work
    rk4_combine(y, Kf, h, n, ynew)


@njit(cache=True, **NO_REFCOUNT)
def rk4_step(f, y, h, par, K, ytmp, ynew):
    """One classical RK4 step of size ``h`` from ``y``, shape (n,), into ``ynew``: the one
    body `rk4_stages` with the right-hand side ``f`` (`RHS_SIG`).

    ``K`` : work array, shape (≥ 4, n), C-contiguous; ``ytmp`` : work array, shape (n,).
    Returns the smallest health over the four stages."""
    work = (y, par, K, K.reshape(K.size), ytmp, ynew, np.uint64(y.size))
    return rk4_stages(work, f, h, _rhs_start, _rhs_point, _rhs_rate, _rhs_combine)


@njit(cache=True)
def _stage(f, y, h, par, K, s, ytmp):
    n = y.size
    for i in range(n):
        acc = 0.0
        for j in range(s):
            a = A[s, j]
            if a != 0.0:
                acc += a * K[j, i]
        ytmp[i] = y[i] + h * acc
    return f(ytmp, par, K[s])


@njit(cache=True)
def dop853_step(f, y, h, par, K, ytmp, ynew, rtol, atol):
    """One DOP853 step attempt of size ``h`` from ``y``, shape (n,).

    On entry ``K[0]`` must hold f(y); ``K`` has shape (16, n) (the 12 stages, f(ynew) in
    row 12, and room for the 3 dense-output stages).  Writes the 8th-order solution into
    ``ynew`` and f(ynew) into ``K[12]``.  Returns ``(err, health)``: the scaled RMS error
    norm of SciPy's DOP853 (accept when err < 1) and the smallest stage health."""
    n = y.size
    hmin = 1e300
    for s in range(1, N_STAGES):
        hmin = min(hmin, _stage(f, y, h, par, K, s, ytmp))
    for i in range(n):
        acc = 0.0
        for j in range(N_STAGES):
            acc += B[j] * K[j, i]
        ynew[i] = y[i] + h * acc
    hmin = min(hmin, f(ynew, par, K[N_STAGES]))
    e5 = 0.0
    e3 = 0.0
    for i in range(n):
        a5 = 0.0
        a3 = 0.0
        for j in range(N_STAGES + 1):
            a5 += E5[j] * K[j, i]
            a3 += E3[j] * K[j, i]
        sc = atol + max(abs(y[i]), abs(ynew[i])) * rtol
        e5 += (a5 / sc) ** 2
        e3 += (a3 / sc) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return 0.0, hmin
    err = abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)
    return err, hmin


@njit(cache=True)
def step_factor(err, rejected):
    """Step-size multiplier after an attempt with error norm ``err`` (SciPy's rule)."""
    if err < 1.0:
        if err == 0.0:
            fac = MAX_FACTOR
        else:
            fac = min(MAX_FACTOR, SAFETY * err ** ERROR_EXPONENT)
        if rejected:
            fac = min(1.0, fac)
        return fac
    return max(MIN_FACTOR, SAFETY * err ** ERROR_EXPONENT)


@njit(cache=True)
def dop853_dense(f, y, ynew, h, par, K, ytmp, F):
    """Coefficients of the 7th-order DOP853 interpolant of the last accepted step.

    ``K`` : the stages of that step, shape (16, n) (rows 13–15 are filled here);
    ``F`` : output, shape (7, n).  Use with :func:`dense_eval`."""
    n = y.size
    for s in range(N_STAGES + 1, N_STAGES_EXTENDED):
        _stage(f, y, h, par, K, s, ytmp)
    _hermite_rows(y, ynew, h, K[0], K[N_STAGES], F)
    for i in range(n):
        for r in range(INTERPOLATOR_POWER - 3):
            acc = 0.0
            for j in range(N_STAGES_EXTENDED):
                acc += D[r, j] * K[j, i]
            F[3 + r, i] = h * acc


@njit(cache=True, inline="always")
def _hermite_rows(y, ynew, h, f0, f1, F):
    """Rows 0–2 of the interpolant coefficients: with the other rows zero, :func:`dense_eval`
    is the cubic Hermite interpolant of (y, f0) and (ynew, f1) over the step h."""
    for i in range(y.size):
        dy = ynew[i] - y[i]
        F[0, i] = dy
        F[1, i] = h * f0[i] - dy
        F[2, i] = 2.0 * dy - h * (f1[i] + f0[i])


@njit(cache=True)
def hermite_dense(y, ynew, h, f0, f1, F):
    """Coefficients (``F``, shape (7, n), for :func:`dense_eval`) of the cubic Hermite
    interpolant of a step from ``y`` to ``ynew`` of size h with slopes f0 = f(y), f1 = f(ynew):
    third order, the dense output of the RK4 routes."""
    _hermite_rows(y, ynew, h, f0, f1, F)
    for r in range(3, INTERPOLATOR_POWER):
        for i in range(y.size):
            F[r, i] = 0.0


@njit(cache=True)
def dense_eval(F, y, x, out):
    """Evaluate the DOP853 interpolant at fraction ``x`` ∈ [0, 1] of the step into ``out``."""
    n = y.size
    for i in range(n):
        acc = 0.0
        for r in range(INTERPOLATOR_POWER - 1, -1, -1):
            acc += F[r, i]
            if (INTERPOLATOR_POWER - 1 - r) % 2 == 0:
                acc *= x
            else:
                acc *= 1.0 - x
        out[i] = y[i] + acc


@njit(cache=True)
def initial_step(f, y, f0, par, interval, hmax, rtol, atol, ytmp, f1):
    """First step size (Hairer, Nørsett & Wanner, Sec. II.4; SciPy ``select_initial_step``)
    for an error estimator of order 7.  ``f0`` = f(y); ``ytmp``, ``f1`` : work, shape (n,)."""
    n = y.size
    d0 = 0.0
    d1 = 0.0
    for i in range(n):
        sc = atol + abs(y[i]) * rtol
        d0 += (y[i] / sc) ** 2
        d1 += (f0[i] / sc) ** 2
    d0 = math.sqrt(d0 / n)
    d1 = math.sqrt(d1 / n)
    if d0 < 1e-5 or d1 < 1e-5:
        h0 = 1e-6
    else:
        h0 = 0.01 * d0 / d1
    h0 = min(h0, interval, hmax)
    for i in range(n):
        ytmp[i] = y[i] + h0 * f0[i]
    f(ytmp, par, f1)
    d2 = 0.0
    for i in range(n):
        sc = atol + abs(y[i]) * rtol
        d2 += ((f1[i] - f0[i]) / sc) ** 2
    d2 = math.sqrt(d2 / n) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, interval, hmax)
