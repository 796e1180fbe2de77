"""The integration loop shared by both formulations, compiled once and driven in chunks.

A *formulation* (``charts.solvers.ambient_formulation``, ``charts.solvers.chart_formulation``) supplies six compiled
hooks; the loop here supplies everything else (time, step-size control, output at the
requested times, invariant monitoring, counters, status codes).  The contract:

``rhs(y, par, dy) -> health``  (:data:`charts.solvers.rk.RHS_SIG`)
    Time derivative of the formulation's state ``y``, shape (ny,).  ``health`` is
    S = Σᵢ sin²θᵢ at the point (S → 0 only at the N = 4 singular points), or a negative
    number if ``y`` is outside the domain of the formulation's coordinates.
``step(rhs, y, h, dt, par, K, ytmp, ynew) -> health``  (:data:`STEP_SIG`), or None
    One RK4 step of size ``h`` (``dt``: the nominal step; h differs from it when the step
    lands on an output time) from ``y`` into ``ynew`` (``y`` unchanged; ``K`` (16, ny),
    ``ytmp`` (ny,) work), returning the smallest health it saw.  None: the generic step,
    `charts.solvers.rk.rk4_step` of ``rhs``, compiled into the loop (:data:`drive`); a
    formulation may supply its own (the ambient one: the tangent kernel's step, bit for bit).
``cap(y, par, ipar) -> hmax``  (:data:`CAP_SIG`)
    Largest step the formulation accepts from ``y`` (resolution of the geometry near
    singular points and chart boundaries; see ``charts.solvers.status``).
``post(y, par, ipar, t, log) -> code``  (:data:`POST_SIG`)
    Called after every accepted step, may change ``y`` in place (projection, chart switch)
    and append rows to ``log``, shape (capacity, 3).  Returns :data:`POST_OK`,
    :data:`POST_CHANGED` (``y`` changed: the loop re-evaluates ``rhs``), :data:`POST_LOG_FULL`
    (changed, and the log must be drained before continuing) or a negative status.
``to_ambient(y, par, ipar, row) -> 0.0``  (:data:`OUT_SIG`)
    Ambient representation ``row = (θ, u, p¹, …, pᵏ)``, shape ((2 + k)·n,), of ``y``.
``invariants(y, par, ipar, inv) -> 0.0``  (:data:`INV_SIG`)
    ``inv`` = (F, G, E) = (Σ aᵢ cos θᵢ − c, Σ uᵢ aᵢ sin θᵢ, ½ Σ mᵢ uᵢ²) of the ambient state
    that ``y`` represents (eqs 9, 10 and the energy), from the sin/cos the formulation
    already holds for ``y`` where it has them.

All loop state lives in one record of named fields (`LOOP_STATE`), so that a chunk can stop
and resume exactly.

numba's disk cache of :func:`drive` is keyed by this file's time stamp only, while the
steppers of ``charts.solvers.rk`` are compiled into it: a change there reaches a cached
``drive`` only with a change of this file (or a fresh cache).
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import from_dtype, types
from ..jit import njit

from .status import (CAP_FRACTION, DOMAIN, FINISHED, LOG_FULL, NONFINITE, OUT_FULL, RUNNING,
                     SINGULAR, UNDERFLOW)
from .rk import (INTERPOLATOR_POWER, NO_REFCOUNT, RHS_TYPE, MIN_FACTOR, dense_eval, dop853_dense,
                 dop853_step, hermite_dense, initial_step, rk4_step, step_factor)

__all__ = ["CAP_SIG", "POST_SIG", "OUT_SIG", "INV_SIG", "STEP_SIG", "drive", "new_state", "LOOP_STATE", "Output", "Work", "monitor", "Formulation",
           "segment_layout", "dense_sample",
           "POST_OK", "POST_CHANGED", "POST_LOG_FULL", "METHOD_RK4", "METHOD_DOP853"]

_f8 = types.float64
_i8 = types.int64
_v = types.float64[::1]
_iv = types.int64[::1]
_m = types.float64[:, ::1]

CAP_SIG = _f8(_v, _v, _iv)
POST_SIG = _i8(_v, _v, _iv, _f8, _m)
OUT_SIG = _f8(_v, _v, _iv, _v)
INV_SIG = _f8(_v, _v, _iv, _v)
STEP_SIG = _f8(RHS_TYPE, _v, _f8, _f8, _v, _m, _v, _v)

#: The loop's state between chunks, one record of named fields (`new_state`): time, step
#: (DOP853's next trial; −1: choose one), the run's end, nominal step and tolerances, the
#: energy at the start, the singular-point threshold, the health at the state; the method,
#: samples written, the next sample time's index, whether there are sample times, the
#: status, accepted steps, rejected attempts, right-hand-side evaluations, steps per chunk,
#: whether the state's slope must be evaluated afresh, dense output, segments written.
LOOP_STATE = np.dtype([(name, np.float64) for name in (
    "t", "h", "t_final", "dt", "rtol", "atol", "e0", "s_sing", "health")] + [
    (name, np.int64) for name in (
    "method", "nout", "ieval", "use_eval", "status", "nsteps", "nrej", "nrhs", "chunk",
    "fresh", "dense", "nseg")])
_state = types.Array(from_dtype(LOOP_STATE), 1, "C")

METHOD_RK4, METHOD_DOP853 = 0, 1

POST_OK, POST_CHANGED, POST_LOG_FULL = 0, 1, 3


def new_state(method: int, t_final: float, dt: float, rtol: float, atol: float, e0: float,
              s_sing: float, use_eval: bool, chunk_steps: int, dense: bool = False):
    """A fresh loop state (`LOOP_STATE`, an array of one record) for :func:`drive` at
    t = 0.  ``dense``: record every step's interpolant (see :func:`segment_layout`)."""
    state = np.zeros(1, dtype=LOOP_STATE)
    for name, value in dict(t_final=t_final, dt=dt, rtol=rtol, atol=atol, e0=e0,
                            s_sing=s_sing, health=1.0, h=-1.0,     # h: DOP853 chooses it
                            method=method, use_eval=use_eval, chunk=chunk_steps, fresh=1,
                            dense=dense).items():
        state[name] = value
    return state


