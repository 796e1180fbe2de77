"""The linkage's flow and tangent vectors advanced together: RK4 (``charts.solvers.rk``) of
``charts.flows.linkage``, projection onto the invariants, Gram–Schmidt re-orthonormalisation
(``charts.solvers.tangent.orthonormalize``, eq 18) and log-norm sums in the one time loop
of the stacked flows (``charts.solvers.driver``) — the linkage's counterpart of
`TangentFlow`, built from the same pieces.

Stacked state Z = [y; ξ¹; …; ξᵏ], shape (1 + k, 14).  After global step i: y is projected
onto F = 0, J v = 0 and the energy (``project_state_linkage``) when i % project_every == 0
(0: never); the ξ are projected onto T_r and re-orthonormalised in the product Σ Mⱼⱼ δqⱼ²
(the kinetic metric on positions: for a massless disk Σ δθᵢ², the pulled-back metric) when
i % reorth_every == 0.  The phases follow a global step counter, so chunked runs give
bit-identical numbers.
"""
from __future__ import annotations

from collections import namedtuple
from functools import cache

import numpy as np
from numba import types
from ..jit import njit

from ..flows.linkage import NY, linkage_rates
from ..geometry.linkage import PROJ_OK, project_state_linkage, project_tangent_linkage
from .rk import RHS_SIG, RHS_TYPE, rk4_step
from .driver import Phases, borrowed, keep_alive, log_sums, no_record, phased_loop
from .status import NONFINITE, RUNNING, IntegrationError
from .tangent import StackedFlow, orthonormalize

__all__ = ["LinkageFlow", "linkage_rhs", "linkage_kernel", "DegenerateMetricError", "DEGENERATE",
           "DEPENDENT", "GRAM_MIN"]

#: Status: the KKT matrix became singular (massless disk where C = ∂F/∂(x, y, α) loses rank).
DEGENERATE = -10
#: Status: a projection met J Jᵀ singular (the four constraints dependent at the state), so
#: it could not project; the kernel stops before using its factors.
DEPENDENT = -11
#: Smallest health det(C̃ᵀC̃) of `linkage_rhs` (``charts.flows.linkage.disk_gram``) accepted in a
#: step with a massless disk (typical values on the default linkage ρ = 2ε: 7·10² for ε ≤ 0.2).
GRAM_MIN = 1e-12


@cache
def linkage_rhs():
    """`charts.flows.linkage.linkage_rates` compiled with the steppers' signature
    (``charts.solvers.rk.RHS_SIG``) on first use, cached on disk."""
    return njit(RHS_SIG, cache=True)(linkage_rates)


class DegenerateMetricError(IntegrationError):
    """The pulled-back metric degenerated (the disk could move with the rotors at rest)."""


#: The named state of the linkage's stacked flow in the time loop
#: (``charts.solvers.driver.phased_loop``): the flat Z = [y; X] and its views, the linkage's
#: parameters and masses, the speed, the step, the inner product's weights, the log-norm sums
#: and their event logs, the smallest health seen, whether the disk is massless, the RK4 work
#: arrays, the rows and the length of Z.
LinkageStack = namedtuple("LinkageStack", [
    "Zf", "y", "X", "par", "mass", "speed", "dt", "w", "logsum", "event_logs", "health",
    "massless", "K", "zt", "zn", "R", "L"])


@njit(cache=True, inline="always")
def linkage_step(fl, f):
    """One RK4 step of the linkage's rates ``f`` (`linkage_rhs`); NONFINITE, or DEGENERATE
    where the step's health (the smallest det(C̃ᵀC̃) of its stages) is not above 0 (`GRAM_MIN`
    with a massless disk), leaving Z at the step's start; the smallest health into
    ``fl.health[0]``."""
    zn = fl.zn
    hmin = rk4_step(f, fl.Zf, fl.dt, fl.par, fl.K, fl.zt, zn)
    if not np.isfinite(hmin) or not np.isfinite(zn[0] + zn[NY - 1]):
        return NONFINITE
    if not hmin > (GRAM_MIN if fl.massless else 0.0):
        return DEGENERATE
    Zf = fl.Zf
    for i in range(fl.L):
        Zf[i] = zn[i]
    fl.health[0] = min(fl.health[0], hmin)
    return RUNNING


@njit(cache=True, inline="always")
def linkage_project(fl):
    """The state onto F = 0, J v = 0 and its energy (`project_state_linkage`); DEPENDENT
    where J Jᵀ is singular."""
    if project_state_linkage(fl.y, fl.par, fl.mass, fl.speed) != PROJ_OK:
        return DEPENDENT
    return RUNNING


@njit(cache=True, inline="always")
def linkage_reorth(fl):
    """The vectors onto T_r (`project_tangent_linkage`; DEPENDENT where J Jᵀ is singular) and
    re-orthonormalised in the kinetic metric (eq 18, logs added to the sums; NONFINITE where
    they overflow)."""
    if fl.R > 1:
        if project_tangent_linkage(fl.y, fl.X, fl.par) != PROJ_OK:
            return DEPENDENT
        orthonormalize(fl.X, fl.w, fl.logsum)
        if not np.isfinite(fl.logsum[fl.R - 2]):
            return NONFINITE
    return RUNNING


