"""Hard cases of the integrators: chart boundaries at |sin θₖ| ≈ 1e-8, the N = 4 singular points (close
passes, exact hits, long runs), the N = 3 flat points, speeds from 1e-3 to 1e3, t = 1e5."""
import numpy as np
import pytest

import charts
from charts import IntegrationError, RotorSystem, integrate
from charts.solvers.integrate import TOLERANCES, ChartDomainError, SingularPointError

from scenarios import (FLAT_N3, chart_edge_n3, gauss_sectional_curvature, masses,
                       near_singular_n4, singular_line_n4)

#: Named tolerances, each with its reason.
TOL = {
    # chart vs ambient through a point with |sin θₖ| = 1e-8 (rtol 1e-13, t ≤ 4): as far from
    # the boundary as any other comparison, since the rule left chart k long before.
    "boundary": 1e-9,
    # Near a singular point at distance √S the flow's sensitivity is ≈ 1/S (the sectional
    # curvature there is ≈ −1/S), so an error ε made before the pass comes out as ≈ ε/S.
    # Bounds below: 10 × (local accuracy)/S_min with S_min = 2e-6 — measured values in comments.
    "near_singular_dop853": 10 * 1e-10 / 2e-6,   # rtol 1e-10, ambient: measured 2.3e-5
    "near_singular_rk4": 1e-6,                   # dt 0.01 + projection: measured 1.1e-7 / 1.5e-7
    # the chart formulation's sin θₖ comes from 1 − C², whose relative rounding error near a
    # singular point is ≈ 1e-16/S: at rtol 1e-13 measured 8e-8 against the ambient reference.
    "near_singular_chart": 1e-6,
    # invariants of projected runs: rounding level, accumulated over up to 2e6 steps.
    "projected_invariants": 1e-12,
    # speed scaling: the same geodesic at speed s is the unit-speed one at time s·t; both at
    # rtol 1e-12 (atol scales with speed), compared at unit time 5.
    "speed_scaling": 1e-9,
}


def _state_through(s, th_mid, u_mid, t_before):
    """The state from which the geodesic reaches (th_mid, u_mid) after ``t_before``."""
    back = integrate(s, th_mid, -u_mid, t_before, formulation="ambient", rtol=1e-13,
                     t_eval=[0.0, t_before])
    return back.theta[-1], -back.u[-1]


# -- chart boundaries -------------------------------------------------------------------------
@pytest.mark.parametrize("n", [3, 5])
def test_trajectory_through_sin_theta_1e8(n):
    s = RotorSystem(n)
    rng = np.random.default_rng(n)
    th = rng.uniform(-3, 3, n)
    th[0] = 1e-8
    C = np.cos(th[:-1]).sum()
    while abs(C) >= 1:  # keep the last angle solvable
        th[1:-1] = rng.uniform(-3, 3, n - 2)
        C = np.cos(th[:-1]).sum()
    th[-1] = np.arccos(-C)
    th = s.project_point(th)
    assert abs(np.sin(th[0])) < 2e-8
    u = s.project_tangent(th, rng.normal(size=n))
    u /= s.speed(u)
    th0, u0 = _state_through(s, th, u, 2.0)
    te = np.linspace(0, 4, 401)
    amb = integrate(s, th0, u0, 4.0, formulation="ambient", rtol=1e-13, t_eval=te)
    for method, kw, tol in [("dop853", dict(rtol=1e-13), TOL["boundary"]),
                            ("rk4", dict(dt=0.001), 1e-9)]:  # RK4: (0.001)⁴-level error
        ch = integrate(s, th0, u0, 4.0, formulation="chart", method=method, t_eval=te, **kw)
        assert np.isfinite(ch.theta).all()
        assert np.abs(ch.theta - amb.theta).max() <= tol
        assert abs(np.sin(ch.theta[200, 0])) < 1e-7  # the run did pass the near-boundary point
        # at that moment the current chart is not chart 0
        current = [b for t, a, b in ch.switches if t <= 2.0]
        start_chart = ch.switches[0][1] if ch.switches else None
        chart_at_2 = current[-1] if current else start_chart
        assert chart_at_2 != 0


