"""The compiled pieces of the analyses against independent routes: the smallest singular
value (closed 3 × 3 route, one-sided Jacobi) against LAPACK, the backward step of the angle test (sin/cos shifted
between stages) against a plain RK4 of the wrappers, route (b) over many samples against the
Gauss equation point by point, the backward pass stopping at a non-finite state, and the
covariant vectors' compiled forward pass stopping at the N = 4 singular point like every
route."""
import numpy as np
import pytest

import charts
from charts.analyses.curvature import exact_curvatures
from charts.analyses.adjoint_pass import backward_kernel
from charts.analyses.hyperbolicity import adjoint_step, smallest_singular_values
from charts.flows.ambient import adjoint_rhs, flow_rhs
from charts.solvers.status import NONFINITE
from charts.solvers.tangent import Rotors, Stepping
from charts.geometry.structured import gauss_frame_curvature


@pytest.mark.parametrize("shape", [(300, 3, 3), (300, 1, 10), (300, 3, 10), (100, 8, 10)])
def test_smallest_singular_value_equals_lapack(shape):
    """Absolute difference ≤ 1e-14·σ_max: LAPACK's own error is ~ε·σ_max (measured ≤ 4e-15)."""
    M = np.random.default_rng(1).normal(size=shape)
    out = np.empty(shape[0])
    smallest_singular_values(M, out)
    sv = np.linalg.svd(M, compute_uv=False)
    assert np.all(np.abs(out - sv[:, -1]) <= 1e-14 * sv[:, 0])


def test_smallest_singular_value_of_3x3_with_close_smallest_pair_equals_lapack():
    """The closed 3 × 3 route where its root is ill-conditioned (σ₂/σ₃ − 1 from 1e-12 to 1,
    σ₃ from 1e-6 to 0.3, scaled by 1e±3): the Rayleigh refinement or the Jacobi rotations
    keep the error ≤ 1e-14·σ_max (measured ≤ 3e-16)."""
    rng = np.random.default_rng(7)
    M = np.empty((2000, 3, 3))
    for q in range(M.shape[0]):
        U = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        V = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        s3 = 10 ** rng.uniform(-6, -0.5)
        sig = [rng.uniform(0.5, 1.0), s3 * (1 + 10 ** rng.uniform(-12, 0)), s3]
        M[q] = U @ np.diag(sig) @ V.T * 10 ** rng.uniform(-3, 3)
    out = np.empty(M.shape[0])
    smallest_singular_values(M, out)
    sv = np.linalg.svd(M, compute_uv=False)
    assert np.all(np.abs(out - sv[:, -1]) <= 1e-14 * sv[:, 0])


def test_smallest_singular_value_of_a_singular_matrix_is_rounding_and_tall_is_refused():
    M = np.random.default_rng(2).normal(size=(50, 3, 3))
    M[:, 2] = M[:, 0] - 2.0 * M[:, 1]          # rank 2: σ_min = 0 up to rounding
    out = np.empty(50)
    smallest_singular_values(M, out)
    assert np.all(out < 1e-14 * np.abs(M).max())
    with pytest.raises(ValueError, match="no more rows than columns"):
        smallest_singular_values(np.ones((1, 3, 2)), np.empty(1))


def _rk4_wrappers(y, W, minv, a, h):
    """Classical RK4 of eq (8) + the adjoint flow from the Python wrappers (libm at every
    stage): the route the backward pass used before it shifted sin/cos."""
    def f(z):
        dz = np.empty_like(z)
        flow_rhs(z[0], minv, a, dz[0])
        adjoint_rhs(z[0], np.ascontiguousarray(z[1:]), minv, a, dz[1:])
        return dz
    z = np.vstack([y, W])
    k1 = f(z)
    k2 = f(z + 0.5 * h * k1)
    k3 = f(z + 0.5 * h * k2)
    k4 = f(z + h * k3)
    return z + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)


@pytest.mark.parametrize("h", [-0.01, 0.01, -0.2])
def test_adjoint_step_equals_plain_rk4(h):
    """|δ| = 0.2 > SHIFT_MAX exercises the libm fallback of the shift.  Tolerance 1e-13
    relative to the largest entry: the two differ by rounding only (measured ≤ 3e-15)."""
    s = charts.RotorSystem(5, masses=[1.0, 2.0, 1.5, 1.0, 0.5])
    th, u = s.random_state(seed=3)
    W = np.random.default_rng(4).normal(size=(3, 10))
    ref = _rk4_wrappers(np.concatenate([th, u]), W, s.minv, s.weights, h)
    Z = np.vstack([np.concatenate([th, u]), W])
    adjoint_step(Z, s.minv, s.weights, h)
    assert np.abs(Z - ref).max() <= 1e-13 * np.abs(ref).max()


def test_backward_pass_stops_at_a_nonfinite_state_like_the_forward_kernel():
    """The backward pass takes the forward kernel's exits: a non-finite checkpoint gives
    NONFINITE at the step where the pass meets it (never the angles of a NaN state)."""
    s = charts.RotorSystem(5)
    th, u = s.random_state(seed=3)
    ck = np.tile(np.concatenate([th, u]), (4, 1))
    ck[3, 0] = np.nan                  # the state the pass starts from (segment 2's end)
    W = np.linalg.qr(np.random.default_rng(0).normal(size=(10, 3)))[0].T.copy()
    V = np.zeros((2, 40))
    rotors = Rotors(s.minv, s.masses, s.weights, s.level)
    stepping = Stepping(1.0, 0.01, np.ones(10), True)
    status, step = backward_kernel(ck, W, rotors, stepping, 10, 5, 5, 5, V, np.zeros(3),
                                   np.empty(2), np.empty(2))
    assert (status, step) == (NONFINITE, 30)


@pytest.mark.parametrize("n", [3, 5])
def test_exact_route_over_samples_equals_the_gauss_equation_per_point(n):
    """Route (b) from the generated Riemann tensor, compiled over the samples, against the
    Gauss equation in ambient form (independent: no chart) at each point; tolerance 1e-10
    relative to the largest |K| (measured ≤ 2e-13: chart conditioning)."""
    s = charts.RotorSystem(n)
    c = charts.curvature_along_trajectory(s, *s.random_state(seed=5), 3.0, t_transient=1.0,
                                          exact=False)
    K = exact_curvatures(s, c.theta, c.frames)
    ref = np.array([gauss_frame_curvature(c.theta[i], c.frames[i], s.masses, s.weights,
                                          np.empty((n - 2, n - 2))) for i in range(c.t.size)])
    assert K.shape == ref.shape == (c.t.size, n - 2, n - 2)
    assert np.abs(K - ref).max() <= 1e-10 * np.abs(ref).max()


def test_covariant_vectors_stop_at_the_singular_point():
    """The compiled forward pass reports the tangent kernel's status as the Python loop did:
    the geodesic through the N = 4 singular point stops there (tests/test_singular_policy.py)."""
    a, b = 0.42426406871192845, 0.565685424949238
    theta = np.array([0.0, 0.0, np.pi, np.pi]) - np.array([a, b, a, b])
    u = np.array([a, b, a, b])
    # (the start of the step whose sub-steps reach the point: tests/test_singular_policy.py)
    with pytest.raises(charts.SingularPointError, match=r"singular point .* at t = 0\.98999999"):
        charts.covariant_lyapunov_vectors(charts.RotorSystem(4), theta, u, 2.0, t_transient=0.0)