def _kernel(f, Z, par, mass, speed, dt, nsteps, counter, reorth_every, project_every, w, logsum,
            events, event_logs, health, massless):
    """Advance Z, shape (1 + k, 14), by ``nsteps`` RK4 steps of ``f`` (`linkage_rhs`) in the
    one time loop of the stacked flows (``charts.solvers.driver.phased_loop``) with the
    linkage's hooks.  Stores ``logsum`` in ``event_logs[e]`` at global step ``events[e]``;
    health[0] keeps the smallest health seen (``massless``: stop where it drops below
    `GRAM_MIN`).  Returns (status, steps done); Z is then at the start of a failing step."""
    R = Z.shape[0]
    L = R * NY
    K = np.empty((4, L))
    zt = np.empty(L)
    zn = np.empty(L)
    b = borrowed
    fl = LinkageStack(b(Z.reshape(L)), b(Z[0]), b(Z[1:]), b(par), b(mass), speed, dt, b(w),
                      b(logsum), b(event_logs), b(health), massless, b(K), b(zt), b(zn), R, L)
    code = phased_loop(fl, nsteps, counter, Phases(project_every, reorth_every, 0, 0), events,
                       linkage_step, f, linkage_project, linkage_reorth, log_sums, no_record)
    keep_alive((K, zt, zn))             # the work arrays, borrowed above, live until here
    return code


_f8, _i8 = types.float64, types.int64
_KERNEL_SIG = types.Tuple((_i8, _i8))(
    RHS_TYPE, _f8[:, ::1], _f8[::1], _f8[::1], _f8, _f8, _i8, _i8[::1], _i8, _i8, _f8[::1],
    _f8[::1], _i8[::1], _f8[:, ::1], _f8[::1], types.boolean)


@cache
def linkage_kernel():
    """`_kernel` compiled with its signature on first use (cached on disk; the right-hand side
    is a first-class function argument, as in ``charts.solvers.loop``)."""
    return njit(_KERNEL_SIG, cache=True)(_kernel)


_NO_ROWS = np.empty((0, 0))
_NO_EVENTS = np.empty(0, dtype=np.int64)


class LinkageFlow(StackedFlow):
    """The linkage state (q, v) and ``k`` tangent vectors (random, projected onto T_r and
    orthonormalised; ``seed``), advanced by `linkage_kernel`.

    Parameters: ``system`` a `LinkageSystem`; (q, v) a validated state; ``dt`` the RK4 step;
    ``reorth_every``, ``project_every`` in steps (project_every = 0: never).
    """

    def __init__(self, system, q, v, k, *, dt, reorth_every=1, project_every=100, seed=0):
        self.system = system
        self.dt = float(dt)
        self.par = system.par
        self.w = np.concatenate([system.mass, np.zeros(system.mass.size)])
        self.reorth_every = int(reorth_every)
        self.project_every = int(project_every)
        self.speed = system.speed(v)
        self.Z = np.empty((1 + k, NY))
        self.Z[0] = np.concatenate([q, v])
        if k:
            X = np.random.default_rng(seed).normal(size=(k, NY))
            if project_tangent_linkage(self.Z[0], X, self.par) != PROJ_OK:
                raise ValueError("q is a singular configuration of the linkage (J Jᵀ singular: "
                                 "no tangent space to start the vectors in); check the state "
                                 "with LinkageSystem.check_state")
            orthonormalize(X, self.w, np.zeros(k))
            self.Z[1:] = X
        self.counter = np.zeros(1, dtype=np.int64)
        self.logsum = np.zeros(k)
        self.health = np.array([np.inf])

    def state(self) -> dict:
        """Copies of every array that decides the next step (for checkpoints), as
        `TangentFlow.state`; ``health`` keeps the smallest KKT health seen."""
        return {"Z": self.Z.copy(), "counter": self.counter.copy(),
                "logsum": self.logsum.copy(), "health": self.health.copy()}

    def load_state(self, a) -> None:
        for key, arr in self.state().items():
            getattr(self, key)[...] = a[key]

    def advance(self, nsteps, *, events=None, event_logs=None, where="linkage RK4"):
        """Advance ``nsteps`` steps; DegenerateMetricError / IntegrationError on failure."""
        if events is None:
            events, event_logs = _NO_EVENTS, _NO_ROWS
        status, done = linkage_kernel()(linkage_rhs(), self.Z, self.par, self.system.mass,
                                        self.speed, self.dt, int(nsteps), self.counter,
                                        self.reorth_every, self.project_every, self.w,
                                        self.logsum, events, event_logs, self.health,
                                        self.system.massless_disk)
        t = self.steps * self.dt
        if status == DEGENERATE:
            raise DegenerateMetricError(
                f"{where}: the kinetic metric degenerated at t = {t:.17g} (the disk can move "
                f"while the rotors stand still: ∂F/∂(x, y, α) lost rank, det(C̃ᵀC̃) < "
                f"{GRAM_MIN:g}). Give the disk inertia: LinkageSystem(..., disk_mass=1e-2, "
                "disk_inertia=1e-3), or use rho > eps (docs/linkage.md).")
        if status == DEPENDENT:
            raise IntegrationError(
                f"{where}: the linkage's constraints became dependent at t = {t:.17g} (J Jᵀ "
                "singular: the state cannot be projected back onto the manifold). Start from "
                "another state or reduce dt.")
        if status != RUNNING:
            raise IntegrationError(f"{where}: the state became non-finite at t = {t:.17g}; "
                                   "reduce dt.")
