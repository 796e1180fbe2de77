"""One step-cap and singular-point policy for every route: a geodesic aimed exactly through
the N = 4 singular point (0, 0, π, π) (the straight line θ = S + (t − 1)v, v = (a, b, a, b),
lies on the manifold; the bundled scene hard-n4-through-singular) stops with
`SingularPointError` near t = 1 in `integrate` and in every analysis — never NaN, never a
ZeroDivisionError or an SVD failure."""
import warnings

import numpy as np
import pytest

import charts
from charts.solvers.status import SINGULAR_S

A, B = 0.42426406871192845, 0.565685424949238
THETA = np.array([0.0, 0.0, np.pi, np.pi]) - np.array([A, B, A, B])   # S − v at t = 0
U = np.array([A, B, A, B])
SYSTEM = charts.RotorSystem(4)

ROUTES = {
    "integrate ambient rk4": lambda: charts.integrate(SYSTEM, THETA, U, 2.0, formulation="ambient",
                                                      method="rk4", dt=0.01),
    "integrate ambient dop853": lambda: charts.integrate(SYSTEM, THETA, U, 2.0,
                                                         formulation="ambient"),
    "lyapunov_spectrum": lambda: charts.lyapunov_spectrum(SYSTEM, THETA, U, 2.0, t_transient=0.0,
                                                          n_batches=2),
    "waveform": lambda: charts.waveform(SYSTEM, THETA, U, 2.0),
    "curvature_along_trajectory": lambda: charts.curvature_along_trajectory(
        SYSTEM, THETA, U, 2.0, t_transient=0.0),
    "hyperbolicity_angles": lambda: charts.hyperbolicity_angles(SYSTEM, THETA, U, 2.0,
                                                                t_transient=0.0),
}


@pytest.mark.parametrize("route", sorted(ROUTES))
def test_every_route_stops_at_the_singular_point(route):
    assert np.cos(THETA).sum() == pytest.approx(0.0, abs=1e-15)
    with pytest.raises(charts.SingularPointError, match=r"singular point .* at t = ") as info:
        ROUTES[route]()
    t = float(str(info.value).split("at t = ")[1].split(";")[0])
    assert 0.99 - 1e-12 <= t <= 1.0 + 1e-12      # the start of the step that reaches it


def test_the_fixed_step_route_caps_its_steps_before_the_singular_point():
    """The tangent kernel cuts its steps near the singular point into sub-steps, each within
    the cap 0.03·√S/|u| at its own start, so it approaches the point geometrically without
    stepping over it until the test S < SINGULAR_S stops it, inside step 100."""
    flow = charts.solvers.tangent.TangentFlow(SYSTEM, THETA, U, 0, dt=0.01, project_every=0)
    with pytest.raises(charts.SingularPointError):
        flow.advance(200)
    S = float(np.sum(flow.sc[0] ** 2))
    # the sub-steps of the 100th step (t = 0.99 → 1) reach the point (S below the test's
    # floor, SINGULAR_S raised by the rounding-level drift: 3.2e-14; the state finite); the
    # steps counted are the 99 completed
    assert flow.steps == 99 and S < 10 * SINGULAR_S and np.all(np.isfinite(flow.Z))


def test_angles_without_transient_sample_the_initial_point():
    """t_transient = 0: the first sample is the initial point (its forward vectors are the
    initial ones, projected and orthonormal), not an unwritten buffer."""
    system = charts.RotorSystem(3)
    th, u = system.random_state(seed=1)
    a = charts.hyperbolicity_angles(system, th, u, 2.0, t_transient=0.0, sample_every=0.5)
    b = charts.hyperbolicity_angles(system, th, u, 2.0, t_transient=0.0, sample_every=0.25)
    assert np.all(np.isfinite(a.phi_full)) and a.t[0] == 0.0
    np.testing.assert_allclose(a.phi_full, b.phi_full[::2], rtol=1e-12)


# -- every critical level of the families: N = 3 at level 1, the cone point (0, 0, π) ---------
# θ₁ = θ₂ is the fixed set of the isometry that swaps them, so the curve
# (s, s, arccos(1 − 2 cos s)) is a geodesic, and it runs into the cone point at s = 0.
with warnings.catch_warnings():
    warnings.simplefilter("ignore")              # the CriticalLevelWarning: that is the point
    CONE = charts.RotorSystem(3, level=1.0)
_S = 0.3
CONE_THETA = np.array([_S, _S, np.arccos(1.0 - 2.0 * np.cos(_S))])
_U = CONE.project_tangent(CONE_THETA, np.array([-1.0, -1.0, 0.0]))
CONE_U = _U / np.linalg.norm(_U)
#: where the chart route, whose constraint holds exactly, reaches the cone point
T_CONE = 0.6011489


@pytest.mark.filterwarnings("ignore::charts.geometry.system.CriticalLevelWarning")
@pytest.mark.parametrize("formulation, method, project", [
    (f, m, p) for f in ("ambient", "chart") for m in ("rk4", "dop853") for p in (False, True)])
def test_a_cone_point_of_a_critical_level_stops_every_integration_route(formulation, method,
                                                                        project):
    """Without projection the ambient routes drift ~1e-12 off the level and used to pass the
    cone point on a neighbouring level (S ≥ 1.5e-12 > SINGULAR_S, status "finished"); the
    drift-aware floor (charts.solvers.status.singular_floor) stops them where the chart
    routes stop."""
    with pytest.raises(charts.SingularPointError, match="critical level") as info:
        charts.integrate(CONE, CONE_THETA, CONE_U, 3.0, formulation=formulation, method=method,
                         project=project)
    t = float(str(info.value).split("at t = ")[1].split(";")[0])
    assert abs(t - T_CONE) < 5e-5


@pytest.mark.filterwarnings("ignore::charts.geometry.system.CriticalLevelWarning")
@pytest.mark.parametrize("route", ["lyapunov_spectrum", "hyperbolicity_angles",
                                   "curvature_along_trajectory", "lanes"])
def test_a_cone_point_of_a_critical_level_stops_every_analysis(route):
    if route == "lanes":
        from charts.solvers.lanes import LaneFlows
        from charts.solvers.tangent import TangentFlow
        flows = [TangentFlow(CONE, th, u, 1, dt=0.01, reorth_every=10, project_every=0, seed=i)
                 for i, (th, u) in enumerate([CONE.random_state(seed=1), (CONE_THETA, CONE_U)])]
        lanes = LaneFlows(flows)
        lanes.advance(100)
        assert lanes.stopped_lanes() == [1]
        assert list(lanes.status) == [charts.solvers.status.RUNNING, charts.solvers.status.SINGULAR]
        return
    call = getattr(charts, route)
    with pytest.raises(charts.SingularPointError, match="critical level"):
        call(CONE, CONE_THETA, CONE_U, 2.0, t_transient=0.0)


def test_the_floor_is_the_paper_constant_on_the_constraint_and_grows_with_the_drift():
    from charts.solvers.status import NECK_FACTOR, singular_floor
    c, wts = np.array([0.5, 0.25, 0.25]), np.array([1.0, 2.0, 0.5])
    assert singular_floor(c, wts, 3, 1.0) == SINGULAR_S
    assert singular_floor(c, wts, 3, 1.0 - 1e-12) == pytest.approx(NECK_FACTOR * 2.0 * 1e-12)
