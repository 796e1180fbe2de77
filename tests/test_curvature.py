"""Curvature along trajectories (section 3): route (a) eqs (19)-(21) with the Jacobi sign,
route (b) the generated Riemann tensor, eq (22) for N = 3."""
import numpy as np
import pytest

from charts.analyses.curvature import (curvature_along_trajectory, curvature_frame,
                                       exact_curvature_matrix, frame_step, numerical_curvature,
                                       gaussian_curvature_eq22)
from charts.geometry.projection import project_tangent
from charts.geometry.system import RotorSystem

from scenarios import REFERENCE_FRACTION_POSITIVE, TOL, gauss_sectional_curvature, masses
from scenarios import gaussian_curvature_eq22 as eq22

#: "coincidence up to the fifth significant digit" (paper, after eq 22): the typical
#: (median) relative error must be below 5e-5.
FIVE_DIGITS = 5e-5
#: route (a) is a second difference of RK4 steps: error ≈ Δt²·(c''''/12 + RK4 terms);
#: measured ≤ 0.36 Δt² along N = 3 trajectories; allow 1.0 Δt².
ABS_ERR_PER_DT2 = 1.0
#: route (a) vs (b) for N = 4, 5 relative to the largest |K_ij| at that point: the
#: O(Δt²) error scales like Δt²·K², so relative error Δt²·|K|; 99 % of points have |K| < 5.
REL_AB_99 = 1e-3
REL_AB_MEDIAN = 1e-4
#: rounding in the generated Riemann tensor vs the closed form eq (22).
ROUND = 1e-9
#: exact route vs the Gauss equation, relative (scenarios.TOL["gauss"]).
GAUSS = TOL["gauss"]


def test_route_b_equals_eq22_and_gauss_route():
    """Route (b) (generated Riemann tensor) against eq (22) and the Gauss equation, both
    written independently in scenarios; the package's eq (22) against route (b)."""
    system = RotorSystem(3)
    rng = np.random.default_rng(0)
    for seed in range(5):
        theta, u = system.random_state(seed=seed)
        w = system.project_tangent(theta, rng.normal(size=3))
        w -= system.inner(theta, w, u) / system.inner(theta, u, u) * u
        P = np.array([u / system.speed(u), w / system.speed(w)])
        K = exact_curvature_matrix(system, theta, P)[0, 0]
        assert K == pytest.approx(eq22(theta), rel=ROUND)
        assert K == pytest.approx(gauss_sectional_curvature(theta, u, w, system.masses), rel=ROUND)
        assert gaussian_curvature_eq22(theta) == pytest.approx(K, rel=ROUND)


def test_n3_route_a_matches_eq22_to_five_digits():
    system = RotorSystem(3)
    theta, u = system.random_state(seed=2)
    dt = 0.01
    res = curvature_along_trajectory(system, theta, u, 200.0, dt=dt)
    Ka = res.K_numeric[:, 0, 0]
    K22 = eq22(res.theta)
    assert Ka.size >= 1000
    # negative curvature everywhere, as eq (22) says: the sign of eq (21) as printed (without
    # the minus of the Jacobi equation) would make every Ka positive
    assert np.all(K22 < 0) and np.all(Ka < 0)
    rel = np.abs(Ka - K22) / np.abs(K22)
    assert np.median(rel) < FIVE_DIGITS, np.median(rel)
    assert np.max(np.abs(Ka - K22)) < ABS_ERR_PER_DT2 * dt ** 2
    np.testing.assert_allclose(res.K_exact[:, 0, 0], K22, rtol=ROUND)


def test_route_a_converges_at_second_order():
    system = RotorSystem(3)
    theta, u = system.random_state(seed=3)
    errs = []
    for dt in (0.02, 0.01):
        res = curvature_along_trajectory(system, theta, u, 20.0, dt=dt, sample_every=0.2,
                                         t_transient=10.0)
        errs.append(np.median(np.abs(res.K_numeric[:, 0, 0] - eq22(res.theta))))
    order = np.log2(errs[0] / errs[1])
    assert 1.6 < order < 2.4, order  # second-difference scheme: order 2