# -- N = 4 singular points ------------------------------------------------------------------
S4 = RotorSystem(4)


def test_close_pass_of_a_singular_point_is_accurate():
    thc, uc = near_singular_n4(1e-3)
    th0, u0 = _state_through(S4, thc, uc, 2.0)
    te = np.linspace(0, 4, 401)
    ref = integrate(S4, th0, u0, 4.0, formulation="ambient", rtol=1e-13, t_eval=te)
    S = (np.sin(ref.theta) ** 2).sum(1)
    assert 1e-6 < S.min() < 3e-6  # the pass comes within Σ sin²θ ≈ 2e-6
    runs = {
        "near_singular_dop853": integrate(S4, th0, u0, 4.0, formulation="ambient", rtol=1e-10, t_eval=te),
        "near_singular_rk4": integrate(S4, th0, u0, 4.0, formulation="ambient", method="rk4", dt=0.01,
                                       project=True, t_eval=te),
        "near_singular_chart": integrate(S4, th0, u0, 4.0, formulation="chart", rtol=1e-13, t_eval=te),
    }
    chart_rk4 = integrate(S4, th0, u0, 4.0, formulation="chart", method="rk4", dt=0.01, project=True,
                          t_eval=te)
    for key, r in list(runs.items()) + [("near_singular_rk4", chart_rk4)]:
        assert np.isfinite(r.theta).all()
        assert np.abs(r.theta - ref.theta).max() <= TOL[key], key
    assert runs["near_singular_rk4"].drift["constraint"] <= TOL["projected_invariants"]
    assert runs["near_singular_rk4"].drift["energy"] <= TOL["projected_invariants"]
    # the tangent kernel (the analyses' route) cuts its steps into sub-steps, within the cap
    # at their own starts where the point comes closer than the equal plan allows: 1.37e-6
    # through the pass (4.97e-5 with the equal sub-steps planned at each step's start only)
    from charts.solvers.tangent import TangentFlow
    flow = TangentFlow(S4, th0, u0, 0, dt=0.01, project_every=1)
    kernel = [flow.Z[0, :4].copy()]
    for _ in range(400):
        flow.advance(1)
        kernel.append(flow.Z[0, :4].copy())
    assert np.abs(np.array(kernel) - ref.theta).max() < 3e-6
    # the pass is a real deflection, not a straight line: the velocity turns by > 0.1 rad
    cosang = S4.inner(None, ref.u[0], ref.u[-1])
    assert cosang < np.cos(0.1)


@pytest.mark.parametrize("formulation", ["ambient", "chart"])
@pytest.mark.parametrize("method", ["rk4", "dop853"])
def test_trajectory_aimed_exactly_at_a_singular_point_raises(formulation, method):
    # (a − t/2, a − t/2, π − a + t/2, π − a + t/2) lies on the manifold for every t and is a
    # unit-speed geodesic (a straight line with Λ = 0): it reaches (0, 0, π, π) at t = 2a.
    a = 1.0
    th, u = singular_line_n4(a)
    with pytest.raises(SingularPointError, match="singular point") as err:
        integrate(S4, th, u, 3.0, formulation=formulation, method=method, t_eval=np.linspace(0, 3, 31))
    res = err.value.result
    assert np.isfinite(res.theta).all() and np.isfinite(res.u).all()  # never NaN
    assert res.t.size >= 10 and res.t[-1] < 2 * a  # samples before the hit are kept
    np.testing.assert_allclose(res.theta[:, 0], a - res.t / 2, rtol=0, atol=1e-9)  # and right


