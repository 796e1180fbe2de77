"""The tangent kernel: a state y and k tangent vectors X advanced together by RK4 of eqs (8)
and (17), re-orthonormalised by Gram–Schmidt (eq 18), projected onto the invariants.  Every
analysis (Lyapunov spectra, curvature, angles, waveforms) and every scene with ambient RK4
advances this one kernel, through `TangentFlow`.

Phase space.  Eq (8) lives in R^{2N}, the physical phase space is the tangent bundle of the
(N−1)-manifold, and the subspace T_r of perturbations that keep the constraint and the
tangency is invariant under eq (17) (``charts.geometry.projection``).  ``restricted=True``
keeps the vectors in T_r (projected at every re-orthonormalisation).

Inner product of eq (18): ⟨a, b⟩ = Σ wᵢ aᵢ bᵢ with w from `inner_weights`: ``"theta"`` (the
paper's: masses on the θ-parts, 0 on the u-parts), ``"full"`` (masses on both) or
``"euclidean"`` (all 1, the product of the angle test of section 4).

Chunk independence.  Everything that decides the arithmetic of the next step — the stacked
state Z = [y; X], the sin/cos of the current angles and the global step counter (which
fixes the phases of projection and re-orthonormalisation) — lives in `TangentFlow` and
persists between calls, so advancing 1000 steps in one call or in any number of chunks gives
bit-identical numbers.  That makes a scene, resumed or not, equal to the API call it mirrors.
"""
from __future__ import annotations

import os
from collections import namedtuple
from math import cos, gcd, isfinite, sin

import numpy as np
from numba import typeof, types
from ..jit import njit

from ..flows.ambient import multiplier, stage_work, state_rate, tangent_factors, tangent_rate
from ..geometry.energy_shares import record_share
from ..geometry.primitives import LANE_WIDTH, SHIFT_MAX, shifted, sincos
from ..geometry.projection import project_state_into, project_tangent, project_tangent_sc
from .gram_schmidt import inner_term, orthonormal_rows, orthonormalize, orthonormalize_lanes
from .driver import Phases, borrowed, keep_alive, log_sums, phased_loop
from .rk import rk4_combine, rk4_point, rk4_stages
from .status import (CAP_FRACTION, NONFINITE, RUNNING, SINGULAR, status_error,
                     fixed_step_status, next_substep, singular_floor, substep_count,
                     sum_squares)

__all__ = ["TangentFlow", "StackedFlow", "tangent_kernel", "orthonormalize", "orthonormal_rows",
           "inner_weights", "orthonormalize_lanes", "inner_term", "shift_sincos",
           "shift_sincos_lanes", "shifted", "stacked_loop", "stacked_work", "tangent_loop", "stacked_rk4_step", "StackedStep",
           "tangent_vectors_rate", "reorth_steps", "substeps", "substep_loop", "REORTH_TIME", "largest_divisor", "check_memory",
           "memory_budget", "stacked_bytes", "RotorStack", "stacked_step", "stacked_project",
           "stacked_reorth", "stacked_record", "Stack", "Rotors", "Stepping", "Records",
           "tangent_kernel_types"]

#: Time between re-orthonormalisations where an analysis only needs the spans of its vectors
#: at sample points (curvature frames, angles): eq (18) costs O(N·k²) against O(N·k) for a
#: step, so every step would dominate for large k (N = 64, k = 62: 4.8× the cost per time unit).
REORTH_TIME = 0.1

_CAP = CAP_FRACTION["rk4"]
#: Bound of the sub-steps of one capped step (never reached: the loop ends when the step is
#: taken or S is singular; the cap at S = SINGULAR_S is still ≥ 3e-9 per unit speed).
MAX_SUBSTEPS = 1 << 40


@njit(cache=True, inline="always")
def _libm_beyond_shift(dl, theta, n, a, s, c):
    """s, c = a sin, a cos of theta (libm) where |δ| > `SHIFT_MAX` (rare: called only where
    a vectorisable count found such a δ)."""
    for j in range(n):
        if abs(dl[j]) > SHIFT_MAX:
            s[j] = a[j] * sin(theta[j])
            c[j] = a[j] * cos(theta[j])


