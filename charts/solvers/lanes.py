"""The tangent kernel for L independent trajectories at once ("lanes"), for ensembles.

Each lane is one `TangentFlow`: a state y and k tangent vectors advanced by RK4 of eqs (8)
and (17), projected onto the invariants every ``project_every`` steps and re-orthonormalised
(eq 18) every ``reorth_every`` steps.  The lanes are a structure of arrays, the lane
innermost (``charts.solvers.lane_layout``: element i of the stacked state Z = [y; X] of lane
l at ``i·Lp + l``, Lp = L rounded up to a multiple of ``LANE_WIDTH`` = 8), and every loop
over lanes runs in blocks of 8 lanes, one AVX-512 register: the RK4 step (the one body
``charts.solvers.rk.rk4_stages`` with the lanes' hooks: the equations' lane loops ``*_lanes``
of ``charts.flows.ambient``, the stage point and sum of ``charts.solvers.rk``,
`shift_sincos_lanes`), the step policy (``fixed_step_status``), the
projection onto T_r (`project_tangent_lanes`) and Gram–Schmidt (`orthonormalize_lanes`).  Lane by lane, on a copy in the one-trajectory layout, remain what
calls libm (the projection of the state, `project_state` and `sincos`; the logs of eq 18's
norms) and a step the singular-point policy cuts into sub-steps (`substeps`).  The time
loop `_lanes_run` is compiled for each (N, k) so that its rotor and row loops have constant
lengths.

Identity with the one-trajectory kernel.  Every lane does the operations of
`tangent_kernel` in the same order (no fast-math, no fused multiply-add: Numba compiles
neither unless asked; libm's sin, cos and log lane by lane; sqrt and division are correctly
rounded in vector units too), so lane l ends with the bits of a `TangentFlow` from the same
start (tests/test_lanes.py).

Per-lane status.  A lane that stops (the policy of ``charts.solvers.status``: singular point,
non-finite state) is frozen at the state `tangent_kernel` would have returned and flagged in
``status`` with the global step it stopped at in ``stopped``; the other lanes go on (their
arithmetic never mixes with its: a NaN stays in its lane).
"""
from __future__ import annotations

from collections import namedtuple
from math import isfinite, log

import numpy as np
from ..jit import njit, vector_lowering

from ..flows.ambient import (multiplier_lanes, stage_work, state_rate_lanes, tangent_factors_lanes,
                             tangent_rate_lanes)
from ..geometry.energy_shares import energies_lanes, record_share_of
from ..geometry.primitives import LANE_WIDTH, sincos
from ..geometry.projection import project_state, project_tangent_lanes
from .lane_layout import gather, lane_arrays, lanes_in, lanes_out, scatter
from .rk import RK4_WEIGHTS, rk4_stages, rk4_sum, stage_point
from .status import CAP_FRACTION, NONFINITE, RUNNING, SINGULAR, fixed_step_status, status_error
from .driver import Phases, borrowed, keep_alive, no_record, phased_loop
from .tangent import orthonormalize_lanes, shift_sincos_lanes, substeps

__all__ = ["lanes_kernel", "LaneFlows", "MIN_LANES", "lanes_compiled", "lanes_pay",
           "lanes_saving", "COMPILE_SECONDS", "ALONE_SECONDS", "LANE_PACE"]

_CAP = CAP_FRACTION["rk4"]


#: The arrays and sizes of the lanes' RK4 step, its hooks' ``work`` (``charts.solvers.rk.
#: rk4_stages``): the flat lanes Zf (length M = R·d·L, element i of lane l at i·L + l), the
#: stage point Zt, the stages K, the start angles th, the angle shift dl, the stage point's
#: sin/cos s, c, eq (17)'s factors f, g, p, q, the weighted sin/cos s0, c0 (N·L), Λ, 1/B and
#: their work dlam (L), M⁻¹, the weights per lane wl (element j·L + l = aⱼ) and the sizes N,
#: R, d, M, L (unsigned, as in ``charts.solvers.tangent.stacked_rk4_step``).
LaneStep = namedtuple("LaneStep", ["Zf", "Zt", "K", "th", "dl", "s", "c", "f", "g", "p", "q",
                                   "s0", "c0", "lam", "iB", "dlam", "minv", "wl", "n", "R", "d",
                                   "M", "L"])


