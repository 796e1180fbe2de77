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

import numpy as np

from ..compilation import announces_compilation
from ..geometry.checks import finite_array, option
from ..geometry.projection import invariants
from ..geometry.system import RotorSystem
from . import loop as D
from .dense import DenseSolution
from .trajectory import IntegrationResult
from .events import EventTracker, check_events
from .progress import progress_reporter
from .status import (CAP_FRACTION, DT_SPEED, FINISHED, RUNNING, SINGULAR_S, ChartDomainError,
                     IntegrationError, SingularPointError, check_duration, check_step, status_error)
from .ambient_formulation import AmbientFlow
from .chart_formulation import DEFAULT_TAU, ChartFlow

__all__ = ["integrate", "IntegrationResult", "IntegrationError", "SingularPointError",
           "ChartDomainError", "TOLERANCES", "DenseSolution"]

#: Named tolerances of the integrators.
TOLERANCES = {
    # Σ sin²θ below which a point counts as an N = 4 singular point (charts.solvers.status).
    "singular_S": SINGULAR_S,
    # default relative tolerance of DOP853; atol defaults to rtol·min(1, speed).
    "rtol": 1e-10,
    # the smallest rtol accepted (the error estimate is meaningless near rounding level).
    "rtol_min": 1e-15,
    # default RK4 step, in units of 1/speed: the paper's Δt = 0.01 at unit speed.
    "dt_speed": DT_SPEED,
}

_METHODS = {"rk4": D.METHOD_RK4, "dop853": D.METHOD_DOP853}
_FORMULATIONS = {"ambient": AmbientFlow, "chart": ChartFlow}
#: Rows of the every-step output buffer: at least this many, and up to a chunk (at most
#: `_EVERY_STEP_BYTES`): each time it fills, the compiled loop returns to Python (≈ 0.1 ms of
#: dispatch per call).
_EVERY_STEP_BUFFER = 4096
_EVERY_STEP_BYTES = 1 << 24
_LOG_CAPACITY = 1024


def _positive(name, x):
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} must be a positive number, got {x!r}")
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name} must be positive and finite, got {x!r}")
    return float(x)


def _span(t_final, t_span):
    """``(t0, t1)`` from the two ways of giving the interval."""
    if (t_final is None) == (t_span is None):
        raise ValueError("give either t_final (from t = 0) or t_span=(t0, t1), not both")
    if t_span is None:
        if isinstance(t_final, bool) or not isinstance(t_final, (int, float, np.integer, np.floating)) \
                or not math.isfinite(t_final) or t_final < 0:
            raise ValueError(f"t_final must be a finite number >= 0, got {t_final!r}")
        return 0.0, float(t_final)
    try:
        t0, t1 = (float(x) for x in t_span)
    except (TypeError, ValueError):
        raise ValueError(f"t_span must be a pair of numbers (t0, t1), got {t_span!r}") from None
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ValueError(f"t_span must be finite, got {t_span!r}")
    return t0, t1


def _eval_times(t_eval, t0, t1, sign):
    """The t_eval times as integration times s = ±(t − t0) ≥ 0, increasing."""
    te = np.atleast_1d(finite_array("t_eval", t_eval))
    if te.ndim != 1 or te.size == 0:
        raise ValueError(f"t_eval must be a non-empty 1-D array of times, got shape {te.shape}")
    if np.any(sign * np.diff(te) <= 0):
        raise ValueError(f"t_eval must be strictly {'increasing' if sign > 0 else 'decreasing'} "
                         "(monotonic in the direction of integration)")
    if min(te[0], te[-1]) < min(t0, t1) or max(te[0], te[-1]) > max(t0, t1):
        raise ValueError(f"t_eval must lie in t_span = ({t0:g}, {t1:g})")
    s = np.minimum(np.maximum(sign * (te - t0), 0.0), abs(t1 - t0))
    return te, np.maximum.accumulate(s)