def test_long_n4_rk4_run_keeps_invariants_at_rounding_level():
    """The paper's setting: RK4, dt = 0.01, N = 4, t = 2e4 (2e6 steps), with projection."""
    th, u = S4.random_state(0)
    r = integrate(S4, th, u, 2e4, formulation="ambient", method="rk4", dt=0.01, project=True,
                  t_eval=np.linspace(0, 2e4, 2001))
    for key in ("constraint", "tangency", "energy"):
        assert r.drift[key] <= TOL["projected_invariants"], r.drift
    S = (np.sin(r.theta) ** 2).sum(1)
    assert np.isfinite(S).all() and S.min() > TOLERANCES["singular_S"]


@pytest.mark.parametrize("formulation", ["ambient", "chart"])
def test_long_run_t1e5_has_bounded_drift(formulation):
    s = RotorSystem(3)
    th, u = s.random_state(5)
    r = integrate(s, th, u, 1e5, formulation=formulation, rtol=1e-10, project=True,
                  t_eval=np.linspace(0, 1e5, 1001))
    for key in ("constraint", "tangency", "energy"):
        assert r.drift[key] <= TOL["projected_invariants"], r.drift
    assert np.isfinite(r.theta).all()
    if formulation == "chart":
        assert len(r.switches) > 1000


# -- N = 3 flat points, speeds -------------------------------------------------------------------
def test_n3_zero_curvature_point():
    s = RotorSystem(3)
    th = np.array(FLAT_N3)  # all cosines vanish: K = 0 (eq 22)
    u = s.project_tangent(th, np.array([1.0, -0.3, 0.2]))
    u /= s.speed(u)
    w = s.project_tangent(th, np.array([0.2, 1.0, 0.0]))
    assert abs(gauss_sectional_curvature(th, u, w, s.masses)) < 1e-30
    te = np.linspace(0, 20, 201)
    amb = integrate(s, th, u, 20.0, formulation="ambient", rtol=1e-13, t_eval=te)
    ch = integrate(s, th, u, 20.0, formulation="chart", rtol=1e-13, t_eval=te)
    assert np.abs(ch.theta - amb.theta).max() <= 1e-9


@pytest.mark.parametrize("formulation", ["ambient", "chart"])
@pytest.mark.parametrize("speed", [1e-3, 1e3])
def test_speed_scaling(formulation, speed):
    s = RotorSystem(4, masses("linear", 4))
    th, u = s.random_state(9)
    te = np.linspace(0, 5, 51)
    one = integrate(s, th, u, 5.0, formulation=formulation, rtol=1e-12, t_eval=te)
    fast = integrate(s, th, speed * u, 5.0 / speed, formulation=formulation, rtol=1e-12,
                     t_eval=te / speed)
    assert np.abs(fast.theta - one.theta).max() <= TOL["speed_scaling"]
    assert np.abs(fast.u / speed - one.u).max() <= TOL["speed_scaling"]
    assert fast.drift["energy"] < 1e-9


# -- failure statuses through the public API ---------------------------------------------------
# A chart is only usable away from its edge sin θₖ = 0, where its metric blows up; the switching
# rule leaves it long before.  With tau → 0 the rule is switched off and a run heading for the
# edge of its chart fails there (at t ≈ sin θ₀/|u₀|) with the domain status: a stage or a step
# outside the chart, or no step left at its boundary (before, depending on how the blow-up of the
# local equations developed in floating point, it could also end non-finite or raise a
# ZeroDivisionError).
# The default tau leaves chart 0 at t = 0 and the same runs finish and agree with the ambient
# formulation.
NO_SWITCHING = 1e-9


def _edge_time(th, u):
    """When θ0 (moving at u0) reaches the end of chart 0's usable part, |sin θ0| =
    CHART_MIN_RATIO·max|sin θ| (the other sines barely change over that time); the run stops
    after 80 % of it at least (the capped steps halve the distance to the edge) and before the
    edge itself."""
    from charts.solvers.status import CHART_MIN_RATIO
    return (abs(np.sin(th[0])) - CHART_MIN_RATIO * np.abs(np.sin(th[1:])).max()) / abs(u[0])