@njit(cache=True, inline="always")
def _lanes_start(w, _eqs):
    """`rk4_stages`' stage 0 of the lanes' step: the start angles into th, eqs (8) + (17) at
    Zf, s0, c0 themselves (no copies) into K[0:M], before the stage loop (stage points as
    inline functions called from two branches of the loop cost the kernel ~40 %, measured).
    Sizes unsigned (R − 1 with a signed 1 would make the row index signed)."""
    Zf, s0, c0, n, L = w.Zf, w.s0, w.c0, w.n, w.L
    W = LANE_WIDTH
    nl = n * L
    z0 = nl - nl
    th = w.th
    for i0 in range(z0, nl, W):
        for t in range(W):
            th[i0 + t] = Zf[i0 + t]
    dL = w.d * L
    multiplier_lanes(Zf, z0, n, L, w.minv, s0, c0, w.lam, w.iB)
    state_rate_lanes(Zf, z0, n, L, w.minv, s0, w.lam, w.K, z0)
    tangent_factors_lanes(Zf, z0, n, L, w.minv, s0, c0, w.lam, w.f, w.g, w.p, w.q)
    tangent_rate_lanes(Zf, dL, w.R - np.uint64(1), n, L, w.f, w.g, w.p, w.q, w.iB, w.dlam, w.K,
                       dL)
    return 0.0, 1


@njit(cache=True, inline="always")
def _lanes_point(w, st, a):
    """`rk4_stages`' stage point of the lanes' step: `rk4_point` in blocks of `LANE_WIDTH`,
    the sin/cos shifted from s0, c0 (`shift_sincos_lanes`)."""
    Zf, Zt, K, dl, M = w.Zf, w.Zt, w.K, w.dl, w.M
    W = LANE_WIDTH
    nl = w.n * w.L
    z0 = nl - nl
    op = np.uint64(st - 1) * M          # the previous stage
    for i0 in range(z0, M, W):
        for t in range(W):
            Zt[i0 + t] = stage_point(Zf[i0 + t], a, K[op + i0 + t])
    for i0 in range(z0, nl, W):
        for t in range(W):
            dl[i0 + t] = a * K[op + i0 + t]
    shift_sincos_lanes(w.s0, w.c0, dl, Zt, nl, w.wl, w.s, w.c)


@njit(cache=True, inline="always")
def _lanes_rate(w, _eqs, st, hmin):
    """`rk4_stages`' stage rates of the lanes' step: eqs (8) + (17) at Zt, s, c into stage
    st of K."""
    Zt, s, c, n, L = w.Zt, w.s, w.c, w.n, w.L
    z0 = n - n
    o = np.uint64(st) * w.M
    dL = w.d * L
    multiplier_lanes(Zt, z0, n, L, w.minv, s, c, w.lam, w.iB)
    state_rate_lanes(Zt, z0, n, L, w.minv, s, w.lam, w.K, o)
    tangent_factors_lanes(Zt, z0, n, L, w.minv, s, c, w.lam, w.f, w.g, w.p, w.q)
    tangent_rate_lanes(Zt, dL, w.R - np.uint64(1), n, L, w.f, w.g, w.p, w.q, w.iB, w.dlam, w.K,
                       o + dL)
    return hmin