@njit(cache=True, inline="always")
def shift_sincos(s0, c0, dl, theta, n, a, s, c):
    """s, c = a sin, a cos of θ = θ₀ + δ from s0, c0 = a sin θ₀, a cos θ₀ and δ = dl, shape
    (N,) (`shifted`; libm of theta for |δ| > `SHIFT_MAX`).  s, c may be s0, c0 (in place)."""
    for j in range(n):
        s[j], c[j] = shifted(s0[j], c0[j], dl[j])
    big = 0
    for j in range(n):
        big += abs(dl[j]) > SHIFT_MAX
    if big:
        _libm_beyond_shift(dl, theta, n, a, s, c)


@njit(cache=True, inline="always")
def shift_sincos_lanes(s0, c0, dl, theta, n, a, s, c):
    """`shift_sincos` of n elements in blocks of ``LANE_WIDTH`` (n a multiple of it)."""
    W = LANE_WIDTH
    big = False  # an or, not a count: a vector compare and a mask test per block
    for j0 in range(n - n, n, W):
        for t in range(W):
            s[j0 + t], c[j0 + t] = shifted(s0[j0 + t], c0[j0 + t], dl[j0 + t])
    for j0 in range(n - n, n, W):
        for t in range(W):
            big |= abs(dl[j0 + t]) > SHIFT_MAX
    if big:
        _libm_beyond_shift(dl, theta, n, a, s, c)


#: The arrays and sizes of `stacked_rk4_step`, its hooks' ``work`` (`rk4_stages`).
StackedStep = namedtuple("StackedStep", ["Zf", "Zt", "K", "th", "dl", "s", "c", "w0", "w1", "w2",
                                         "w3", "s0", "c0", "minv", "wts", "n", "R", "d", "L"])


@njit(cache=True, inline="always")
def stacked_rk4_step(Zf, Zt, K, th, dl, s, c, w0, w1, w2, w3, s0, c0, minv, wts, h, n, R, d, L,
                     vectors_rate):
    """One RK4 step of size h (h < 0: backward), in place, of eq (8) for the state Zf[:2N]
    and of a linear flow of the R − 1 vector rows after it (flat, length L = R·d): the one
    body ``charts.solvers.rk.rk4_stages`` with the stacked layout's hooks, the one RK4 step
    of every stacked flow.  The weighted sin/cos s0, c0 of the state's angles are kept
    current (weights wts) by the angle shift from the step's start (`shift_sincos`);
    w0…w3 and the rest are work space.

    ``vectors_rate(Zt, n, minv, s, c, lam, iB, w0, w1, w2, w3, K, o, R, d)`` is the
    formulation's hook: the rates of the R vector rows (stride d, as the hook lays them out)
    after the state at the stage point Zt into K[o:], from the state's multiplier Λ = lam and
    1/B = iB (`tangent_vectors_rate`: eq 17;
    ``charts.analyses.adjoint_pass.adjoint_vectors_rate``: ẇ = −Jᵀw;
    ``charts.solvers.ambient_formulation``: eq 19, which also keeps the stages' smallest
    Σ (a sin θ)² in its work space).  It is a compile-time argument, inlined: each kernel
    compiles the step with its own hook.  (A health returned through the step, unused by the
    tangent kernel, cost it 4 %: 0.124 against 0.119 s, measured.)

    n, R, d, L are unsigned (``np.uint64``), so every flat index here and in the inlined
    equations is unsigned: Numba compiles a negative-index wraparound
    (``i + (i >> 63 & len)``) into every signed array access whose sign LLVM cannot prove,
    i.e. every ``x[o + j]`` with a run-time offset o, which cost a quarter of the step.
    The lane kernel's step (``charts.solvers.lanes``) is the same body in the lanes'
    memory layout."""
    rk4_stages(StackedStep(Zf, Zt, K, th, dl, s, c, w0, w1, w2, w3, s0, c0, minv, wts, n, R, d, L),
               vectors_rate, h, _stacked_start, _stacked_point, _stacked_rate, _stacked_combine)


