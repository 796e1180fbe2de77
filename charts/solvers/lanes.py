"""The tangent kernel for L independent trajectories at once ("lanes"), for ensembles.

Each lane is one `TangentFlow`: a state y and k tangent vectors advanced by RK4 of eqs (8)
and (17), projected onto the invariants every ``project_every`` steps and re-orthonormalised
(eq 18) every ``reorth_every`` steps.  The lanes are stored as a structure of arrays: element
i of the stacked state Z = [y; X] (flat, i < (1 + k)·2N) of lane l at ``Z[i, l]``, the lane
innermost, so that the RK4 stages — the equations' lane loops ``*_lanes`` of
``charts.flows.ambient``, `rk4_point`, `rk4_combine` and `shift_sincos` (elementwise) — run
across the lanes in the CPU's vector units.  What happens once per lane and per projection or
re-orthonormalisation (`project_state`, `sincos`, `project_tangent_sc`, `orthonormalize`) and
a step the singular-point policy cuts into sub-steps (`substeps`) is done lane by lane
through the one-trajectory homes, on a copy of the lane in the one-trajectory layout.

Identity with the one-trajectory kernel.  Every lane does the operations of
`tangent_kernel` in the same order (no fast-math, no fused multiply-add: Numba compiles
neither unless asked, and libm's sin/cos are called lane by lane), so lane l ends with the
bits of a `TangentFlow` from the same start (tests/test_lanes.py).

Per-lane status.  A lane that stops (the policy of ``charts.solvers.status``: singular point,
non-finite state) is frozen at the state `tangent_kernel` would have returned and flagged in
``status`` with the global step it stopped at in ``stopped``; the other lanes go on (their
arithmetic never mixes with its: a NaN stays in its lane).
"""
from __future__ import annotations

from math import isfinite

import numpy as np
from numba import njit

from ..flows.ambient import (multiplier_lanes, sincos, stage_work, state_rate_lanes,
                             tangent_factors_lanes, tangent_rate_lanes)
from ..geometry.projection import project_state, project_tangent_sc
from .rk import rk4_combine, rk4_node, rk4_point
from .status import CAP_FRACTION, NONFINITE, RUNNING, SINGULAR, fixed_step_status, status_error
from .tangent import countdowns, orthonormalize, shift_sincos, substeps

__all__ = ["lanes_kernel", "LaneFlows"]

_CAP = CAP_FRACTION["rk4"]


@njit(cache=True, inline="always")
def _lanes_step(Zf, Zt, K, th, dl, s, c, f, g, p, q, s0, c0, lam, iB, dlam, minv, wl, h, n,
                R, d, M, L):
    """One RK4 step of size h of eqs (8) + (17) for the L lanes of Zf (flat, length
    M = R·d·L, element i of lane l at i·L + l); s0, c0, shape (N·L,), the weighted sin/cos
    of the angles, updated; wl = the weights, element j·L + l = aⱼ.  The lane form of
    `charts.solvers.tangent._rk4_step`: the same operations per lane, in the same order,
    written out as there (the stage points as shared inline functions, called from the two
    branches of the stage loop, cost both kernels ~40 %, measured).  Sizes unsigned
    (``np.uint64``) as there."""
    nl = n * L
    for i in range(nl):
        th[i] = Zf[i]
    zero = np.uint64(0)
    dL = d * L
    for st in range(4):
        o = np.uint64(st) * M
        if st == 0:
            for i in range(M):
                Zt[i] = Zf[i]
            for i in range(nl):
                s[i] = s0[i]
                c[i] = c0[i]
        else:
            a = rk4_node(st) * h
            op = o - M
            rk4_point(Zf, K, op, a, M, Zt)
            for i in range(nl):
                dl[i] = a * K[op + i]
            shift_sincos(s0, c0, dl, Zt, nl, wl, s, c)
        multiplier_lanes(Zt, zero, n, L, minv, s, c, lam, iB)
        state_rate_lanes(Zt, zero, n, L, minv, s, lam, K, o)
        tangent_factors_lanes(Zt, zero, n, L, minv, s, c, lam, f, g, p, q)
        for r in range(np.uint64(1), R):
            tangent_rate_lanes(Zt, r * dL, n, L, f, g, p, q, iB, dlam, K, o + r * dL)
    rk4_combine(Zf, K, h, M, Zf)
    for i in range(nl):
        dl[i] = Zf[i] - th[i]
    shift_sincos(s0, c0, dl, Zf, nl, wl, s0, c0)