@njit(cache=True, inline="always")
def _lanes_combine(w, h):
    """`rk4_stages`' end of the lanes' step: `rk4_combine` in blocks of `LANE_WIDTH`, then
    s0, c0 shifted from the start angles th to the new ones."""
    Zf, K, dl, th, M = w.Zf, w.K, w.dl, w.th, w.M
    W = LANE_WIDTH
    nl = w.n * w.L
    z0 = nl - nl
    h6 = RK4_WEIGHTS[0] * h
    M2 = M + M
    M3 = M2 + M
    for i0 in range(z0, M, W):
        for t in range(W):
            i = i0 + t
            Zf[i] = rk4_sum(Zf[i], h6, K[i], K[M + i], K[M2 + i], K[M3 + i])
    for i0 in range(z0, nl, W):
        for t in range(W):
            dl[i0 + t] = Zf[i0 + t] - th[i0 + t]
    shift_sincos_lanes(w.s0, w.c0, dl, Zf, nl, w.wl, w.s0, w.c0)


def lanes_kernel(Z, sc, counter, status, stopped, frozen, minv, m, wts, level, speed, dt,
                 nsteps, reorth_every, w, restricted, project_every, logsum, events,
                 event_logs, shares, arrays=None):
    """Advance the L lanes of Z, shape ((1 + k)·2N, L), by ``nsteps`` RK4 steps: lane l does
    what `tangent_kernel` does to the flat state Z[:, l] with ``sc[:, :, l]`` (sc: (2, N, L)),
    the shared step counter ``counter`` (1,), ``speed[l]`` and ``logsum[l]`` (logsum: (L, k));
    at the global step events[e] it stores logsum[l] in event_logs[e, l] (event_logs:
    (E, L, k)); at every re-orthonormalisation it adds lane l's largest kinetic-energy share
    to the histogram shares[l] (shares: (L, bins), bins 0: none).  Recording of states is
    not offered.

    ``status`` (L,) holds each lane's status (RUNNING, or SINGULAR / NONFINITE once it
    stopped, with the global step in ``stopped[l]``); a stopped lane keeps, in ``frozen``
    (the shape of Z plus 2N rows for its sin/cos), the state `tangent_kernel` would have
    returned, and leaves every call with it.  Returns the number of running lanes.

    The steps run in `_lanes_run`, compiled for each N and k (their loops then have constant
    lengths, which LLVM unrolls), on copies of Z and sc with the lane count rounded up to a
    multiple of `LANE_WIDTH` (the extra lanes: copies of a running lane, never read back) and
    every array distinct, as its ``noalias`` compilation requires.  ``arrays``: those
    copies and the loop's work arrays (`lane_arrays` of Z's shape and wts), kept by the
    caller between calls (allocating them costs ~10 µs a call); None: allocated here."""
    n = int(wts.size)
    k = Z.shape[0] // (2 * n) - 1
    Zp, s0, c0, work = lane_arrays(*Z.shape, wts) if arrays is None else arrays
    lanes_in(Z, sc, Zp, s0, c0)
    running = _lanes_run(Zp, s0, c0, counter, status, stopped, frozen, minv, m, wts, level,
                         speed, dt, nsteps, reorth_every, w, restricted, project_every, logsum,
                         events, event_logs, shares, work, (0,) * n, (0,) * k)
    lanes_out(Zp, s0, c0, Z, sc)
    return running


#: The named state of the lanes in the time loop (``charts.solvers.driver.phased_loop``):
#: the flat lanes Zf, s0, c0, the step counter, each lane's status, stop step and frozen
#: state, the system, each lane's speed, the step, the inner product's weights, the sums and
#: histograms, the step's work arrays (``lane_layout.lane_arrays``), one lane's work arrays
#: in the one-trajectory layout (``one``: z, its sin/cos, the RK4 work and stage work), the
#: work of the policy (``subs``: each lane's status and cap, the lanes that take sub-steps,
#: their caps, states and sin/cos), N and k as the lengths of the tuples ``n_tag``, ``k_tag``
#: (compile-time constants: the loops over rotors and rows have constant lengths), and the
#: padded lane count Lp (the stride of the flat lanes).
LaneStack = namedtuple("LaneStack", [
    "Zf", "s0", "c0", "counter", "status", "stopped", "frozen", "minv", "m", "wts", "level",
    "speed", "dt", "w", "restricted", "logsum", "event_logs", "shares", "work", "one", "subs",
    "n_tag", "k_tag", "Lp"])