@njit(cache=True, inline="always")
def _stacked_start(w, vectors_rate):
    """`rk4_stages`' start of `stacked_rk4_step`: the start angles into th; stage 0's point
    is a copy that `_stacked_point` makes (the rates, eq (8) and the hook, then compile once:
    twice, the first call of an analysis took 20 % longer to compile, measured)."""
    Zf, th = w.Zf, w.th
    for j in range(w.n):
        th[j] = Zf[j]
    return 0.0, 0


@njit(cache=True, inline="always")
def _stacked_point(w, st, a):
    """`rk4_stages`' stage point of `stacked_rk4_step`: Zt = Zf + a·K_{st−1} and its
    sin/cos s, c shifted from s0, c0 (`shift_sincos`); copies of Zf, s0, c0 at stage 0,
    outside the branch-free `rk4_point` (an inlined function that branches on the stage
    releases its arrays at different places in its two branches, and Numba's reference-count
    pruning then leaves an atomic incref/decref pair per array and stage in the loop)."""
    Zf, Zt, K, dl, s, c, s0, c0, n, L = w.Zf, w.Zt, w.K, w.dl, w.s, w.c, w.s0, w.c0, w.n, w.L
    if st == 0:
        for i in range(L):
            Zt[i] = Zf[i]
        for j in range(n):
            s[j] = s0[j]
            c[j] = c0[j]
    else:
        op = np.uint64(st - 1) * L      # offset of the previous stage in K
        rk4_point(Zf, K, op, a, L, Zt)
        for j in range(n):
            dl[j] = a * K[op + j]
        shift_sincos(s0, c0, dl, Zt, n, w.wts, s, c)


@njit(cache=True, inline="always")
def _stacked_rate(w, vectors_rate, st, hmin):
    """`rk4_stages`' stage rates of `stacked_rk4_step` at Zt with sin/cos s, c into stage st
    of K: eq (8), then the vectors' hook from the state's multiplier Λ and 1/B."""
    Zt, K, s, c, minv, n = w.Zt, w.K, w.s, w.c, w.minv, w.n
    zero = np.uint64(0)
    o = np.uint64(st) * w.L
    lam, B = multiplier(Zt, zero, n, minv, s, c)
    state_rate(Zt, zero, n, minv, s, lam, K, o)
    iB = 1.0 / B if B > 0.0 else 0.0
    vectors_rate(Zt, n, minv, s, c, lam, iB, w.w0, w.w1, w.w2, w.w3, K, o, w.R, w.d)
    return hmin


@njit(cache=True, inline="always")
def _stacked_combine(w, h):
    """`rk4_stages`' end of `stacked_rk4_step`: Zf from its stages K, and the weighted
    sin/cos s0, c0 shifted from the step's start angles th to the new ones."""
    Zf, th, dl, n = w.Zf, w.th, w.dl, w.n
    rk4_combine(Zf, w.K, h, w.L, Zf)
    for j in range(n):
        dl[j] = Zf[j] - th[j]
    shift_sincos(w.s0, w.c0, dl, Zf, n, w.wts, w.s0, w.c0)


@njit(cache=True, inline="always")
def tangent_vectors_rate(Zt, n, minv, s, c, lam, iB, f, g, p, q, K, o, R, d):
    """Eq (17) for the R − 1 tangent vectors after the state in Zt (rows of d = 2N) into
    K[o + d:], the factors f, g, p, q computed once for all of them (the hook of
    `stacked_rk4_step`)."""
    zero = np.uint64(0)
    tangent_factors(Zt, zero, n, minv, s, c, lam, f, g, p, q)
    for r in range(np.uint64(1), R):
        tangent_rate(Zt, r * d, n, f, g, p, q, iB, K, o + r * d)