def segment_layout(ny: int, npar: int):
    """Columns of a row of the segment buffer ``Seg`` written by :func:`drive` when dense
    output is on: ``(t, h, y (ny), F (INTERPOLATOR_POWER·ny, row-major), par (npar))`` — the
    step's start time and size, the formulation state at its start, the coefficients of its
    interpolant (:func:`charts.solvers.rk.dense_eval`) and the formulation's parameters during
    the step; the int parameters go to the same row of ``ISeg``.  Returns the slices
    ``(y, F, par)`` and the row width."""
    y = slice(2, 2 + ny)
    F = slice(y.stop, y.stop + INTERPOLATOR_POWER * ny)
    par = slice(F.stop, F.stop + npar)
    return y, F, par, par.stop


@njit(cache=True)
def monitor(inv, e0, mon):
    """Update ``mon`` = running max of |F|, |G|, |ΔE|/E₀ with the invariants ``inv`` = (F, G,
    E) of a state (the ``invariants`` hook); False if they are not finite."""
    F, G, E = inv[0], inv[1], inv[2]
    dE = abs(E - e0) / e0
    if not (math.isfinite(F) and math.isfinite(G) and math.isfinite(E)):
        return False
    mon[0] = max(mon[0], abs(F))
    mon[1] = max(mon[1], abs(G))
    mon[2] = max(mon[2], dE)
    return True


@njit(cache=True)
def _record_segment(row, irow, t, h, y, F, par, ipar):
    """Write one step's interpolant into a row of the segment buffers (``segment_layout``)."""
    ny = y.size
    row[0] = t
    row[1] = h
    for i in range(ny):
        row[2 + i] = y[i]
    o = 2 + ny
    for j in range(INTERPOLATOR_POWER):
        for i in range(ny):
            row[o + j * ny + i] = F[j, i]
    o += INTERPOLATOR_POWER * ny
    for i in range(par.size):
        row[o + i] = par[i]
    for i in range(ipar.size):
        irow[i] = ipar[i]