@njit(cache=True, inline="always")
def _gather(Z2, S2, l, z, s0, c0):
    """Lane l of Z2 (R·d, L) and S2 (2, N, L) into z (R·d,), s0, c0 (N,)."""
    for i in range(z.size):
        z[i] = Z2[i, l]
    for j in range(s0.size):
        s0[j] = S2[0, j, l]
        c0[j] = S2[1, j, l]


@njit(cache=True, inline="always")
def _scatter(z, s0, c0, Z2, S2, l):
    """The inverse of `_gather`."""
    for i in range(z.size):
        Z2[i, l] = z[i]
    for j in range(s0.size):
        S2[0, j, l] = s0[j]
        S2[1, j, l] = c0[j]


@njit(cache=True)
def lanes_kernel(Z, sc, counter, status, stopped, frozen, minv, m, wts, level, speed, dt,
                 nsteps, reorth_every, w, restricted, project_every, logsum, events,
                 event_logs):
    """Advance the L lanes of Z, shape ((1 + k)·2N, L), by ``nsteps`` RK4 steps: lane l does
    what `tangent_kernel` does to the flat state Z[:, l] with ``sc[:, :, l]`` (sc: (2, N, L)),
    the shared step counter ``counter`` (1,), ``speed[l]`` and ``logsum[l]`` (logsum: (L, k));
    at the global step events[e] it stores logsum[l] in event_logs[e, l] (event_logs:
    (E, L, k)).  Recording of states is not offered.

    ``status`` (L,) holds each lane's status (RUNNING, or SINGULAR / NONFINITE once it
    stopped, with the global step in ``stopped[l]``); a stopped lane keeps, in ``frozen``
    (the shape of Z plus 2N rows for its sin/cos), the state `tangent_kernel` would have
    returned, and leaves every call with it.  Returns the number of running lanes."""
    D, L = Z.shape
    n = wts.size
    d = 2 * n
    R = D // d
    k = R - 1
    M = D * L
    nl = n * L
    nu, Ru, du, Mu, Lu = np.uint64(n), np.uint64(R), np.uint64(d), np.uint64(M), np.uint64(L)
    Zf = Z.reshape(M)
    s0 = sc[0].reshape(nl)
    c0 = sc[1].reshape(nl)
    Zt = np.empty(M)
    K = np.empty(4 * M)
    th = np.empty(nl)
    dl = np.empty(nl)
    s, c, f, g, p, q = np.empty(nl), np.empty(nl), np.empty(nl), np.empty(nl), np.empty(nl), np.empty(nl)
    lam, iB, dlam, S, U = np.empty(L), np.empty(L), np.empty(L), np.empty(L), np.empty(L)
    code = np.empty(L, dtype=np.int64)
    cap = np.empty(L)
    wl = np.empty(nl)
    for j in range(n):
        for l in range(L):
            wl[j * L + l] = wts[j]
    # one lane in the one-trajectory layout (projections, eq 18, sub-steps)
    z = np.empty(D)
    zs0 = np.empty(n)
    zc0 = np.empty(n)
    X1 = z[d:].reshape(k, d)
    y1 = z[:d]
    Zt1 = np.empty(D)
    K1 = np.empty(4 * D)
    th1 = np.empty(n)
    dl1 = np.empty(n)
    s1, c1, f1, g1, p1, q1 = stage_work(n)
    sub = np.empty(L, dtype=np.int64)
    subcap = np.empty(L)
    subZ = np.empty((L, D))
    subS = np.empty((L, 2, n))
    to_proj, to_reorth, ev = countdowns(counter[0], project_every, reorth_every, events)
    for it in range(nsteps):
        for l in range(L):
            S[l] = 0.0
            U[l] = 0.0
        for j in range(n):
            for l in range(L):
                S[l] += s0[j * L + l] * s0[j * L + l]
                U[l] += Zf[(n + j) * L + l] * Zf[(n + j) * L + l]
        for l in range(L):  # the policy, across the lanes
            code[l], cap[l] = fixed_step_status(S[l], U[l], dt, _CAP)
        nsub = 0
        for l in range(L):
            if status[l] != RUNNING or (code[l] == RUNNING and cap[l] >= dt):
                continue
            st, hc = code[l], cap[l]
            if st != RUNNING:
                _stop(l, st, counter[0], Z, sc, status, stopped, frozen)
            elif hc < dt:  # near a singular point: this lane takes the sub-steps alone
                sub[nsub] = l
                subcap[nsub] = hc
                _gather(Z, sc, l, subZ[nsub], subS[nsub, 0], subS[nsub, 1])
                nsub += 1
        _lanes_step(Zf, Zt, K, th, dl, s, c, f, g, p, q, s0, c0, lam, iB, dlam, minv, wl, dt,
                    nu, Ru, du, Mu, Lu)
        for t in range(nsub):
            l = sub[t]
            zz = subZ[t]
            ok = substeps(zz, Zt1, K1, th1, dl1, s1, c1, f1, g1, p1, q1, subS[t, 0], subS[t, 1],
                          minv, wts, dt, subcap[t], nu, Ru, du, np.uint64(D))
            _scatter(zz, subS[t, 0], subS[t, 1], Z, sc, l)
            if not ok:
                _stop(l, SINGULAR, counter[0], Z, sc, status, stopped, frozen)
        counter[0] += 1
        to_proj -= 1
        if to_proj == 0:
            to_proj = project_every
            for l in range(L):
                if status[l] == RUNNING:
                    _gather(Z, sc, l, z, zs0, zc0)
                    project_state(y1, m, wts, level, speed[l])
                    sincos(z, 0, n, wts, zs0, zc0)
                    _scatter(z, zs0, zc0, Z, sc, l)
        to_reorth -= 1
        if to_reorth == 0:
            to_reorth = reorth_every
            if R > 1:
                for l in range(L):
                    if status[l] != RUNNING:
                        continue
                    _gather(Z, sc, l, z, zs0, zc0)
                    if restricted:
                        project_tangent_sc(y1, X1, minv, zs0, zc0)
                    orthonormalize(X1, w, logsum[l])
                    _scatter(z, zs0, zc0, Z, sc, l)
                    if not isfinite(logsum[l, R - 2]):
                        _stop(l, NONFINITE, counter[0], Z, sc, status, stopped, frozen)
        if ev < events.size and counter[0] == events[ev]:
            for l in range(L):
                if status[l] == RUNNING:
                    for r in range(k):
                        event_logs[ev, l, r] = logsum[l, r]
            ev += 1
    running = 0
    for l in range(L):
        if status[l] == RUNNING:
            running += 1
        else:
            for i in range(D):
                Z[i, l] = frozen[i, l]
            for j in range(n):
                sc[0, j, l] = frozen[D + j, l]
                sc[1, j, l] = frozen[D + n + j, l]
    return running