@njit(cache=True, inline="always")
def _lanes_policy_step(fl, rate):
    """One step dt of every lane: the policy across the lanes (padding too); a lane at a
    singular point or with a non-finite state stops (`_stop`), one nearer a singular point
    than the step allows takes its step alone in sub-steps (`substeps`, in the
    one-trajectory layout) after the lanes' step (``rk4_stages`` with the lanes' hooks,
    `LaneStep`) has moved the others.
    ``rate`` is unused (the lanes' step has eq (17) written in)."""
    n = len(fl.n_tag)
    k = len(fl.k_tag)
    Zf, s0, c0, status, counter, dt = fl.Zf, fl.s0, fl.c0, fl.status, fl.counter, fl.dt
    Zt, K, th, dl, s, c, f, g, p, q, lam, iB, dlam, wl, S, U, cap, v1, v2, v3, nrm = fl.work
    z, zs0, zc0, Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1 = fl.one
    code, sub, subcap, subZ, subS = fl.subs
    L = status.size
    Lp = fl.Lp
    d = 2 * n
    R = k + 1
    D = R * d
    nu, Ru, du, Mu, Lu = np.uint64(n), np.uint64(R), np.uint64(d), np.uint64(D * Lp), np.uint64(Lp)
    W = LANE_WIDTH
    for l0 in range(Lu - Lu, Lu, W):  # the policy, across the lanes (padding too)
        for t in range(W):
            S[l0 + t] = 0.0
            U[l0 + t] = 0.0
        for j in range(nu):
            a = j * Lu + l0
            b = (nu + j) * Lu + l0
            for t in range(W):
                S[l0 + t] += s0[a + t] * s0[a + t]
                U[l0 + t] += Zf[b + t] * Zf[b + t]
        for t in range(W):
            code[l0 + t], cap[l0 + t] = fixed_step_status(S[l0 + t], U[l0 + t], dt, _CAP)
    nsub = 0
    for l in range(L):
        if status[l] != RUNNING or (code[l] == RUNNING and cap[l] >= dt):
            continue
        st, hc = code[l], cap[l]
        if st != RUNNING:
            _stop(l, st, counter[0], Zf, s0, c0, Lp, status, fl.stopped, fl.frozen)
        elif hc < dt:  # near a singular point: this lane takes the sub-steps alone
            sub[nsub] = l
            subcap[nsub] = hc
            gather(Zf, s0, c0, Lp, l, subZ[nsub], subS[nsub, 0], subS[nsub, 1])
            nsub += 1
    rk4_stages(LaneStep(Zf, Zt, K, th, dl, s, c, f, g, p, q, s0, c0, lam, iB, dlam, fl.minv, wl,
                        nu, Ru, du, Mu, Lu), 0, dt, _lanes_start, _lanes_point, _lanes_rate,
               _lanes_combine)    # the lanes' step: eqs (8) + (17) in the one RK4 body
    for t in range(nsub):
        l = sub[t]
        zz = subZ[t]
        ok = substeps(zz, (Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1), subS[t, 0], subS[t, 1],
                      fl.minv, fl.wts, fl.level, dt, subcap[t], nu, Ru, du, np.uint64(D))
        scatter(zz, subS[t, 0], subS[t, 1], Zf, s0, c0, Lp, l)
        if not ok:
            _stop(l, SINGULAR, counter[0], Zf, s0, c0, Lp, status, fl.stopped, fl.frozen)
    return RUNNING


@njit(cache=True, inline="always")
def _lanes_project(fl):
    """Every running lane's state onto the invariants (`project_state`, in the one-trajectory
    layout), its sin/cos anew."""
    n = len(fl.n_tag)
    z, zs0, zc0, Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1 = fl.one
    Zf, s0, c0, status = fl.Zf, fl.s0, fl.c0, fl.status
    Lp = fl.Lp
    y1 = z[:2 * n]
    for l in range(status.size):
        if status[l] == RUNNING:
            gather(Zf, s0, c0, Lp, l, z, zs0, zc0)
            project_state(y1, fl.m, fl.wts, fl.level, fl.speed[l])
            sincos(z, 0, n, fl.wts, zs0, zc0)
            scatter(z, zs0, zc0, Zf, s0, c0, Lp, l)
    return RUNNING