def _drive(rhs, step, cap, post, to_ambient, invariants, y, par, ipar, loop_state, out, work):
    """Advance ``y`` from ``state.t`` towards ``state.t_final`` for at most ``state.chunk``
    accepted steps, ``state`` the one record of ``loop_state`` (`LOOP_STATE`).  Writes ambient samples (rows of ``Y_out``, times in ``T_out``) at the
    times ``t_eval`` (if ``state.use_eval``; ``Y_out`` then has a row for every one of
    them) or after every step (until ``Y_out`` is full).  Returns the status code, also
    stored in ``state.status``.  With ``state.dense``, every accepted step also writes a row
    of ``Seg``/``ISeg`` (:func:`segment_layout`): DOP853's own 7th-order interpolant, or for
    RK4 the cubic Hermite interpolant of the step's end values and slopes (one more
    right-hand-side evaluation a step); ``OUT_FULL`` when the buffer is full.

    ``out`` (`Output`) and ``work`` (`Work`): y (ny,); K (16, ny); F (7, ny); ytmp, ynew
    (ny,); Y_out (cap, na); inv (3,); mon (3,) = running max of |Σcos θ|, |Σ u sin θ|, |ΔE|/E₀ over accepted steps."""
    state = loop_state[0]
    t_eval, T_out, Y_out, log, mon, Seg, ISeg = out
    K, F, ytmp, ynew, inv = work
    ny = y.size
    method = state.method
    use_eval = state.use_eval != 0
    dense = state.dense != 0
    ne = t_eval.size
    t = state.t
    t_final = state.t_final
    s_sing = state.s_sing
    rtol = state.rtol
    atol = state.atol
    status = RUNNING
    steps = 0
    while True:
        if t >= t_final:
            status = FINISHED
            break
        if steps >= state.chunk:
            break
        if not use_eval and state.nout >= Y_out.shape[0]:
            status = OUT_FULL
            break
        if dense and state.nseg >= Seg.shape[0]:
            status = OUT_FULL
            break
        hcap = cap(y, par, ipar)
        if hcap < 10.0 * (np.nextafter(t, np.inf) - t):
            # the formulation allows no step: at a chart boundary that the switching rule
            # does not leave (steps shrink geometrically towards it), or outside the chart
            status = DOMAIN
            break
        t_next = t_final
        if use_eval and state.ieval < ne:
            t_next = min(t_next, t_eval[state.ieval])
        if method == METHOD_RK4:
            h = min(state.dt, hcap)
            if h * (1.0 + 1e-9) >= t_next - t:  # land exactly; no sliver step from t += h rounding
                h = t_next - t
                t_new = t_next
            else:
                t_new = t + h
            if step is None:  # (pruned at compile time: two specialisations, `drive`)
                hs = rk4_step(rhs, y, h, par, K, ytmp, ynew)
            else:
                hs = step(rhs, y, h, state.dt, par, K, ytmp, ynew)
            state.nrhs += 4
            if hs < 0.0:
                status = DOMAIN
                break
            if hs < s_sing:
                status = SINGULAR
                break
            if dense:  # cubic Hermite from f(y) = K[0] and f(ynew)
                rhs(ynew, par, K[12])
                state.nrhs += 1
                hermite_dense(y, ynew, h, K[0], K[12], F)
        else:
            if state.fresh != 0:
                state.health = rhs(y, par, K[0])
                state.nrhs += 1
                state.fresh = 0
            if state.health < s_sing:
                status = SINGULAR if state.health >= 0.0 else DOMAIN
                break
            if state.h <= 0.0:
                state.h = initial_step(rhs, y, K[0], par, t_final - t, hcap, rtol, atol,
                                       ytmp, K[1])
                state.nrhs += 1
            h = min(state.h, hcap)
            rejected = False
            status = RUNNING
            while True:
                min_step = 10.0 * (np.nextafter(t, np.inf) - t)
                if h < min_step:
                    status = UNDERFLOW
                    break
                if t + h >= t_final:
                    t_new = t_final
                    h = t_final - t
                else:
                    t_new = t + h
                err, hs = dop853_step(rhs, y, h, par, K, ytmp, ynew, rtol, atol)
                state.nrhs += 12
                if hs < 0.0 or not math.isfinite(err):
                    h *= MIN_FACTOR  # a stage left the chart: shrink and retry
                    rejected = True
                    state.nrej += 1
                    continue
                if hs < s_sing:
                    status = SINGULAR
                    break
                fac = step_factor(err, rejected)
                if err < 1.0:
                    state.h = h * fac
                    break
                h *= fac
                rejected = True
                state.nrej += 1
            if status != RUNNING:
                break
            state.health = hs
            # samples strictly inside the step, from the 7th-order interpolant
            if dense or (use_eval and state.ieval < ne and t_eval[state.ieval] < t_new):
                dop853_dense(rhs, y, ynew, h, par, K, ytmp, F)
                state.nrhs += 3
            if use_eval and state.ieval < ne and t_eval[state.ieval] < t_new:
                while state.ieval < ne and t_eval[state.ieval] < t_new:
                    te = t_eval[state.ieval]
                    dense_eval(F, y, (te - t) / h, ytmp)
                    to_ambient(ytmp, par, ipar, Y_out[state.nout])
                    T_out[state.nout] = te
                    state.nout += 1
                    state.ieval += 1
        if dense:  # the step's interpolant, in the formulation's coordinates of the step
            _record_segment(Seg[state.nseg], ISeg[state.nseg], t, t_new - t, y, F, par, ipar)
            state.nseg += 1
        # accept the step
        for i in range(ny):
            y[i] = ynew[i]
        if method == METHOD_DOP853:
            for i in range(ny):
                K[0, i] = K[12, i]  # first-same-as-last
        t = t_new
        steps += 1
        state.nsteps += 1
        code = post(y, par, ipar, t, log)
        if code < 0:
            status = code
            break
        if code != POST_OK:
            state.fresh = 1
        # samples at the end of the step (after projection / chart switch); the invariants
        # are monitored on the state of the step's end
        if use_eval:
            while state.ieval < ne and t_eval[state.ieval] <= t:
                to_ambient(y, par, ipar, Y_out[state.nout])
                T_out[state.nout] = t_eval[state.ieval]
                state.nout += 1
                state.ieval += 1
        else:
            to_ambient(y, par, ipar, Y_out[state.nout])
            T_out[state.nout] = t
            state.nout += 1
        invariants(y, par, ipar, inv)
        if not monitor(inv, state.e0, mon):
            status = NONFINITE
            break
        if code == POST_LOG_FULL:
            status = LOG_FULL
            break
    state.t = t
    state.status = status
    return status


