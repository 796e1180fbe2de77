"""``integrate``: geodesics of the rotor manifold, in the ambient or the chart formulation.

Both formulations return ambient angles and velocities, so their results compare directly:

* ``formulation="ambient"`` — eq (8) (+ eq (19) for transported vectors), optionally
  projected back onto the invariants after every step (``charts.solvers.ambient_formulation``);
* ``formulation="chart"`` — eq (14) (+ eq (16)) in the atlas of N charts × 2 branches, with
  switching to the best conditioned chart (``charts.solvers.chart_formulation``).

``method="rk4"`` is the classical fixed-step method of the paper; ``method="dop853"`` the
adaptive 8th-order method (``charts.solvers.rk``).  The loop runs compiled, in chunks of
``chunk_steps`` accepted steps; between chunks ``progress(t, t_final)`` is called, and
returning ``False`` stops the run with everything computed so far.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry.projection import invariants
from ..geometry.system import RotorSystem
from . import loop as D
from .progress import progress_reporter
from .status import (CAP_FRACTION, FINISHED, RUNNING, SINGULAR_S, ChartDomainError,
                     IntegrationError, SingularPointError, status_error)
from .ambient_formulation import AmbientFlow
from .chart_formulation import DEFAULT_TAU, ChartFlow

__all__ = ["integrate", "IntegrationResult", "IntegrationError", "SingularPointError",
           "ChartDomainError", "TOLERANCES"]

#: Named tolerances of the integrators.
TOLERANCES = {
    # Σ sin²θ below which a point counts as an N = 4 singular point (charts.solvers.status).
    "singular_S": SINGULAR_S,
    # default relative tolerance of DOP853; atol defaults to rtol·min(1, speed).
    "rtol": 1e-10,
    # the smallest rtol accepted (the error estimate is meaningless near rounding level).
    "rtol_min": 1e-15,
    # default RK4 step, in units of 1/speed: the paper's Δt = 0.01 at unit speed.
    "dt_speed": 0.01,
}

_METHODS = {"rk4": D.METHOD_RK4, "dop853": D.METHOD_DOP853}
_FORMULATIONS = {"ambient": AmbientFlow, "chart": ChartFlow}
_EVERY_STEP_BUFFER = 4096
_LOG_CAPACITY = 1024


@dataclass
class IntegrationResult:
    """Samples of a geodesic, in ambient coordinates for both formulations.

    Attributes
    ----------
    t : ndarray, shape (m,)
    theta, u : ndarray, shape (m, n)
        Ambient angles (continuous, not wrapped) and velocities dθ/dt.
    transported : ndarray, shape (m, k, n), or None
        The transported vectors (eq 16 / eq 19), ambient components.
    switches : list of (t, from_chart, to_chart)
        Chart switches, in order (chart formulation; empty for the ambient one).
    drift : dict
        Max over every accepted step and every sample of ``constraint`` = |Σ cos θ|,
        ``tangency`` = |Σ uᵢ sin θᵢ|, ``energy`` = |E − E₀|/E₀; with ``transport``, also
        ``transport`` = max change of the Gram matrix of (u, p¹…pᵏ) relative to |u|·|p|.
    n_steps, n_rejected, n_rhs : int
        Accepted steps, rejected DOP853 attempts, right-hand-side evaluations.
    status : str
        ``"finished"`` or ``"stopped"`` (by ``progress``), or the error status on
        ``IntegrationError.result``.
    """

    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    transported: np.ndarray | None
    switches: list
    drift: dict
    n_steps: int
    n_rejected: int
    n_rhs: int
    status: str
    formulation: str
    method: str
    options: dict = field(default_factory=dict)

    def __repr__(self):
        return (f"IntegrationResult({self.formulation}/{self.method}, {self.t.size} samples, "
                f"t = {self.t[-1] if self.t.size else 0.0:g}, {len(self.switches)} switches, "
                f"{self.n_steps} steps, status={self.status!r})")


def _positive(name, x):
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} must be a positive number, got {x!r}")
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name} must be positive and finite, got {x!r}")
    return float(x)


def integrate(system: RotorSystem, theta0, u0, t_final, *, formulation="chart", method="dop853",
              dt=None, rtol=None, atol=None, t_eval=None, project=False, transport=None,
              tau=DEFAULT_TAU, chart=None, progress=None, chunk_steps=20000) -> IntegrationResult:
    """Integrate the geodesic through (θ₀, u₀) from t = 0 to ``t_final``.

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : array_like, shape (n,)
        Initial point on Σ cos θ = 0 (eq 9) and tangent velocity, Σ uᵢ sin θᵢ = 0 (eq 10).
    t_final : float ≥ 0
    formulation : {"chart", "ambient"}
        Eq (14)/(16) in switching charts, or eq (8)/(19) in ambient angles.
    method : {"dop853", "rk4"}
    dt : float, optional (rk4 only)
        Step; default 0.01/|u₀|.  Steps are shortened to land on ``t_eval`` and ``t_final``
        and, near N = 4 singular points and chart boundaries, to move at most
        ``charts.solvers.status.CAP_FRACTION`` of the distance to them.
    rtol, atol : float, optional (dop853 only)
        Local error tolerances, default 1e-10 and rtol·min(1, |u₀|).
    t_eval : array_like, shape (m,), optional
        Strictly increasing sample times in [0, t_final]; default: t = 0 and every step.
    project : bool
        Ambient: project onto constraint, tangency and energy after every step.
        Chart: rescale the velocity to the initial energy after every step (constraint
        and tangency hold by construction).
    transport : array_like, shape (k, n) or (n,), optional
        Tangent vectors at θ₀ to parallel-transport along the geodesic.
    tau : float in (0, 1)
        Chart switching threshold (chart formulation), see ``charts.solvers.chart_formulation``.
    chart : int, optional
        Initial chart (default: the best conditioned one); left at t = 0 if the rule says so.
    progress : bool or callable(t, t_final) -> bool, optional
        True: a progress bar.  A callable is called after every chunk; returning ``False``
        stops the run early.
    chunk_steps : int
        Accepted steps per compiled chunk.

    Returns
    -------
    IntegrationResult

    Raises
    ------
    ValueError
        Bad input: non-finite or off-manifold state, dt ≤ 0, t_final < 0, unknown
        formulation or method, options of the other method, bad ``t_eval``.
    SingularPointError, ChartDomainError, IntegrationError
        The run could not be completed; ``err.result`` holds the samples up to the failure.
    """
    if not isinstance(system, RotorSystem):
        raise ValueError(f"system must be a RotorSystem, got {type(system).__name__}")
    if formulation not in _FORMULATIONS:
        raise ValueError(f"unknown formulation {formulation!r}; use one of {sorted(_FORMULATIONS)}")
    if method not in _METHODS:
        raise ValueError(f"unknown method {method!r}; use one of {sorted(_METHODS)}")
    if isinstance(t_final, bool) or not isinstance(t_final, (int, float, np.integer, np.floating)) \
            or not math.isfinite(t_final) or t_final < 0:
        raise ValueError(f"t_final must be a finite number >= 0, got {t_final!r}")
    t_final = float(t_final)
    theta0, u0 = system.check_state(theta0, u0)
    S0 = float(np.sum(np.sin(theta0) ** 2))
    if S0 < TOLERANCES["singular_S"]:
        raise ValueError(f"theta0 is a singular point of the manifold (sum(sin^2 theta) = {S0:.1e}); "
                         "the tangent space is not defined there")
    speed = float(system.speed(u0))
    if not speed > 0:
        raise ValueError("u0 is zero: the geodesic is a point; give a nonzero velocity")
    n = system.n
    if transport is None:
        P = np.zeros((0, n))
    else:
        P = np.array(transport, dtype=float)
        if P.ndim == 1:
            P = P[None, :]
        if P.ndim != 2 or P.shape[1] != n:
            raise ValueError(f"transport must have shape (k, {n}) or ({n},), got {np.shape(transport)}")
        P = np.array([system.check_tangent(theta0, p, "transport vector") for p in P]).reshape(-1, n)
    if method == "rk4":
        if rtol is not None or atol is not None:
            raise ValueError("rtol/atol apply to method='dop853'; rk4 takes dt")
        dt = TOLERANCES["dt_speed"] / speed if dt is None else _positive("dt", dt)
        rtol_v = atol_v = 0.0
    else:
        if dt is not None:
            raise ValueError("dt applies to method='rk4'; dop853 takes rtol/atol")
        rtol_v = TOLERANCES["rtol"] if rtol is None else _positive("rtol", rtol)
        if rtol_v < TOLERANCES["rtol_min"]:
            raise ValueError(f"rtol={rtol_v:g} is below {TOLERANCES['rtol_min']:g}, where the error "
                             "estimate is dominated by rounding; use a larger rtol")
        atol_v = rtol_v * min(1.0, speed) if atol is None else _positive("atol", atol)
        dt = 0.0
    if isinstance(chunk_steps, bool) or not isinstance(chunk_steps, (int, np.integer)) or chunk_steps < 1:
        raise ValueError(f"chunk_steps must be a positive integer, got {chunk_steps!r}")
    bar = None
    if progress is True:  # a bar over simulated time; the callable form may also stop the run
        bar = progress_reporter(True, t_final, f"integrate N={system.n}")

        def progress(t, total):
            bar.update(t - bar.done)
    elif progress is False:
        progress = None
    elif progress is not None and not callable(progress):
        raise ValueError("progress must be True, False, None or callable(t, t_final)")

    use_eval = t_eval is not None
    if use_eval:
        te = np.array(t_eval, dtype=float).ravel()
        if te.size == 0 or not np.all(np.isfinite(te)):
            raise ValueError("t_eval must be a non-empty array of finite times")
        if np.any(np.diff(te) <= 0):
            raise ValueError("t_eval must be strictly increasing")
        if te[0] < 0 or te[-1] > t_final:
            raise ValueError(f"t_eval must lie in [0, t_final] = [0, {t_final:g}]")
    else:
        te = np.zeros(0)

    form_cls = _FORMULATIONS[formulation]
    kw = {"tau": tau, "chart": chart} if formulation == "chart" else {}
    if formulation == "ambient" and (chart is not None or tau != DEFAULT_TAU):
        raise ValueError("tau and chart apply to formulation='chart'")
    form = form_cls(system, project=project, cap_fraction=CAP_FRACTION[method], **kw)
    y, par, ipar = form.initial(theta0, u0, P)
    rhs, cap, post, to_amb = form.hooks()
    st, ist = D.new_state(_METHODS[method], t_final, dt, rtol_v, atol_v, float(system.energy(u0)),
                          TOLERANCES["singular_S"], use_eval, int(chunk_steps))
    ny = y.size
    na = (2 + P.shape[0]) * n
    K = np.zeros((16, ny))
    F = np.zeros((7, ny))
    ytmp = np.zeros(ny)
    ynew = np.zeros(ny)
    arow = np.zeros(na)
    log = np.zeros((_LOG_CAPACITY, 3))
    mon = np.zeros(3)
    mpar = np.concatenate([system.masses, system.weights, [system.level]])

    ts, rows = [], []
    row0 = np.concatenate([theta0, u0, P.ravel()])  # the t = 0 sample is the input, exactly
    if use_eval:
        first = 1 if te[0] == 0.0 else 0
        if first:
            ts.append(np.array([0.0]))
            rows.append(row0[None, :])
        ist[D.I_IEVAL] = first
        T_out = np.zeros(te.size - first)
        Y_out = np.zeros((te.size - first, na))
    else:
        ts.append(np.array([0.0]))
        rows.append(row0[None, :])
        T_out = np.zeros(_EVERY_STEP_BUFFER)
        Y_out = np.zeros((_EVERY_STEP_BUFFER, na))
    switches = list(form.initial_switches)

    def drain():
        nout = int(ist[D.I_NOUT])
        if not use_eval and nout:
            ts.append(T_out[:nout].copy())
            rows.append(Y_out[:nout].copy())
            ist[D.I_NOUT] = 0
        switches.extend(form.drain_log(log, ipar))

    def result(status):
        if use_eval:
            nout = int(ist[D.I_NOUT])
            ts.append(T_out[:nout])
            rows.append(Y_out[:nout])
        t = np.concatenate(ts)
        Y = np.concatenate(rows, axis=0)
        return _make_result(system, t, Y, P.shape[0], mon, switches, ist, status, formulation,
                            method, dict(dt=dt, rtol=rtol_v, atol=atol_v, project=bool(project),
                                         tau=tau if formulation == "chart" else None,
                                         chunk_steps=int(chunk_steps)))

    status_name = "finished"
    while True:
        status = D.drive(rhs, cap, post, to_amb, y, par, ipar, st, ist, te, T_out, Y_out, log,
                         mon, mpar, K, F, ytmp, ynew, arow)
        drain()
        if status < 0:
            res = result(f"failed at t = {st[D.S_T]:.17g}")
            raise status_error(status, st[D.S_T], f"{formulation}/{method}", res)
        if status == FINISHED:
            if progress is not None:
                progress(st[D.S_T], t_final)
            if bar is not None:
                bar.close()
            break
        if status == RUNNING and progress is not None and progress(st[D.S_T], t_final) is False:
            status_name = "stopped"
            break
    return result(status_name)


def _make_result(system, t, Y, k, mon, switches, ist, status, formulation, method, options):
    n = system.n
    theta = Y[:, :n]
    u = Y[:, n:2 * n]
    transported = Y[:, 2 * n:].reshape(-1, k, n) if k else None
    F, G, E = invariants(theta, u, system.masses, system.weights, system.level)
    drift = {
        "constraint": float(max(mon[0], np.max(np.abs(F), initial=0.0))),
        "tangency": float(max(mon[1], np.max(np.abs(G), initial=0.0))),
        "energy": float(max(mon[2], np.max(np.abs(E - E[0]) / E[0], initial=0.0))),
    }
    if k:
        V = np.concatenate([u[:, None, :], transported], axis=1)  # (m, k+1, n)
        G = np.einsum("tin,tjn,n->tij", V, V, system.masses)
        norms = np.maximum(np.sqrt(np.diagonal(G[0])), 1e-300)
        drift["transport"] = float(np.max(np.abs(G - G[0]) / np.outer(norms, norms)))
    return IntegrationResult(t=t, theta=theta, u=u, transported=transported, switches=switches,
                             drift=drift, n_steps=int(ist[D.I_NSTEPS]), n_rejected=int(ist[D.I_NREJ]),
                             n_rhs=int(ist[D.I_NRHS]), status=status, formulation=formulation,
                             method=method, options=options)