@njit(cache=True)
def _stop(l, st, step, Z, sc, status, stopped, frozen):
    """Stop lane l with status st at the global step ``step``, freezing its state."""
    status[l] = st
    stopped[l] = step
    D = Z.shape[0]
    n = sc.shape[1]
    for i in range(D):
        frozen[i, l] = Z[i, l]
    for j in range(n):
        frozen[D + j, l] = sc[0, j, l]
        frozen[D + n + j, l] = sc[1, j, l]


def _same_system(a, b) -> bool:
    """Whether two `RotorSystem` s are the same system (masses, weights and level)."""
    return a is b or (type(a) is type(b) and a.n == b.n and a.level == b.level
                      and np.array_equal(a.masses, b.masses)
                      and np.array_equal(a.weights, b.weights))


_NO_EVENTS = np.empty(0, dtype=np.int64)
_NO_LOGS = np.empty((0, 0, 0))


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
    ``status`` (L,) and ``stopped`` (L,) (global step of a stopped lane).
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
                    and f.steps == 0)
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
        self.counter = np.zeros(1, dtype=np.int64)
        self.status = np.full(L, RUNNING, dtype=np.int64)
        self.stopped = np.zeros(L, dtype=np.int64)
        self.frozen = np.zeros((self.Z.shape[0] + 2 * self.system.n, L))

    @property
    def steps(self) -> int:
        return int(self.counter[0])

    def lane(self, l):
        """Lane l's stacked state Z, shape (1 + k, 2N) (a copy)."""
        return self.Z[:, l].reshape(-1, 2 * self.system.n).copy()

    def store(self, l, flow) -> None:
        """Lane l's whole state (stacked state, sin/cos, step counter, log-norm sums) into the
        `TangentFlow` ``flow``: what ``flow`` would hold had it advanced alone."""
        flow.load_state({"Z": self.lane(l), "sc": self.sc[:, :, l], "counter": self.counter,
                         "logsum": self.logsum[l]})

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
        return lanes_kernel(self.Z, self.sc, self.counter, self.status, self.stopped,
                            self.frozen, sys_.minv, sys_.masses, sys_.weights, sys_.level,
                            self.speed, self.dt, int(nsteps), self.reorth_every, self.w,
                            self.restricted, self.project_every, self.logsum, events,
                            event_logs)

    def error(self, l, where):
        """The exception `TangentFlow.advance` raises for the stopped lane l (``where`` names
        the route)."""
        return status_error(int(self.status[l]), int(self.stopped[l]) * self.dt, where)