_STEP_TYPE = types.FunctionType(STEP_SIG)
_CAP_TYPE = types.FunctionType(CAP_SIG)
_POST_TYPE = types.FunctionType(POST_SIG)
_OUT_TYPE = types.FunctionType(OUT_SIG)
_INV_TYPE = types.FunctionType(INV_SIG)
_im = types.int64[:, ::1]
#: The loop's output (`drive`): the sample times asked for, the samples' times and rows, the
#: formulation's log, the invariants' monitor, the dense output's segments (float and int).
Output = namedtuple("Output", ["t_eval", "T", "Y", "log", "mon", "Seg", "ISeg"])
#: The loop's work arrays: the stages K (16, ny), the interpolant F (7, ny), a stage point,
#: the new state, the invariants (3,).
Work = namedtuple("Work", ["K", "F", "ytmp", "ynew", "inv"])
_OUTPUT_TYPE = types.NamedTuple((_v, _v, _m, _m, _v, _m, _im), Output)
_WORK_TYPE = types.NamedTuple((_m, _m, _v, _v, _v), Work)
_DRIVE_ARGS = (_CAP_TYPE, _POST_TYPE, _OUT_TYPE, _INV_TYPE, _v, _v, _iv, _state, _OUTPUT_TYPE,
               _WORK_TYPE)
DRIVE_SIG = _i8(RHS_TYPE, _STEP_TYPE, *_DRIVE_ARGS)
#: `drive` for a formulation whose step is the generic one (step None)
DRIVE_GENERIC_SIG = _i8(RHS_TYPE, types.none, *_DRIVE_ARGS)