@announces_compilation
def integrate(system: RotorSystem, theta0, u0, t_final=None, *, t_span=None, formulation="chart",
              method="dop853", dt=None, rtol=None, atol=None, t_eval=None, dense_output=False,
              events=None, project=False, transport=None, tau=DEFAULT_TAU, chart=None,
              progress=None, chunk_steps=20000) -> IntegrationResult:
    """Integrate the geodesic through (θ₀, u₀) from t = 0 to ``t_final``, or over
    ``t_span = (t0, t1)`` (t1 < t0 integrates backwards), as ``scipy.integrate.solve_ivp``.

    Parameters
    ----------
    system : RotorSystem
    theta0, u0 : array_like, shape (n,)
        Initial point on Σ cos θ = 0 (eq 9) and tangent velocity, Σ uᵢ sin θᵢ = 0 (eq 10).
    t_final : float ≥ 0
        The end time, from t = 0 (the same as ``t_span=(0, t_final)``).
    t_span : (float, float), optional
        ``(t0, t1)``: the state is given at t0.  Backwards (t1 < t0) is exact time reversal
        of the geodesic flow: the run goes forwards from (θ₀, −u₀) and u is negated back.
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
        Sample times in the span, strictly monotonic in the direction of integration;
        default: t0 and every step.
    dense_output : bool
        Also return ``result.sol``, a :class:`DenseSolution`: DOP853's own 7th-order
        interpolant, or the cubic Hermite one for RK4, in the coordinates of each step and
        mapped to ambient (θ, u), so valid across chart switches (``charts.solvers.dense``).
    events : callable or list of callables, optional
        ``event(t, y)`` with y = [θ, u] (+ transported vectors), attributes ``terminal`` and
        ``direction``: SciPy's contract (``charts.solvers.events``); zeros in
        ``result.t_events``, ``result.y_events``.
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
    t0, t1 = _span(t_final, t_span)
    sign = -1.0 if t1 < t0 else 1.0
    t_final = abs(t1 - t0)  # the run below goes from s = 0 to s = t_final
    event_list = check_events(events)
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
        check_step(dt, speed, system.n)
        check_duration(t_final, speed, dt)
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
        check_duration(t_final, speed)
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
    te_user, te = _eval_times(t_eval, t0, t1, sign) if use_eval else (None, np.zeros(0))
    dense = bool(dense_output) or bool(event_list)
    if any(ev[1] for ev in event_list):
        chunk_steps = min(int(chunk_steps), 256)  # bounds the work done past a terminal event

    project = option("project", project, (False, True))
    form_cls = _FORMULATIONS[formulation]
    kw = {"tau": tau, "chart": chart} if formulation == "chart" else {}
    if formulation == "ambient" and (chart is not None or tau != DEFAULT_TAU):
        raise ValueError("tau and chart apply to formulation='chart'")
    form = form_cls(system, project=project, cap_fraction=CAP_FRACTION[method], **kw)
    y, par, ipar = form.initial(theta0, sign * u0, P)
    rhs, step, cap, post, to_amb, invariants = form.hooks(method)
    st, ist = D.new_state(_METHODS[method], t_final, dt, rtol_v, atol_v, float(system.energy(u0)),
                          TOLERANCES["singular_S"], use_eval, int(chunk_steps), dense)
    ny = y.size
    na = (2 + P.shape[0]) * n
    K = np.zeros((16, ny))
    F = np.zeros((7, ny))
    ytmp = np.zeros(ny)
    ynew = np.zeros(ny)
    inv = np.zeros(3)
    log = np.zeros((_LOG_CAPACITY, 3))
    mon = np.zeros(3)
    seg_cap = min(int(chunk_steps), 4096) if dense else 1
    Seg = np.zeros((seg_cap, D.segment_layout(ny, par.size)[3]))
    ISeg = np.zeros((seg_cap, ipar.size), dtype=np.int64)
    sol = DenseSolution(to_amb, ny, par.size, n, na, t0, sign) if dense else None
    tracker = EventTracker(event_list, sol, lambda s: t0 + sign * s) if event_list else None

    ts, rows = [], []
    row0 = np.concatenate([theta0, sign * u0, P.ravel()])  # the t = 0 sample is the input, exactly
    if use_eval:
        first = 1 if te[0] == 0.0 else 0
        if first:
            ts.append(np.array([0.0]))
            rows.append(row0[None, :])
        ist[D.I_IEVAL] = first
        T_out = np.zeros(te.size - first)
        Y_out = np.zeros((te.size - first, na))
    else:  # the loop writes every step into the buffer after the t = 0 row
        # (RK4: room for the whole run unless the cap shortens steps, up to _EVERY_STEP_BYTES)
        expected = math.ceil(t_final / dt) + 2 if method == "rk4" else int(chunk_steps)
        rows_out = max(_EVERY_STEP_BUFFER, min(expected, _EVERY_STEP_BYTES // (8 * na)))
        T_out = np.empty(rows_out)
        Y_out = np.empty((rows_out, na))
        T_out[0] = 0.0
        Y_out[0] = row0
        ist[D.I_NOUT] = 1
    switches = list(form.initial_switches)

    def drain():
        nonlocal T_out, Y_out
        nout = int(ist[D.I_NOUT])
        if not use_eval and nout == T_out.size:  # full: keep it, the loop gets a fresh one
            ts.append(T_out)
            rows.append(Y_out)
            T_out = np.empty_like(T_out)
            Y_out = np.empty_like(Y_out)
            ist[D.I_NOUT] = 0
        switches.extend(form.drain_log(log, ipar))
        if dense:
            sol.extend(Seg, ISeg, int(ist[D.I_NSEG]))
            ist[D.I_NSEG] = 0

    def result(status, s_end):
        nout = int(ist[D.I_NOUT])
        ts.append(T_out[:nout])
        rows.append(Y_out[:nout])
        if len(rows) == 1 and 2 * nout >= Y_out.shape[0]:  # one buffer, mostly used: no copy
            s, Y = ts[0], rows[0]
        else:
            s = np.concatenate(ts)
            Y = np.concatenate(rows, axis=0)
        sw = [(t0 + sign * w[0],) + tuple(w[1:]) for w in switches if w[0] <= s_end]
        keep = slice(0, int(np.searchsorted(s, s_end, side="right")))  # s <= s_end (s increases)
        t = te_user[:s.size][keep] if use_eval else t0 + sign * s[keep]
        Y = Y[keep]
        if sol is not None:
            sol.close(s_end)
        if sign < 0:
            Y[:, n:2 * n] *= -1.0            # back from the forward run from (θ₀, −u₀)
        # rows whose invariants the loop's monitor has not seen (in ``mon`` already): the
        # input row and, with t_eval, every sample (not every sample is a step's end)
        check = np.ones(Y.shape[0], bool) if use_eval else np.arange(Y.shape[0]) == 0
        if tracker is not None and tracker.stop is not None and not use_eval \
                and not (s.size and s[keep][-1] == s_end):
            t = np.append(t, t0 + sign * s_end)  # the terminal event closes the output (SciPy)
            Y = np.concatenate([Y, sol.sample([s_end])])   # (sol's rows are in user time)
            check = np.append(check, True)
        res = _make_result(system, t, Y, check, P.shape[0], mon, sw, ist, status, formulation,
                           method, dict(dt=dt, rtol=rtol_v, atol=atol_v, project=bool(project),
                                        tau=tau if formulation == "chart" else None,
                                        chunk_steps=int(chunk_steps), t_span=[t0, t1]))
        res.sol = sol if dense_output else None
        if tracker is not None:
            res.t_events, res.y_events = tracker.results()
        return res

    status_name = "finished"
    while True:
        status = D.drive(rhs, step, cap, post, to_amb, invariants, y, par, ipar, st, ist, te, T_out,
                         Y_out, log, mon, K, F, ytmp, ynew, inv, Seg, ISeg)
        drain()
        if status < 0:
            t_fail = t0 + sign * st[D.S_T]
            res = result(f"failed at t = {t_fail:.17g}", st[D.S_T])
            raise status_error(status, t_fail, f"{formulation}/{method}", res)
        if tracker is not None and tracker.scan() is not None:
            if bar is not None:
                bar.close()
            return result("event", tracker.stop)
        if status == FINISHED:
            if progress is not None:
                progress(st[D.S_T], t_final)
            if bar is not None:
                bar.close()
            break
        if status == RUNNING and progress is not None and progress(st[D.S_T], t_final) is False:
            status_name = "stopped"
            break
    return result(status_name, st[D.S_T])


def _make_result(system, t, Y, check, k, mon, switches, ist, status, formulation, method, options):
    """The result; the drift of the invariants is the max of the loop's monitor ``mon`` and
    of the rows ``Y[check]`` that it has not seen (the same formula: ``invariants``)."""
    n = system.n
    theta = Y[:, :n]
    u = Y[:, n:2 * n]
    transported = Y[:, 2 * n:].reshape(-1, k, n) if k else None
    F, G, E = invariants(theta[check], u[check], system.masses, system.weights, system.level)
    e0 = float(system.energy(u[0])) if len(u) else 1.0
    drift = {
        "constraint": float(max(mon[0], np.max(np.abs(F), initial=0.0))),
        "tangency": float(max(mon[1], np.max(np.abs(G), initial=0.0))),
        "energy": float(max(mon[2], np.max(np.abs(E - e0) / e0, initial=0.0))),
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
