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

The pieces, each in its own home as SciPy's ``solve_ivp`` keeps them: the checked arguments
(``charts.solvers.integration_arguments``), the run of the compiled loop
(``charts.solvers.loop_run``, the ``OdeSolver``), the result (``charts.solvers.trajectory``,
assembled by ``charts.solvers.integration_output``), dense output (``charts.solvers.dense``)
and events (``charts.solvers.events``).
"""
from __future__ import annotations

from ..jit.compilation import announces_compilation
from ..geometry.system import RotorSystem
from .chart_formulation import DEFAULT_TAU
from .dense import DenseSolution
from .events import EventTracker
from .integration_arguments import TOLERANCES, check_arguments
from .integration_output import collect_result
from .loop_run import LoopRun
from .status import FINISHED, RUNNING, ChartDomainError, IntegrationError, SingularPointError, status_error
from .trajectory import IntegrationResult

__all__ = ["integrate", "IntegrationResult", "IntegrationError", "SingularPointError",
           "ChartDomainError", "TOLERANCES", "DenseSolution"]


@announces_compilation(variant=("formulation", "method"))
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
    args = check_arguments(system, theta0, u0, t_final, t_span=t_span, formulation=formulation,
                           method=method, dt=dt, rtol=rtol, atol=atol, t_eval=t_eval,
                           dense_output=dense_output, events=events, project=project,
                           transport=transport, tau=tau, chart=chart, progress=progress,
                           chunk_steps=chunk_steps, default_tau=DEFAULT_TAU)
    run = LoopRun(args)
    tracker = EventTracker(args.events, run.sol, args.user_time) if args.events else None
    status_name = "finished"
    while True:
        status = run.advance()
        if status < 0:
            t_fail = args.user_time(run.s)
            res = collect_result(args, run, f"failed at t = {t_fail:.17g}", run.s, tracker)
            raise status_error(status, t_fail, f"{args.formulation}/{args.method}", res)
        if tracker is not None and tracker.scan() is not None:
            _close(args.bar)
            return collect_result(args, run, "event", tracker.stop, tracker)
        if status == FINISHED:
            if args.progress is not None:
                args.progress(run.s, args.t_final)
            _close(args.bar)
            break
        if status == RUNNING and args.progress is not None \
                and args.progress(run.s, args.t_final) is False:
            status_name = "stopped"
            break
    return collect_result(args, run, status_name, run.s, tracker)


def _close(bar):
    if bar is not None:
        bar.close()