@njit(cache=True, inline="always")
def _lanes_reorth(fl):
    """Across all lanes (a stopped lane's copy is restored at the end): the vectors onto T_r
    (if restricted) and re-orthonormalised (eq 18), each running lane's logs added to its
    sums (it stops where they overflow: NONFINITE); the largest kinetic-energy shares into
    the histograms; the padding and stopped lanes refreshed (`_refresh`)."""
    n = len(fl.n_tag)
    k = len(fl.k_tag)
    Zt, K, th, dl, s, c, f, g, p, q, lam, iB, dlam, wl, S, U, cap, v1, v2, v3, nrm = fl.work
    z, zs0, zc0, Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1 = fl.one
    Zf, s0, c0, status, logsum, shares = fl.Zf, fl.s0, fl.c0, fl.status, fl.logsum, fl.shares
    L = status.size
    Lp = fl.Lp
    R = k + 1
    nu, ku, du, Lu = np.uint64(n), np.uint64(k), np.uint64(2 * n), np.uint64(Lp)
    if R > 1:
        if fl.restricted:
            project_tangent_lanes(Zf, nu, ku, Lu, fl.minv, s0, c0, v1, v2, v3)
        orthonormalize_lanes(Zf, du * Lu, ku, du, Lu, fl.w, v1, nrm)
        for l in range(L):
            if status[l] != RUNNING:
                continue
            for r in range(k):
                logsum[l, r] += log(nrm[r * Lp + l])
            if not isfinite(logsum[l, R - 2]):
                _stop(l, NONFINITE, fl.counter[0], Zf, s0, c0, Lp, status, fl.stopped,
                      fl.frozen)
    if shares.shape[1] > 0:       # S, U: free until the next step's policy
        energies_lanes(Zf, n, fl.m, Lp, S, U)
        for l in range(L):
            if status[l] == RUNNING:
                record_share_of(U[l], S[l], shares, l)
    _refresh(Zf, s0, c0, Lp, status, z, zs0, zc0)
    return RUNNING


@njit(cache=True, inline="always")
def _lanes_log_event(fl, ev):
    """Every running lane's log-norm sums into its event logs, row ``ev``."""
    status, logsum, event_logs = fl.status, fl.logsum, fl.event_logs
    for l in range(status.size):
        if status[l] == RUNNING:
            for r in range(len(fl.k_tag)):
                event_logs[ev, l, r] = logsum[l, r]