@njit(cache=True, inline="always")
def substep_loop(Zf, work, s0, c0, minv, wts, level, dt, hc, nsub, n, nu, Ru, du, Lu,
                 vectors_rate):
    """The step dt (< 0: backward) by `stacked_rk4_step` with the hook ``vectors_rate`` (its
    body ``rk4_stages`` with its hooks, called here directly: each level of inlining re-runs
    numba's passes over everything inlined below it), as the policy of
    ``charts.solvers.status`` takes it: one step where ``nsub`` = 1 (the cap
    ``hc`` at the step's start not below |dt|), else sub-steps (`next_substep`: equal ones as
    planned from the cap, each within its own cap once the point comes closer), each from a
    point that passes the singular-point test (`singular_floor`).  Returns RUNNING, or
    SINGULAR inside a cut step (where its sub-steps reached the singular point).  The one
    home of the sub-step policy: `stacked_step` (every stacked flow) and `substeps` (a lane
    of the lane kernel) call it.  One inlined step in a loop: no second copy of it to
    compile (a separately compiled sub-step function cost every first call 3.7 s of
    compiling, the backward pass's another 3.8 s), and no slower (measured).  ``work``: the
    step's work arrays (`stacked_work`)."""
    Zt, K, th, dl, s, c, f, g, p, q = work
    w = StackedStep(Zf, Zt, K, th, dl, s, c, f, g, p, q, s0, c0, minv, wts, nu, Ru, du, Lu)
    adt = abs(dt)
    h = dt
    planned = 0
    hp = adt
    left = adt
    adaptive = np.bool_(False)      # not the literal: next_substep compiled once
    if nsub > 1:
        planned = substep_count(adt, hc)
        h = dt / planned
        hp = abs(h)
    for sub in range(nsub):
        if nsub > 1:
            S = sum_squares(s0, 0, n)
            if S < singular_floor(c0, wts, n, level):
                return SINGULAR
            hs, adaptive = next_substep(left, S, sum_squares(Zf, n, n), hp, adaptive, _CAP)
            if adaptive:
                h = hs if dt > 0.0 else -hs
        rk4_stages(w, vectors_rate, h, _stacked_start, _stacked_point, _stacked_rate,
                   _stacked_combine)
        left -= abs(h)
        if nsub > 1 and (left <= 0.0 if adaptive else sub + 1 == planned):
            break
    return RUNNING


@njit(cache=True)
def substeps(Zf, work, s0, c0, minv, wts, level, dt, hc, n, R, d, L):
    """The step dt (> 0, capped at hc < dt at its start) of one lane of the lane kernel
    (``charts.solvers.lanes``, in the one-trajectory layout) in the sub-steps that
    `tangent_kernel` takes (`substep_loop`); False if a sub-step starts at a singular point
    (`singular_floor`)."""
    return substep_loop(Zf, work, s0, c0, minv, wts, level, dt, hc, MAX_SUBSTEPS, n, n, R, d,
                        L, tangent_vectors_rate) == RUNNING


@njit(cache=True)
def stacked_work(R, d):
    """The work arrays of `stacked_loop` for R rows of d = 2N."""
    n = d // 2
    L = R * d
    s, c, f, g, p, q = stage_work(n)
    return (np.empty(L), np.empty(4 * L), np.empty(n), np.empty(n), s, c, f, g, p, q)


#: The named state of a stacked flow of the rotors in the time loop (`stacked_loop`): the
#: flat Z = [y; X] and its views, the weighted sin/cos s0, c0 of y's angles, the system, the
#: step, the inner product's weights, the sums and records, the work arrays of the step
#: (`stacked_work`), and the sizes (N, rows, row length, length of Z; unsigned, see `stacked_rk4_step`).
RotorStack = namedtuple("RotorStack", [
    "Zf", "y", "X", "s0", "c0", "minv", "m", "wts", "level", "speed", "dt", "w", "restricted",
    "logsum", "states", "event_logs", "shares", "work", "n", "R", "nu", "Ru", "du", "Lu", "nz",
    "nsc"])


@njit(cache=True, inline="always")
def stacked_step(fl, vectors_rate):
    """One step dt of the stacked flow ``fl`` (`RotorStack`) by `stacked_rk4_step` with the
    vectors hook ``vectors_rate``, following the policy of ``charts.solvers.status`` (for
    |dt|): a step longer than the cap near a singular point is cut into sub-steps
    (`next_substep`: equal ones as planned from the cap at the step's start, each within its
    own cap once the point comes closer), each from a point that passes the singular-point
    test (`singular_floor`).  Returns RUNNING, or SINGULAR / NONFINITE with the state at the
    start of the failing step (SINGULAR inside a cut step: where its sub-steps reached the
    singular point; `substep_loop`, the one home of the policy).  (The largest weight
    computed once before the loop instead made the whole kernel 2× slower, measured.)"""
    n = fl.n
    dt = fl.dt
    adt = abs(dt)
    code, hc = fixed_step_status(sum_squares(fl.s0, 0, n), sum_squares(fl.Zf, n, n), adt, _CAP)
    if code != RUNNING:
        return code
    return substep_loop(fl.Zf, fl.work, fl.s0, fl.c0, fl.minv, fl.wts, fl.level, dt, hc,
                        1 if hc >= adt else MAX_SUBSTEPS, n, fl.nu, fl.Ru, fl.du, fl.Lu,
                        vectors_rate)