@pytest.mark.parametrize("sin0, error, message", [
    (5e-2, ChartDomainError, "left the domain of the current chart"),
    (1e-3, ChartDomainError, "left the domain of the current chart"),
])
def test_run_kept_in_a_chart_up_to_its_edge_fails_with_a_status(sin0, error, message):
    s = RotorSystem(3)
    th, u = chart_edge_n3(sin0)
    with pytest.raises(error, match=message) as err:
        integrate(s, th, u, 1.0, formulation="chart", method="rk4", dt=0.01, chart=0,
                  tau=NO_SWITCHING)
    assert type(err.value) is error
    res = err.value.result
    assert res.status.startswith("failed at t = ") and res.t.size >= 3 and res.switches == []
    # it failed at the edge: θ₀ (moving at u₀) reaches 0 after ≈ sin0/|u₀|
    assert 0.8 * _edge_time(th, u) <= res.t[-1] <= abs(np.sin(th[0])) / abs(u[0])
    # the samples before the failing step are finite (the last one may not be)
    assert np.isfinite(res.theta[:-1]).all() and np.isfinite(res.u[:-1]).all()
    # the same run with the switching rule: leaves chart 0 at t = 0, finishes, and agrees
    # with the ambient formulation (both RK4, dt = 0.01)
    ok = integrate(s, th, u, 1.0, formulation="chart", method="rk4", dt=0.01, chart=0)
    amb = integrate(s, th, u, 1.0, formulation="ambient", method="rk4", dt=0.01)
    assert ok.switches[0][:2] == (0.0, 0) and ok.status == "finished"
    assert np.abs(ok.theta[-1] - amb.theta[-1]).max() < 1e-9


@pytest.mark.parametrize("sin0", [2e-4, 2e-3, 1e-2, 3e-2])
def test_every_run_into_the_chart_edge_ends_in_an_integration_error(sin0):
    """An RK4 step that lands outside the chart ends with the DOMAIN status (it used to
    divide by sin θₖ = 0 in the chart formulation's post-step hook)."""
    s = RotorSystem(3)
    th, u = chart_edge_n3(sin0)
    with pytest.raises(IntegrationError) as err:
        integrate(s, th, u, 1.0, formulation="chart", method="rk4", dt=0.01, chart=0,
                  tau=NO_SWITCHING)
    assert 0.8 * _edge_time(th, u) <= err.value.result.t[-1] <= abs(np.sin(th[0])) / abs(u[0])


@pytest.mark.parametrize("sin0", [2e-3, 3e-2])
def test_dop853_at_a_chart_edge_it_may_not_leave_stops_instead_of_crawling(sin0):
    """With switching off, DOP853's error control would crawl towards the chart edge in steps
    of ~1e-9 forever; the route stops with the domain status where the chart becomes
    ill-conditioned beyond use."""
    s = RotorSystem(3)
    th, u = chart_edge_n3(sin0)
    with pytest.raises(ChartDomainError, match="ill-conditioned") as err:
        integrate(s, th, u, 1.0, formulation="chart", method="dop853", chart=0, tau=NO_SWITCHING)
    assert 0.8 * _edge_time(th, u) <= err.value.result.t[-1] <= abs(np.sin(th[0])) / abs(u[0])
    assert err.value.result.n_steps < 10_000


def test_a_velocity_whose_energy_overflows_is_refused():
    s = RotorSystem(3)
    th, u = s.random_state(seed=0)
    for fn in (lambda: integrate(s, th, u * 1e155, 1.0),
               lambda: integrate(s, th, u * 1e155, 1.0, method="rk4"),
               lambda: charts.lyapunov_spectrum(s, th, u * 1e155, 2.0)):
        with pytest.raises(ValueError, match="overflows"):
            fn()