@njit(cache=True, **vector_lowering.options())
def _lanes_run(Zf, s0, c0, counter, status, stopped, frozen, minv, m, wts, level, speed, dt,
               nsteps, reorth_every, w, restricted, project_every, logsum, events, event_logs,
               shares, work, n_tag, k_tag):
    """`lanes_kernel`'s steps on the flat lanes Zf, s0, c0 (element i of lane l at
    i·Lp + l, Lp a multiple of `LANE_WIDTH`; lanes ≥ L = status.size are padding, copied
    from lane 0 after each re-orthonormalisation), in the one time loop of the stacked flows
    (``charts.solvers.driver.phased_loop``) with the lanes' hooks; ``work``: the step's work
    arrays and the weights per lane; ``n_tag``, ``k_tag``: tuples of N and k elements, so
    that each (N, k) has its own compilation.  Every array argument distinct (``noalias``).
    Returns the number of running lanes, the stopped ones restored to their frozen state."""
    n = len(n_tag)                      # N and k, fixed at compile time (tuple lengths)
    k = len(k_tag)
    L = status.size
    Zt, K, th, dl, s, c, f, g, p, q, lam, iB, dlam, wl, S, U, cap, v1, v2, v3, nrm = work
    Lp = lam.size
    D = (k + 1) * 2 * n
    # one lane in the one-trajectory layout (projections, eq 18, sub-steps), the policy's work
    z = np.empty(D)
    zs0 = np.empty(n)
    zc0 = np.empty(n)
    Zt1 = np.empty(D)
    K1 = np.empty(4 * D)
    th1 = np.empty(n)
    dl1 = np.empty(n)
    s1, c1, f1, g1, p1, q1 = stage_work(n)
    code = np.empty(Lp, dtype=np.int64)
    sub = np.empty(L, dtype=np.int64)
    subcap = np.empty(L)
    subZ = np.empty((L, D))
    subS = np.empty((L, 2, n))
    b = borrowed
    fl = LaneStack(b(Zf), b(s0), b(c0), b(counter), b(status), b(stopped), b(frozen), b(minv),
                   b(m), b(wts), level, b(speed), dt, b(w), restricted, b(logsum),
                   b(event_logs), b(shares),
                   (b(Zt), b(K), b(th), b(dl), b(s), b(c), b(f), b(g), b(p), b(q), b(lam),
                    b(iB), b(dlam), b(wl), b(S), b(U), b(cap), b(v1), b(v2), b(v3), b(nrm)),
                   (b(z), b(zs0), b(zc0), b(Zt1), b(K1), b(th1), b(dl1), b(s1), b(c1), b(f1),
                    b(g1), b(p1), b(q1)),
                   (b(code), b(sub), b(subcap), b(subZ), b(subS)), n_tag, k_tag, Lp)
    phased_loop(fl, nsteps, counter, Phases(project_every, reorth_every, 0, 0), events,
                _lanes_policy_step, 0, _lanes_project, _lanes_reorth, _lanes_log_event,
                no_record)
    keep_alive((z, zs0, zc0, Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1, code, sub, subcap,
                subZ, subS))            # the work arrays, borrowed above, live until here
    running = 0
    for l in range(L):
        if status[l] == RUNNING:
            running += 1
        else:
            for i in range(D):
                Zf[i * Lp + l] = frozen[i, l]
            for j in range(n):
                s0[j * Lp + l] = frozen[D + j, l]
                c0[j * Lp + l] = frozen[D + n + j, l]
    return running


@njit(cache=True, inline="always")
def _refresh(Zf, s0, c0, Lp, status, z, zs, zc):
    """Copy the first running lane into the padding lanes and the stopped lanes (which
    would otherwise go on computing on a state that may overflow)."""
    L = status.size
    first = -1
    for l in range(L):
        if status[l] == RUNNING:
            first = l
            break
    if first < 0:
        return
    gathered = False
    for l in range(Lp):
        if l >= L or status[l] != RUNNING:
            if not gathered:
                gather(Zf, s0, c0, Lp, first, z, zs, zc)
                gathered = True
            scatter(z, zs, zc, Zf, s0, c0, Lp, l)


@njit(cache=True)
def _stop(l, st, step, Zf, s0, c0, Lp, status, stopped, frozen):
    """Stop lane l with status st at the global step ``step``, freezing its state."""
    status[l] = st
    stopped[l] = step
    D = Zf.size // Lp
    n = s0.size // Lp
    for i in range(D):
        frozen[i, l] = Zf[i * Lp + l]
    for j in range(n):
        frozen[D + j, l] = s0[j * Lp + l]
        frozen[D + n + j, l] = c0[j * Lp + l]


def _same_system(a, b) -> bool:
    """Whether two `RotorSystem` s are the same system (masses, weights and level)."""
    return a is b or (type(a) is type(b) and a.n == b.n and a.level == b.level
                      and np.array_equal(a.masses, b.masses)
                      and np.array_equal(a.weights, b.weights))


_NO_EVENTS = np.empty(0, dtype=np.int64)
_NO_LOGS = np.empty((0, 0, 0))