@njit(cache=True, inline="always")
def stacked_project(fl):
    """The state y of ``fl`` onto the invariants (`project_state_into`), its sin/cos anew."""
    Zt, K, th, dl, s, c, f, g, p, q = fl.work
    project_state_into(fl.y, fl.m, fl.wts, fl.level, fl.speed, s, f)
    sincos(fl.Zf, 0, fl.n, fl.wts, fl.s0, fl.c0)
    return RUNNING


@njit(cache=True, inline="always")
def stacked_reorth(fl):
    """The vectors X of ``fl`` onto T_r (if restricted) and re-orthonormalised (eq 18, logs
    added to its sums; NONFINITE where they overflow); the largest kinetic-energy share into
    its histogram."""
    if fl.R > 1:
        if fl.restricted:
            project_tangent_sc(fl.y, fl.X, fl.minv, fl.s0, fl.c0)
        orthonormalize(fl.X, fl.w, fl.logsum)
        if not isfinite(fl.logsum[fl.R - 2]):
            return NONFINITE
    record_share(fl.Zf, fl.n, fl.m, fl.shares)
    return RUNNING


@njit(cache=True, inline="always")
def stacked_record(fl, row):
    """Z's first nz entries, then (where asked) the weighted sines and cosines, into the
    record row ``row`` of ``fl`` (if the records have that row)."""
    states = fl.states
    if row < states.shape[0]:
        Zf = fl.Zf
        nz = fl.nz
        n = fl.n
        for j in range(nz):
            states[row, j] = Zf[j]
        for j in range(fl.nsc):
            states[row, nz + j] = fl.s0[j]
            states[row, nz + n + j] = fl.c0[j]


#: A stacked flow's state as the kernels take it: Z = [y; X] (1 + k, 2N), the weighted
#: sin/cos sc (2, N) of y's angles, the global step counter (1,), the log-norm sums (k,) and
#: the histogram of energy shares (bins,) — `TangentFlow.state`'s arrays.
Stack = namedtuple("Stack", ["Z", "sc", "counter", "logsum", "shares"])
#: The system as the kernels read it: M⁻¹ (N,), the masses (N,), the constraint's weights
#: (N,) and its level.
Rotors = namedtuple("Rotors", ["minv", "m", "wts", "level"])
#: How a flow steps: the speed its state is projected back to, the step dt (< 0: backward),
#: the weights w (2N,) of the vectors' inner product (eq 18) and whether the vectors are kept
#: in T_r.
Stepping = namedtuple("Stepping", ["speed", "dt", "w", "restricted"])
#: What a run records: ``states`` (rows, width): Z's first entries (then sc where wider) at
#: the record steps (`Phases`); ``events`` (E,): sorted global steps at which ``event_logs``
#: (E, k) receive the log-norm sums.
Records = namedtuple("Records", ["states", "events", "event_logs"])


