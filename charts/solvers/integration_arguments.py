"""The arguments of ``integrate``, checked once and held as one record.

:func:`check_arguments` turns the user's call into an :class:`IntegrationArguments` (SciPy's
``solve_ivp`` checks its arguments the same way before it builds a solver): the time span in
either form, the state on the manifold (eqs 9, 10), the vectors to transport, the method's
settings (RK4's step, DOP853's tolerances), sample times, events and progress.  Every bad
argument is a ``ValueError`` that names it, raised here, before anything is compiled or run.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..geometry.checks import finite_array, number, option, shown
from ..geometry.checks import flag
from ..geometry.system import RotorSystem
from .events import check_events
from .progress import progress_reporter
from .status import DT_SPEED, SINGULAR_S, check_duration, check_step

__all__ = ["IntegrationArguments", "check_arguments", "TOLERANCES", "METHODS", "FORMULATIONS"]

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

METHODS = ("rk4", "dop853")
FORMULATIONS = ("ambient", "chart")
#: Most accepted steps between two progress calls (a chunk's arrays are sized by it).
MAX_CHUNK_STEPS = 10 ** 9


@dataclass(frozen=True)
class IntegrationArguments:
    """One checked call of ``integrate``.

    The run goes forwards in integration time s from 0 to ``t_final`` = |t1 − t0|; user time
    is t = t0 + sign·s (``sign`` = −1 integrates backwards: time reversal, u₀ → −u₀).
    ``s_eval`` are the sample times as integration times (empty without ``t_eval``); ``P``,
    shape (k, n), the vectors to transport; ``dt`` is 0 for DOP853 and ``rtol``/``atol`` 0
    for RK4."""

    system: RotorSystem
    theta0: np.ndarray
    u0: np.ndarray
    P: np.ndarray
    t0: float
    t1: float
    sign: float
    t_final: float
    speed: float
    formulation: str
    method: str
    dt: float
    rtol: float
    atol: float
    t_eval: np.ndarray | None
    s_eval: np.ndarray
    dense_output: bool
    events: list
    project: bool
    tau: float
    chart: int | None
    chunk_steps: int
    progress: Callable | None
    bar: object

    @property
    def use_eval(self) -> bool:
        return self.t_eval is not None

    @property
    def record_segments(self) -> bool:
        """Every step's interpolant is kept: for dense output and for locating events."""
        return self.dense_output or bool(self.events)

    def user_time(self, s):
        """The user's time at integration time s."""
        return self.t0 + self.sign * s

    def params(self) -> dict:
        """The system and the initial state a result records (``IntegrationResult.params``):
        with `options`, the whole call."""
        sys_ = self.system
        return dict(n=sys_.n, masses=sys_.masses.tolist(), weights=sys_.weights.tolist(),
                    level=float(sys_.level), speed=float(self.speed),
                    theta0=np.asarray(self.theta0, float).tolist(),
                    u0=np.asarray(self.u0, float).tolist(), n_transported=int(self.P.shape[0]))

    def options(self) -> dict:
        """The settings a result records (``IntegrationResult.options``), only those that
        apply, so that a saved file carries nothing that meant nothing to the run: RK4's
        ``dt`` or DOP853's ``rtol`` and ``atol``; ``project``; the chart formulation's
        ``tau`` and ``chart`` (the starting chart asked for; None: the best conditioned
        one); ``chunk_steps``, ``t_span`` and ``output`` ("t_eval": the samples are at the
        times ``t_eval`` asked for, which the file's ``t`` holds; "steps": at every step)."""
        out = dict(dt=self.dt) if self.method == "rk4" else dict(rtol=self.rtol, atol=self.atol)
        out["project"] = self.project
        if self.formulation == "chart":
            out.update(tau=self.tau, chart=None if self.chart is None else int(self.chart))
        out.update(chunk_steps=self.chunk_steps, t_span=[self.t0, self.t1],
                   output="t_eval" if self.use_eval else "steps")
        return out


def check_arguments(system, theta0, u0, t_final, *, t_span, formulation, method, dt, rtol, atol,
                    t_eval, dense_output, events, project, transport, tau, chart, progress,
                    chunk_steps, default_tau) -> IntegrationArguments:
    """The checked :class:`IntegrationArguments` of an ``integrate`` call (its parameters,
    same names); ValueError naming the first bad one."""
    if not isinstance(system, RotorSystem):
        raise ValueError(f"system must be a RotorSystem, got {type(system).__name__}")
    if not isinstance(formulation, str) or formulation not in FORMULATIONS:
        raise ValueError(f"unknown formulation {shown(formulation)}; use one of "
                         f"{sorted(FORMULATIONS)}")
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"unknown method {shown(method)}; use one of {sorted(METHODS)}")
    dense_output = flag("dense_output", dense_output)
    t0, t1 = _span(t_final, t_span)
    sign = -1.0 if t1 < t0 else 1.0
    duration = abs(t1 - t0)
    event_list = check_events(events)
    theta0, u0, speed = _initial_state(system, theta0, u0)
    P = _transported(system, theta0, transport)
    dt, rtol, atol = _method_settings(method, dt, rtol, atol, speed, system.n, duration)
    if isinstance(chunk_steps, bool) or not isinstance(chunk_steps, (int, np.integer)) \
            or not 1 <= chunk_steps <= MAX_CHUNK_STEPS:
        raise ValueError(f"chunk_steps must be a positive integer (at most "
                         f"{MAX_CHUNK_STEPS}), got {shown(chunk_steps)}")
    progress, bar = _progress(progress, duration, system.n)
    te_user, s_eval = _eval_times(t_eval, t0, t1, sign) if t_eval is not None else (None, np.zeros(0))
    chunk_steps = int(chunk_steps)
    if any(ev[1] for ev in event_list):
        chunk_steps = min(chunk_steps, 256)  # bounds the work done past a terminal event
    project = option("project", project, (False, True))
    if formulation == "ambient" and (chart is not None or tau != default_tau):
        raise ValueError("tau and chart apply to formulation='chart'")
    return IntegrationArguments(
        system=system, theta0=theta0, u0=u0, P=P, t0=t0, t1=t1, sign=sign, t_final=duration,
        speed=speed, formulation=formulation, method=method, dt=dt, rtol=rtol, atol=atol,
        t_eval=te_user, s_eval=s_eval, dense_output=bool(dense_output), events=event_list,
        project=bool(project), tau=tau, chart=chart, chunk_steps=chunk_steps,
        progress=progress, bar=bar)