class _CompiledOnUse:
    """``fn`` compiled with the signature ``sig`` and numba ``options`` on its first call
    (cached on disk)."""

    def __init__(self, fn, sig, **options):
        self.fn, self.sig, self.options, self.compiled = fn, sig, options, None
        self.__doc__ = f"Compiled :func:`{fn.__name__}` (compiled on first use, cached on disk)."

    def __call__(self, *args):
        if self.compiled is None:
            self.compiled = njit(self.sig, cache=True, **self.options)(self.fn)
        return self.compiled(*args)


class _Drive:
    """`_drive` compiled on first use (cached on disk) in two specialisations: with the
    formulation's ``step`` hook, and for ``step`` None with the generic `rk4_step` compiled
    in (through a hook it costs a chart RK4 step 3 %, N = 5)."""

    def __init__(self):
        self.own = _CompiledOnUse(_drive, DRIVE_SIG, **NO_REFCOUNT)
        self.generic = _CompiledOnUse(_drive, DRIVE_GENERIC_SIG, **NO_REFCOUNT)
        self.__doc__ = self.own.__doc__

    def __call__(self, rhs, step, *args):
        return (self.generic if step is None else self.own)(rhs, step, *args)


drive = _Drive()


def _dense_sample(to_ambient, Seg, ISeg, ny, idx, x, out):
    """Rows ``out[j]`` = ambient state of the interpolant of segment ``idx[j]`` at fraction
    ``x[j]`` of its step (segments as written by :func:`drive`)."""
    ys = 2                                   # the columns of segment_layout
    Fs = ys + ny
    ps = Fs + INTERPOLATOR_POWER * ny
    npar = Seg.shape[1] - ps
    F = np.empty((INTERPOLATOR_POWER, ny))
    y0 = np.empty(ny)
    yx = np.empty(ny)
    par = np.empty(npar)
    for j in range(idx.size):
        r = idx[j]
        for i in range(ny):
            y0[i] = Seg[r, ys + i]
        for k in range(INTERPOLATOR_POWER):
            for i in range(ny):
                F[k, i] = Seg[r, Fs + k * ny + i]
        for i in range(npar):
            par[i] = Seg[r, ps + i]
        dense_eval(F, y0, x[j], yx)
        to_ambient(yx, par, ISeg[r].copy(), out[j])
    return 0


dense_sample = _CompiledOnUse(_dense_sample, _i8(_OUT_TYPE, _m, _im, _i8, _iv, _v, _m))


class Formulation:
    """Base of the formulations driven by :func:`drive`.  A subclass supplies

    * ``hooks(method, vectors)`` → ``(rhs, step, cap, post, to_ambient, invariants)`` (the
      order of :data:`drive`'s arguments) for ``method`` ("rk4" or "dop853") and a state
      with ``vectors`` transported vectors, compiled with
      :data:`charts.solvers.rk.RHS_SIG`, :data:`STEP_SIG`, :data:`CAP_SIG`, :data:`POST_SIG`,
      :data:`OUT_SIG`, :data:`INV_SIG` (see the module docstring; ``step`` is only called by
      RK4, and may be None: the generic step);
    * ``initial(theta, u, P)`` → ``(y, par, ipar)``: the formulation's state, float
      parameters and int parameters for the ambient start (θ, u, transported vectors P,
      shape (k, n)).

    It may override ``drain_log(log, ipar)`` to turn the rows its ``post`` hook wrote into
    records (default: no records), and set ``initial_switches`` in ``initial``.  The run bookkeeping (chunks, outputs, counters, status)
    lives in ``charts.integrate``.
    """

    name = "abstract"

    def __init__(self, system, *, project: bool, cap_fraction: float = CAP_FRACTION["dop853"]):
        self.system = system
        self.n = system.n
        self.project = bool(project)
        self.cap_fraction = float(cap_fraction)

    def hooks(self, method, vectors):  # pragma: no cover - contract
        raise NotImplementedError

    def initial(self, theta, u, P):  # pragma: no cover - contract
        raise NotImplementedError

    initial_switches: list = []

    def drain_log(self, log, ipar):
        """Records for the rows ``post`` appended to ``log`` since the last drain."""
        return []