@njit(cache=True, inline="always")
def stacked_loop(stack, rotors, stepping, phases, records, nsteps, vectors_rate, work):
    """Every stacked flow of the rotors in the one time loop (``charts.solvers.driver``):
    advance ``stack.Z`` = [y; X], shape (1 + k, 2N), by ``nsteps`` RK4 steps of eq (8) and of
    the vectors' linear flow ``vectors_rate`` (the hook of `stacked_rk4_step`: eq (17) in
    `tangent_kernel`, the adjoint flow in the backward pass of
    ``charts.analyses.adjoint_pass``) on the constraint Σ wtsᵢ cos θᵢ = level (`Rotors`), as
    ``stepping`` says (`Stepping`: dt < 0 steps backward in time).

    ``stack`` (`Stack`): sc holds a sin θ, a cos θ of y's angles (a = wts), kept current;
    counter the global step count.  After global step i (``phases``: `Phases`): project y
    onto the invariants (`project_state`) when i % project_every == 0 (0: never); project X
    onto T_r (if restricted) and re-orthonormalise (eq 18, logs added to ``stack.logsum``)
    when i % reorth_every == 0; when i ≥ rec_start and (i − rec_start) % rec_every == 0,
    store the first ``records.states.shape[1]`` entries of Z (y, then the rows of X), then
    of sc (the weighted sines, then cosines, as the loop keeps them) in
    ``records.states[row]``, row = (i − rec_start) // rec_every (if it has that row); when
    i = records.events[e], store the log-norm sums in ``records.event_logs[e]``; at every
    re-orthonormalisation step add the largest kinetic-energy share to the histogram
    ``stack.shares`` (``charts.geometry.energy_shares``; size 0: none).  Each step follows
    the policy near singular points (`stacked_step`).  Returns (status, steps done):
    RUNNING, or SINGULAR / NONFINITE with Z at the start of the failing step.

    The loop and its hooks are inlined into one function on purpose: an array-valued call or
    view inside the loop would cost reference-count updates per step (see
    docs/performance.md).  Per stage, sin/cos come from the start of the step shifted by
    `shift_sincos`: one libm sin/cos pair per angle per projection, not four per step.

    ``work`` = (Zt: (1 + k)·2N, K: 4·(1 + k)·2N, then th, dl, s, c, f, g, p, q: N each), the
    work arrays (`stacked_work`), given by the caller: the loop allocates nothing, so that it
    also compiles for a GPU thread whose work arrays are its local memory
    (``charts.solvers.device``).
    """
    Z, sc, counter, logsum, shares = stack
    minv, m, wts, level = rotors
    speed, dt, w, restricted = stepping
    states, events, event_logs = records
    R, d = Z.shape
    n = d // 2
    L = R * d
    nrec = states.shape[1]
    nz = nrec if nrec < L else L        # the record: Z's first nz entries, then where
    nsc = n if nrec > L else 0          # asked s0 and c0 (nsc each)
    Zt, K, th, dl, s, c, f, g, p, q = work
    b = borrowed
    fl = RotorStack(b(Z.reshape(L)), b(Z[0]), b(Z[1:]), b(sc[0]), b(sc[1]), b(minv), b(m), b(wts),
                    level, speed, dt, b(w), restricted, b(logsum), b(states), b(event_logs),
                    b(shares), (b(Zt), b(K), b(th), b(dl), b(s), b(c), b(f), b(g), b(p), b(q)), n,
                    R, np.uint64(n), np.uint64(R), np.uint64(d), np.uint64(L), nz, nsc)
    code = phased_loop(fl, nsteps, counter, phases, events, stacked_step, vectors_rate,
                       stacked_project, stacked_reorth, log_sums, stacked_record)
    keep_alive(work)                    # the work arrays, borrowed above, live until here
    return code


@njit(cache=True)
def tangent_kernel(stack, rotors, stepping, phases, records, nsteps, work):
    """`stacked_loop` of eqs (8) + (17) (hook `tangent_vectors_rate`): the kernel of
    `TangentFlow` and of every forward analysis on the CPU.  It allocates its work arrays in
    its own body, where LLVM knows they alias nothing (``work`` is ignored: callers pass
    None; it is there so that `tangent_loop` can stand in for it): given by the caller, the
    warm kernel ran 15 % slower (0.138 against 0.120 s, scripts/bench_kernel_pair.py)."""
    R, d = stack.Z.shape
    n = d // 2
    s, c, f, g, p, q = stage_work(n)
    return stacked_loop(stack, rotors, stepping, phases, records, nsteps, tangent_vectors_rate,
                        (np.empty(R * d), np.empty(4 * R * d), np.empty(n), np.empty(n), s, c, f,
                         g, p, q))