@pytest.mark.parametrize("n", [4, 5])
def test_routes_a_and_b_agree(n):
    system = RotorSystem(n)
    theta, u = system.random_state(seed=2)
    res = curvature_along_trajectory(system, theta, u, 200.0)
    Ka, Kb = res.K_numeric, res.K_exact
    assert Ka.shape == (res.t.size, n - 2, n - 2)
    scale = np.abs(Kb).max(axis=(1, 2))
    rel = np.abs(Ka - Kb).max(axis=(1, 2)) / scale
    assert np.median(rel) < REL_AB_MEDIAN, np.median(rel)
    assert np.percentile(rel, 99) < REL_AB_99
    # the frame is M-orthonormal and tangent
    P = res.frames[7]
    np.testing.assert_allclose(P @ P.T, np.eye(n - 1), rtol=0, atol=1e-12)
    np.testing.assert_allclose(P @ np.sin(res.theta[7]), 0.0, rtol=0, atol=1e-10)
    # both signs occur for N ≥ 4 (the paper's claim), mostly negative, at the rates of the
    # full-preset reference: over t = 200 (≈ 40 correlation times) a fraction p has a
    # sampling spread ≈ √(p(1−p)/40) ≲ 0.06; allow 0.15
    frac = res.fraction_positive("exact")
    assert np.all(frac < 0.5) and frac.max() > 0.01
    np.testing.assert_allclose(frac, REFERENCE_FRACTION_POSITIVE[n], rtol=0, atol=0.15)


def test_masses_route_a_matches_gauss_route():
    system = RotorSystem(4, masses("mixed", 4))
    theta, u = system.random_state(seed=1)
    res = curvature_along_trajectory(system, theta, u, 30.0, t_transient=10.0)
    for i in range(0, res.t.size, 10):
        P = res.frames[i]
        Kg = gauss_sectional_curvature(res.theta[i], P[0], P[1], system.masses)
        assert res.K_exact[i, 0, 0] == pytest.approx(Kg, rel=GAUSS, abs=1e-10)
        assert res.K_numeric[i, 0, 0] == pytest.approx(Kg, abs=ABS_ERR_PER_DT2 * 1e-4 * (1 + Kg ** 2))


def test_route_names_are_the_scenes_and_unknown_ones_are_refused():
    system = RotorSystem(3)
    theta, u = system.random_state(seed=2)
    res = curvature_along_trajectory(system, theta, u, 1.0, t_transient=0.0, exact=False)
    np.testing.assert_array_equal(res.diagonal("numerical"), res.diagonal("numeric"))
    with pytest.raises(ValueError, match="exact route was not computed"):
        res.diagonal("exact")
    with pytest.raises(ValueError, match="route must be"):
        res.fraction_positive("both")


@pytest.mark.parametrize("n", [4, 5])
def test_route_a_equals_two_plain_frame_steps(n):
    """Route (a) shares the first stage of its ±Δt steps and shifts sin/cos between stages;
    against two `frame_step` calls (libm at every stage) it differs by rounding amplified by
    1/Δt² in the second difference of eq (21): ≤ 1e-10 absolute (measured ≤ 4.4e-12)."""
    s = RotorSystem(n, masses=masses("ramp", n))
    th, u = s.random_state(seed=5)
    y = np.concatenate([th, u])
    k, dt = n - 2, 0.01
    X = np.random.default_rng(6).normal(size=(k, 2 * n))
    project_tangent(y, X, s.minv, s.weights)
    Xj = np.empty((k, 2 * n))
    P = np.empty((k + 1, n))
    uu = curvature_frame(y, X, s.minv, s.weights, s.masses, Xj, P)
    K = np.empty((k, k))
    numerical_curvature(y, Xj, P, s.minv, s.weights, s.masses, dt, uu, K)
    cs = np.zeros((k, k))
    work = np.empty(6 * (2 * n + k * 2 * n + (k + 1) * n) + 6 * n)
    for h in (dt, -dt):
        y2, X2, P2 = y.copy(), Xj.copy(), P.copy()
        frame_step(y2, X2, P2, s.minv, s.weights, h, work)
        cs += (P2[1:] * s.masses) @ X2[:, :n].T
    ref = -(cs - 2.0 * np.eye(k)) / (dt * dt * uu)
    assert np.abs(K - ref).max() <= 1e-10
