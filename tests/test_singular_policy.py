"""One step-cap and singular-point policy for every route: a geodesic aimed exactly through
the N = 4 singular point (0, 0, π, π) (the straight line θ = S + (t − 1)v, v = (a, b, a, b),
lies on the manifold; the bundled scene hard-n4-through-singular) stops with
`SingularPointError` near t = 1 in `integrate` and in every analysis — never NaN, never a
ZeroDivisionError or an SVD failure."""
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
    with pytest.raises(charts.SingularPointError, match=r"singular point .* at t = 0\.99|t = 1\b"):
        ROUTES[route]()


def test_the_fixed_step_route_caps_its_steps_before_the_singular_point():
    """The tangent kernel cuts its steps near the singular point (cap 0.03·√S/|u|), so it
    approaches it without stepping over it until the test S < SINGULAR_S stops it."""
    flow = charts.solvers.tangent.TangentFlow(SYSTEM, THETA, U, 0, dt=0.01, project_every=0)
    with pytest.raises(charts.SingularPointError):
        flow.advance(200)
    S = float(np.sum(flow.sc[0] ** 2))
    # the capped sub-steps land on the point itself at t = 1 (S at rounding level, the state
    # finite), and the next step refuses to start from it
    assert flow.steps == 100 and S < SINGULAR_S and np.all(np.isfinite(flow.Z))


def test_angles_without_transient_sample_the_initial_point():
    """t_transient = 0: the first sample is the initial point (its forward vectors are the
    initial ones, projected and orthonormal), not an unwritten buffer."""
    system = charts.RotorSystem(3)
    th, u = system.random_state(seed=1)
    a = charts.hyperbolicity_angles(system, th, u, 2.0, t_transient=0.0, sample_every=0.5)
    b = charts.hyperbolicity_angles(system, th, u, 2.0, t_transient=0.0, sample_every=0.25)
    assert np.all(np.isfinite(a.phi_full)) and a.t[0] == 0.0
    np.testing.assert_allclose(a.phi_full, b.phi_full[::2], rtol=1e-12)