@njit(cache=True)
def tangent_loop(stack, rotors, stepping, phases, records, nsteps, work):
    """`tangent_kernel` on the caller's work arrays ``work`` (`stacked_work`), allocating
    nothing: the forward pass of the angle test in a GPU thread
    (``charts.analyses.angle_blocks``)."""
    return stacked_loop(stack, rotors, stepping, phases, records, nsteps, tangent_vectors_rate,
                        work)


def tangent_kernel_types(stack, rotors, stepping, *_):
    """The argument types with which the drivers call `tangent_kernel` (from the numba types of
    their first three arguments: `Stack`, `Rotors`, `Stepping`): the phases and the record
    rows as `TangentFlow.advance` passes them, int64 steps, no work arrays (the
    ``kernel_types`` of ``charts.jit.kernel_calls.CallsKernel``)."""
    return (stack, rotors, stepping, _PHASES_TYPE, _RECORDS_TYPE, types.int64, types.none)


def reorth_steps(dt, *multiples) -> int:
    """Steps between re-orthonormalisations: the largest count <= REORTH_TIME/dt (at least 1)
    that divides every one of ``multiples`` (step counts; zeros are ignored), so that the
    vectors are orthonormal at every step that is a multiple of them (the sample points)."""
    g = 0
    for m in multiples:
        g = gcd(g, int(m))
    return largest_divisor(g, max(1, int(round(REORTH_TIME / dt))))


def largest_divisor(g, limit) -> int:
    """The largest count ≤ ``limit`` (≥ 1) that divides ``g`` (``limit`` itself for g = 0)."""
    if g == 0:
        return limit
    return max(r for r in range(1, min(limit, g) + 1) if g % r == 0)


def inner_weights(system, inner):
    """Weights w, shape (2N,), of the tangent inner product Σ wᵢ aᵢ bᵢ (see module doc)."""
    if inner == "theta":
        return np.concatenate([system.masses, np.zeros(system.n)])
    if inner == "full":
        return np.concatenate([system.masses, system.masses])
    if inner == "euclidean":
        return np.ones(2 * system.n)
    raise ValueError(f"inner must be 'theta' (the paper's θ-only product), 'full' or "
                     f"'euclidean', got {inner!r}")


_NO_ROWS = np.empty((0, 0))
_NO_EVENTS = np.empty(0, dtype=np.int64)
_PHASES_TYPE = typeof(Phases(0, 0, 0, 0))
_RECORDS_TYPE = typeof(Records(_NO_ROWS, _NO_EVENTS, _NO_ROWS))


#: Floats per entry of the stacked state Z = [y; X] that a tangent flow holds at once: Z, the
#: RK4 stage point and four stages, the initial random vectors.
STACKED_COPIES = 7


def stacked_bytes(n, k) -> int:
    """Bytes a flow of a state and ``k`` tangent vectors of N = ``n`` rotors holds."""
    return STACKED_COPIES * (1 + int(k)) * 2 * int(n) * 8