def _positive(name, x):
    """``x`` as a positive finite float (the typed layer's `number`: a float32 is the decimal
    it prints, a 0-d array the number it holds)."""
    x = number(name, x)
    if not x > 0:
        raise ValueError(f"{name} must be positive and finite, got {x!r}")
    return x


def _span(t_final, t_span):
    """``(t0, t1)`` from the two ways of giving the interval."""
    if (t_final is None) == (t_span is None):
        raise ValueError("give either t_final (from t = 0) or t_span=(t0, t1), not both")
    if t_span is None:
        given = t_final
        try:
            t_final = number("t_final", t_final)
        except ValueError:
            t_final = math.nan
        if not t_final >= 0:
            raise ValueError(f"t_final must be a finite number >= 0, got {shown(given)}")
        return 0.0, t_final
    try:
        t0, t1 = (float(x) for x in t_span)
    except (TypeError, ValueError):
        raise ValueError(f"t_span must be a pair of numbers (t0, t1), got {t_span!r}") from None
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ValueError(f"t_span must be finite, got {t_span!r}")
    return t0, t1


def _initial_state(system, theta0, u0):
    """(θ₀, u₀, speed) checked: on the manifold, not at a singular point, moving."""
    theta0, u0 = system.check_state(theta0, u0, ("theta0", "u0"))
    S0 = float(np.sum(np.sin(theta0) ** 2))
    if S0 < TOLERANCES["singular_S"]:
        raise ValueError(f"theta0 is a singular point of the manifold (sum(sin^2 theta) = {S0:.1e}); "
                         "the tangent space is not defined there")
    speed = float(system.speed(u0))
    if not speed > 0:
        raise ValueError("u0 is zero: the geodesic is a point; give a nonzero velocity")
    return theta0, u0, speed


def _transported(system, theta0, transport):
    """The vectors to transport, shape (k, n), each checked tangent at θ₀."""
    n = system.n
    if transport is None:
        return np.zeros((0, n))
    P = finite_array("transport", transport)
    if P.ndim == 1:
        P = P[None, :]
    if P.ndim != 2 or P.shape[1] != n:
        raise ValueError(f"transport must have shape (k, {n}) or ({n},), got {np.shape(transport)}")
    return np.array([system.check_tangent(theta0, p, "transport vector") for p in P]).reshape(-1, n)


def _method_settings(method, dt, rtol, atol, speed, n, t_final):
    """(dt, rtol, atol): RK4's step (default 0.01/speed) or DOP853's tolerances."""
    if method == "rk4":
        if rtol is not None or atol is not None:
            raise ValueError("rtol/atol apply to method='dop853'; rk4 takes dt")
        dt = TOLERANCES["dt_speed"] / speed if dt is None else _positive("dt", dt)
        check_step(dt, speed, n)
        check_duration(t_final, speed, dt)
        return dt, 0.0, 0.0
    if dt is not None:
        raise ValueError("dt applies to method='rk4'; dop853 takes rtol/atol")
    rtol = TOLERANCES["rtol"] if rtol is None else _positive("rtol", rtol)
    if rtol < TOLERANCES["rtol_min"]:
        raise ValueError(f"rtol={rtol:g} is below {TOLERANCES['rtol_min']:g}, where the error "
                         "estimate is dominated by rounding; use a larger rtol")
    atol = rtol * min(1.0, speed) if atol is None else _positive("atol", atol)
    check_duration(t_final, speed)
    return 0.0, rtol, atol


def _progress(progress, t_final, n):
    """(callable(t, t_final) or None, the bar to close or None)."""
    if progress is True:  # a bar over simulated time; the callable form may also stop the run
        bar = progress_reporter(True, t_final, f"integrate N={n}")

        def update(t, total):
            bar.update(t - bar.done)
        return update, bar
    if progress is False or progress is None:
        return None, None
    if not callable(progress):
        raise ValueError("progress must be True, False, None or callable(t, t_final)")
    return progress, None


def _eval_times(t_eval, t0, t1, sign):
    """The t_eval times, and as integration times s = ±(t − t0) ≥ 0, increasing."""
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