#: Fewest trajectories worth one lane kernel: below, the members run one after the other in
#: the one-trajectory kernel, which is as fast there (the lanes are padded to blocks of 8;
#: N = 5, paired: 0.98x the one-trajectory kernel's pace at 2 lanes, 1.44x at 3, 1.83x at
#: 4, 3.6x at 8; docs/performance.md, "Ensembles in vector lanes").
MIN_LANES = 3
#: CPU seconds `_lanes_run` takes to compile for a new (N, k): 18–23 s at N = 3, 4, 5 with
#: k = N − 2 on the 2-core VM (docs/performance.md, "First use").
COMPILE_SECONDS = 20.0
#: CPU seconds of the one-trajectory kernel per step and entry of the stacked state
#: Z = [y; X]: N = 5, k = 3 (40 entries) ran 27,191 time units per CPU second
#: (docs/performance.md, "Every target in one run").
ALONE_SECONDS = 9.2e-9
#: The lanes' pace against the one-trajectory kernel, (lane count, ratio) from that count on:
#: N = 5, paired, 1.44x at 3 lanes, 1.83x at 4, 3.3x at 8 and more (docs/performance.md,
#: "Ensembles in vector lanes"; 5–7 lanes taken at the pace of 4).
LANE_PACE = ((3, 1.44), (4, 1.83), (8, 3.3))


def lanes_compiled(n, k) -> bool:
    """Whether `_lanes_run` for N = ``n`` rotors and ``k`` vectors is compiled in this process
    or in numba's disk cache (loaded, then, in well under a second); False where that cannot
    be read (numba's cache index is private API: a failure only costs the lanes' speed,
    the numbers are the same on both routes)."""
    def ours(sig):
        return len(sig) > 2 and len(sig[-2]) == n and len(sig[-1]) == k

    try:
        if any(ours(sig) for sig in _lanes_run.overloads):
            return True
        cache = _lanes_run._cache
        codegen = _lanes_run.targetctx.codegen()
        index = cache._cache_file._load_index()
        return any(ours(key[0]) and key == cache._index_key(key[0], codegen) for key in index)
    except Exception:                   # noqa: BLE001 - not readable: taken as not compiled
        return False


def lanes_saving(n, k, lanes, steps, runs=None) -> float:
    """CPU seconds the lanes save against the one-trajectory kernel: ``runs`` (default
    ``lanes``) trajectories of N = ``n`` rotors with ``k`` tangent vectors, ``steps`` steps
    each, advanced ``lanes`` to a kernel (`ALONE_SECONDS`, `LANE_PACE`; 0 below `MIN_LANES`)."""
    if lanes < MIN_LANES:
        return 0.0
    pace = [ratio for count, ratio in LANE_PACE if count <= lanes][-1]
    alone = (lanes if runs is None else runs) * steps * (1 + k) * 2 * n * ALONE_SECONDS
    return alone * (1.0 - 1.0 / pace)


def lanes_pay(n, k, lanes, steps, runs=None) -> bool:
    """Whether trajectories of N = ``n`` rotors with ``k`` tangent vectors, ``steps`` steps
    each, ``lanes`` to a kernel and ``runs`` (default ``lanes``) in all that share one
    compilation, should run in the lanes of one kernel (`LaneFlows`) rather than one after
    the other in the one-trajectory kernel (the same bits either way): at least `MIN_LANES`
    to a kernel, and the lane kernel for (N, k) compiled already (`lanes_compiled`) or the
    time the lanes save (`lanes_saving`) larger than its compilation (`COMPILE_SECONDS`).  A
    short ensemble on an empty cache then costs seconds, not the lanes' compilation."""
    if lanes < MIN_LANES:
        return False
    return lanes_saving(n, k, lanes, steps, runs) > COMPILE_SECONDS or lanes_compiled(n, k)