def memory_budget() -> int:
    """The bytes a single flow may take: half this machine's physical memory (64 GiB where
    the platform does not say)."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2
    except (AttributeError, ValueError, OSError):         # e.g. Windows
        return 64 << 30


def check_memory(need, what, remedy) -> None:
    """ValueError, before anything is allocated, when ``need`` bytes exceed `memory_budget`:
    the numbers and what to change."""
    budget = memory_budget()
    if need > budget:
        raise ValueError(f"{what} need {need / 2**30:.1f} GiB, more than the {budget / 2**30:.1f} "
                         f"GiB one run may take (half this machine's memory); {remedy}")


class StackedFlow:
    """What every flow of a state and its tangent vectors stacked as ``Z`` = [y; ξ¹; …; ξᵏ]
    with a global step ``counter`` provides (`TangentFlow`,
    ``charts.mechanism.tangent_flow.MechanismTangentFlow``): views of the state ``y`` and the
    vectors ``X``, the steps done, and ``shares``, the histogram of energy shares (empty
    here: a flow that records them has its own)."""

    shares = np.zeros(0, dtype=np.int64)

    @property
    def y(self):
        return self.Z[0]

    @property
    def X(self):
        return self.Z[1:]

    @property
    def steps(self) -> int:
        return int(self.counter[0])


class TangentFlow(StackedFlow):
    """The state (θ, u) and ``k`` tangent vectors, advanced by `tangent_kernel`.

    Parameters
    ----------
    system : RotorSystem
    theta, u : ndarray, shape (N,)
        A validated state (``system.check_state``) with nonzero speed.
    k : int
        Number of tangent vectors; they start as ``seed``-random vectors, projected onto
        T_r if ``restricted``, orthonormal in ``inner``.
    dt : float
        RK4 step.
    reorth_every, project_every : int
        Steps between re-orthonormalisations / projections of y (0: never project).
    share_bins : int
        Bins of the histogram ``shares`` of the largest kinetic-energy share, sampled at every
        re-orthonormalisation (``charts.geometry.energy_shares``; 0: not recorded).

    Attributes: ``Z`` (1 + k, 2N) = [y; X], ``sc`` (2, N), ``counter`` (1,), ``logsum``
    (k,), ``shares`` (share_bins,) — together the whole state (``state()`` /
    ``load_state()`` for checkpoints).
    """

    def __init__(self, system, theta, u, k, *, dt, inner="theta", restricted=True,
                 reorth_every=1, project_every=100, seed=0, share_bins=0):
        n = system.n
        check_memory(stacked_bytes(n, k), f"{k} tangent vectors of N = {n}",
                     "compute fewer exponents (n_exponents) or fewer vectors")
        self.system = system
        self.dt = float(dt)
        self.w = inner_weights(system, inner)
        self.restricted = bool(restricted)
        self.reorth_every = int(reorth_every)
        self.project_every = int(project_every)
        self.speed = float(system.speed(u))
        self.Z = np.empty((1 + k, 2 * n))
        self.Z[0, :n] = theta
        self.Z[0, n:] = u
        if k:
            X = np.random.default_rng(seed).normal(size=(k, 2 * n))
            if self.restricted:
                project_tangent(self.Z[0], X, system.minv, system.weights)
            orthonormalize(X, self.w, np.zeros(k))
            self.Z[1:] = X
        a = system.weights
        self.sc = np.vstack([a * np.sin(self.Z[0, :n]), a * np.cos(self.Z[0, :n])])
        self.counter = np.zeros(1, dtype=np.int64)
        self.logsum = np.zeros(k)
        self.shares = np.zeros(int(share_bins), dtype=np.int64)

    def advance(self, nsteps, *, rec_start=0, rec_every=0, states=None, events=None,
                event_logs=None, where="RK4"):
        """Advance ``nsteps`` steps (recording as `tangent_kernel` says); raises
        `SingularPointError` / `IntegrationError` (``where`` names the route) on failure."""
        states = _NO_ROWS if states is None else states
        if events is None:
            events, event_logs = _NO_EVENTS, _NO_ROWS
        status, done = tangent_kernel(
            self.stack(), self.rotors(), self.stepping(),
            Phases(self.project_every, self.reorth_every, int(rec_start), int(rec_every)),
            Records(states, events, event_logs), int(nsteps), None)
        if status != RUNNING:
            raise status_error(status, self.steps * self.dt, where)

    def stack(self) -> Stack:
        """The flow's state as the kernels take it (its own arrays, not copies)."""
        return Stack(self.Z, self.sc, self.counter, self.logsum, self.shares)

    def rotors(self) -> Rotors:
        """The system as the kernels read it."""
        sys_ = self.system
        return Rotors(sys_.minv, sys_.masses, sys_.weights, sys_.level)

    def stepping(self) -> Stepping:
        """How the flow steps, as the kernels take it."""
        return Stepping(self.speed, self.dt, self.w, self.restricted)

    def state(self) -> dict:
        """Copies of every array that decides the next step (for checkpoints)."""
        return {"Z": self.Z.copy(), "sc": self.sc.copy(), "counter": self.counter.copy(),
                "logsum": self.logsum.copy(), "shares": self.shares.copy()}

    def load_state(self, a) -> None:
        """The arrays of `state` back (a checkpoint without ``shares``, written before they
        were recorded, leaves the histogram as it is)."""
        self.Z[...] = a["Z"]
        self.sc[...] = a["sc"]
        self.counter[...] = a["counter"]
        self.logsum[...] = a["logsum"]
        if "shares" in a:
            self.shares[...] = a["shares"]
