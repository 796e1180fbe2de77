"""N = 64 end to end on the structured kernels, unequal masses, short runs: integrate in both
formulations, the Lyapunov spectrum (leading k and full), curvature by both routes (exact by
the Gauss equation) and the restricted angles, with checks that can fail (formulations and
routes against each other, ± pairs, the speed scaling of a geodesic flow)."""
import numpy as np
import pytest

from charts import (RotorSystem, curvature_along_trajectory, hyperbolicity_angles, integrate,
                    lyapunov_spectrum)

from scenarios import gauss_sectional_curvature

N = 64
#: chart (eq 14, structured kernels) vs ambient (eq 8), DOP853 at rtol 1e-12 up to t = 5:
#: measured 1e-11 (3 chart switches).
CHART_VS_AMBIENT = 1e-9
#: a pair ±λ on one trajectory differs by the log-norm defect of the QR factors spread over
#: T (the N = 7 bound of tests/test_large_n.py, measured 2.2 there; here 1.5 for the pairs, 0.7
#: for the zero pair and 2.0 for the leading three computed alone, at T = 40).
PAIR_DEFECT = 5.0
#: route (a) (second difference, O((|u|Δt)²·|K|)) vs route (b), relative to the largest |K_ij|
#: (measured median 3e-4 at |u|Δt = 0.08, 2e-5 at |u|Δt = 0.02, the step used here).
REL_AB_MEDIAN = 1e-4


@pytest.fixture(scope="module")
def start():
    """Speed √N: kinetic energy ½ per rotor, each rotor turning at ~1 rad per time unit (at
    unit total speed the same runs would need 8 times longer, see the scaling test)."""
    s = RotorSystem(N, np.linspace(0.6, 1.8, N))
    theta, u = s.random_state(seed=5, speed=np.sqrt(N))
    return s, theta, u


def test_integrate_chart_vs_ambient(start):
    s, theta, u = start
    te = np.linspace(0.0, 5.0, 11)
    amb = integrate(s, theta, u, 5.0, formulation="ambient", rtol=1e-12, t_eval=te)
    ch = integrate(s, theta, u, 5.0, formulation="chart", rtol=1e-12, t_eval=te)
    assert np.abs(ch.theta - amb.theta).max() < CHART_VS_AMBIENT
    assert np.abs(ch.u - amb.u).max() < CHART_VS_AMBIENT


def test_lyapunov_full_spectrum_pairs_and_leading(start):
    """All 2N − 2 = 126 exponents: pairs ±λ; N − 2 positive and a zero pair (flow direction,
    energy); the leading 3 computed alone (other initial vectors) agree with the first three
    within the same O(1/T) defect.  (Finite-time exponents need not be sorted.)"""
    s, theta, u = start
    T = 40.0
    full = lyapunov_spectrum(s, theta, u, T, t_transient=5.0, n_batches=4, inner="full",
                             n_exponents=2 * N - 2)
    lam = full.exponents
    assert lam.shape == (2 * N - 2,) and np.all(np.isfinite(lam))
    np.testing.assert_allclose(lam + lam[::-1], 0.0, rtol=0, atol=PAIR_DEFECT / T)
    assert np.abs(lam[N - 2:N]).max() < PAIR_DEFECT / T            # the zero pair
    assert lam[:5].mean() > 0.15 > lam[N - 12:N - 2].mean() > 0.0    # decreasing positive half
    lead = lyapunov_spectrum(s, theta, u, T, t_transient=5.0, n_batches=4, inner="full",
                             n_exponents=3, seed=7)
    np.testing.assert_allclose(lead.exponents, lam[:3], rtol=0, atol=PAIR_DEFECT / T)


def test_speed_scaling_of_the_exponents():
    """A geodesic flow at speed c is the unit-speed flow with time scaled by c: with every time
    (dt, T, transient, re-orthonormalisation, projection) divided by c the same steps are
    taken, so λ(c) = c·λ(1) up to the initial tangent vectors' defect (the random vectors
    are the same, their velocity parts are not scaled by c), O(1/T): measured 0.005 at
    T = 400 (N = 6, c = 4, λ₁ = 0.25)."""
    s = RotorSystem(6)
    theta, u = s.random_state(seed=2)
    c, T = 4.0, 400.0
    kw = dict(n_batches=4)
    one = lyapunov_spectrum(s, theta, u, T, dt=0.01, t_transient=10.0, reorth_every=0.1, **kw)
    fast = lyapunov_spectrum(s, theta, c * u, T / c, dt=0.01 / c, t_transient=10.0 / c,
                             reorth_every=0.1 / c, project_every=1.0 / c, **kw)
    np.testing.assert_allclose(fast.exponents / c, one.exponents, rtol=0, atol=4.0 / T)


def test_curvature_both_routes(start):
    s, theta, u = start
    # route (a)'s error goes with (speed·dt)²: dt = 0.0025 at speed 8 is 0.02 of arc per step
    res = curvature_along_trajectory(s, theta, u, 2.0, t_transient=2.0, sample_every=0.1,
                                     dt=0.0025, exact=True)
    Ka, Kb = res.K_numeric, res.K_exact
    assert Ka.shape == Kb.shape == (20, N - 2, N - 2)
    rel = np.abs(Ka - Kb).max(axis=(1, 2)) / np.abs(Kb).max(axis=(1, 2))
    assert np.median(rel) < REL_AB_MEDIAN, np.median(rel)
    for i in (0, 19):
        P = res.frames[i]
        np.testing.assert_allclose(P @ np.diag(s.masses) @ P.T, np.eye(N - 1), rtol=0, atol=1e-12)
        for j in (1, 30, N - 2):   # the chart's curvature operator and the numpy Gauss form
            Kc = s.sectional_curvature(res.theta[i], P[0], P[j])
            assert Kb[i, j - 1, j - 1] == pytest.approx(Kc, rel=1e-9, abs=1e-12)
            Kg = gauss_sectional_curvature(res.theta[i], P[0], P[j], s.masses)
            assert Kc == pytest.approx(Kg, rel=1e-9, abs=1e-12)
    assert 0.0 < res.fraction_positive("exact").mean() < 1.0


def test_restricted_angles(start):
    s, theta, u = start
    r = hyperbolicity_angles(s, theta, u, 2.0, t_transient=3.0, n_unstable=4)
    assert r.t.size == 20
    for phi in (r.phi_full, r.phi_restricted):
        assert np.all(np.isfinite(phi)) and np.all(phi > 0) and np.all(phi <= np.pi / 2)
    assert np.all(r.phi_restricted >= r.phi_full - 1e-9)       # E_cs ∩ T_r ⊂ E_cs
    assert np.all(r.forward_exponents > 0.0) and np.all(r.adjoint_exponents > 0.0)