class LaneFlows:
    """L `TangentFlow` s of one system and one set of settings, advanced together by
    `lanes_kernel`.

    Parameters
    ----------
    flows : sequence of TangentFlow
        The lanes' starting points (their state is copied; they share the system (equal
        masses, weights and level), ``dt``,
        ``w``, ``restricted``, ``reorth_every`` and ``project_every``, checked here) and no
        steps done.

    Attributes: ``Z`` ((1 + k)·2N, L), ``sc`` (2, N, L), ``counter`` (1,), ``logsum`` (L, k),
    ``shares`` (L, bins) (the histograms of the largest energy share, as the flows record
    them), ``status`` (L,) and ``stopped`` (L,) (global step of a stopped lane).
    """

    def __init__(self, flows):
        flows = list(flows)
        if not flows:
            raise ValueError("flows must hold at least one TangentFlow")
        f0 = flows[0]
        for f in flows:
            same = (_same_system(f.system, f0.system) and f.dt == f0.dt and np.array_equal(f.w, f0.w)
                    and f.restricted == f0.restricted and f.reorth_every == f0.reorth_every
                    and f.project_every == f0.project_every and f.Z.shape == f0.Z.shape
                    and f.shares.shape == f0.shares.shape and f.steps == 0)
            if not same:
                raise ValueError("flows must share their system and settings, none advanced")
        self.system, self.dt, self.w = f0.system, f0.dt, f0.w
        self.restricted, self.reorth_every = f0.restricted, f0.reorth_every
        self.project_every = f0.project_every
        L = len(flows)
        self.Z = np.ascontiguousarray(np.stack([f.Z.reshape(-1) for f in flows], axis=1))
        self.sc = np.ascontiguousarray(np.stack([f.sc for f in flows], axis=2))
        self.speed = np.array([f.speed for f in flows])
        self.logsum = np.zeros((L, f0.Z.shape[0] - 1))
        self.shares = np.zeros((L, f0.shares.size), dtype=np.int64)
        self.counter = np.zeros(1, dtype=np.int64)
        self.status = np.full(L, RUNNING, dtype=np.int64)
        self.stopped = np.zeros(L, dtype=np.int64)
        self.frozen = np.zeros((self.Z.shape[0] + 2 * self.system.n, L))
        self._arrays = None  # `lanes_kernel`'s arrays, allocated at the first advance

    @property
    def steps(self) -> int:
        return int(self.counter[0])

    def lane(self, l):
        """Lane l's stacked state Z, shape (1 + k, 2N) (a copy)."""
        return self.Z[:, l].reshape(-1, 2 * self.system.n).copy()

    def store(self, l, flow) -> None:
        """Lane l's whole state (stacked state, sin/cos, step counter, log-norm sums, energy
        shares) into the `TangentFlow` ``flow``: what ``flow`` would hold had it advanced
        alone."""
        flow.load_state({"Z": self.lane(l), "sc": self.sc[:, :, l], "counter": self.counter,
                         "logsum": self.logsum[l], "shares": self.shares[l]})

    def stopped_lanes(self):
        """The lanes that stopped (see `error`), in order."""
        return [int(l) for l in np.flatnonzero(self.status != RUNNING)]

    def advance(self, nsteps, *, events=None, event_logs=None) -> int:
        """Advance ``nsteps`` steps; at the global steps ``events`` (sorted), store every
        running lane's log-norm sums in ``event_logs`` (E, L, k).  Returns the number of
        running lanes (see `error` for the others)."""
        sys_ = self.system
        if events is None:
            events, event_logs = _NO_EVENTS, _NO_LOGS
        if self._arrays is None:
            self._arrays = lane_arrays(*self.Z.shape, sys_.weights)
        return lanes_kernel(self.Z, self.sc, self.counter, self.status, self.stopped,
                            self.frozen, sys_.minv, sys_.masses, sys_.weights, sys_.level,
                            self.speed, self.dt, int(nsteps), self.reorth_every, self.w,
                            self.restricted, self.project_every, self.logsum, events,
                            event_logs, self.shares, self._arrays)

    def error(self, l, where):
        """The exception `TangentFlow.advance` raises for the stopped lane l (``where`` names
        the route)."""
        return status_error(int(self.status[l]), int(self.stopped[l]) * self.dt, where)
