"""N >= 7 end to end: geometry derived on demand (one N = 7 derivation per session, conftest),
unequal masses ("n7"), through ``integrate`` in both formulations and through every analysis,
with short runs and checks that can fail (formulations against each other, ± pairs of the
spectrum, numerical against exact curvature, exact curvature against the Gauss equation,
restricted against full angles)."""
import numpy as np
import pytest

from charts import (curvature_along_trajectory, hyperbolicity_angles, integrate,
                    lyapunov_spectrum)

from scenarios import TOL, gauss_sectional_curvature

N = 7
#: chart (eq 14) vs ambient (eq 8), both DOP853 at rtol 1e-12 up to t = 10 (3 switches):
#: measured 3e-11 (rounding amplified by the chaos, λ₁ ≈ 0.16).
CHART_VS_AMBIENT = 1e-9
#: RK4 at dt = 0.01 against that: the global error of RK4 over t = 10 (measured 2e-11).
RK4_VS_DOP853 = 1e-8
#: the exponents of a pair ±λ computed on one trajectory differ by the log-norm defect of the
#: QR factors, bounded (measured ≈ 2.2 at T = 200 and 400), spread over T.
PAIR_DEFECT = 5.0
#: θ-only vs full inner product on one trajectory: the norms differ by a bounded factor, spread
#: over T; λ₅ ≈ 0.05 lies close to the zero pair, so its vector aligns slowly (like e^{−0.05 t})
#: and the two products' log-norms differ by a few units (measured 2.6 at T = 400).
INNER_DEFECT = 5.0
#: route (a) (second difference, O(Δt²·|K|)) vs route (b), relative to the largest |K_ij|:
#: measured median 5e-6 along 50 samples.
REL_AB_MEDIAN = 1e-4


@pytest.fixture(scope="module")
def start(system7):
    theta, u = system7.random_state(seed=2)
    return system7, theta, u


def test_system7_is_derived_with_its_masses(start):
    s, theta, u = start
    assert s.n == N and s.dim == N - 1 and not np.allclose(s.masses, 1.0)
    assert abs(np.cos(theta).sum()) < 1e-13 and s.speed(u) == pytest.approx(1.0)


def test_integrate_both_formulations_and_methods_agree(start):
    s, theta, u = start
    te = np.linspace(0.0, 10.0, 101)
    amb = integrate(s, theta, u, 10.0, formulation="ambient", rtol=1e-12, t_eval=te)
    ch = integrate(s, theta, u, 10.0, formulation="chart", rtol=1e-12, t_eval=te)
    assert len(ch.switches) >= 1
    assert np.abs(ch.theta - amb.theta).max() < CHART_VS_AMBIENT
    assert np.abs(ch.u - amb.u).max() < CHART_VS_AMBIENT
    for form in ("chart", "ambient"):
        rk = integrate(s, theta, u, 10.0, formulation=form, method="rk4", t_eval=te)
        assert np.abs(rk.theta - amb.theta).max() < RK4_VS_DOP853, form
    # unprojected invariants drift by the integration error at rtol 1e-12 (measured ≤ 4e-11)
    for r in (amb, ch):
        assert r.drift["constraint"] < 1e-9 and r.drift["energy"] < 1e-9


def test_lyapunov_spectrum_pairs(start):
    """All 2N−2 = 12 exponents in the restricted space: pairs ±λ (symplectic tangent flow),
    and the leading N−2 of the paper's θ-only product equal those of the full product."""
    s, theta, u = start
    T = 400.0
    full = lyapunov_spectrum(s, theta, u, T, t_transient=10.0, n_batches=5, inner="full",
                             n_exponents=2 * N - 2)
    lam = full.exponents
    assert lam.shape == (2 * N - 2,) and np.all(np.isfinite(lam))
    np.testing.assert_allclose(lam + lam[::-1], 0.0, rtol=0, atol=PAIR_DEFECT / T)
    assert lam[0] > 0.1 and np.all(np.diff(lam[:N - 2]) < 0.02)
    lead = lyapunov_spectrum(s, theta, u, T, t_transient=10.0, n_batches=5)
    assert lead.exponents.shape == (N - 2,)
    np.testing.assert_allclose(lead.exponents, lam[:N - 2], rtol=0, atol=INNER_DEFECT / T)


def test_curvature_exact_and_numerical_routes(start):
    s, theta, u = start
    res = curvature_along_trajectory(s, theta, u, 5.0, t_transient=5.0, exact=True)
    Ka, Kb = res.K_numeric, res.K_exact
    assert Kb.shape == Ka.shape == (res.t.size, N - 2, N - 2) and res.t.size >= 20
    rel = np.abs(Ka - Kb).max(axis=(1, 2)) / np.abs(Kb).max(axis=(1, 2))
    assert np.median(rel) < REL_AB_MEDIAN, np.median(rel)
    for i in range(0, res.t.size, 10):
        P = res.frames[i]
        np.testing.assert_allclose(P @ np.diag(s.masses) @ P.T, np.eye(N - 1), rtol=0, atol=1e-12)
        np.testing.assert_allclose(P @ np.sin(res.theta[i]), 0.0, rtol=0, atol=1e-10)
        for j in range(1, N - 1):
            Kg = gauss_sectional_curvature(res.theta[i], P[0], P[j], s.masses)
            assert Kb[i, j - 1, j - 1] == pytest.approx(Kg, rel=TOL["gauss"], abs=TOL["gauss"])


def test_hyperbolicity_angles(start):
    s, theta, u = start
    r = hyperbolicity_angles(s, theta, u, 20.0, t_transient=30.0)
    assert r.t.size >= 100
    for phi in (r.phi_full, r.phi_restricted):
        assert np.all(np.isfinite(phi)) and np.all(phi > 0) and np.all(phi <= np.pi / 2)
    assert np.all(r.phi_restricted >= r.phi_full - 1e-9)       # E_cs ∩ T_r ⊂ E_cs
    # N − 2 = 5 expanding directions: both passes see five positive growth rates
    assert r.forward_exponents.shape == r.adjoint_exponents.shape == (N - 2,)
    assert np.all(r.forward_exponents > 0.02) and np.all(r.adjoint_exponents > 0.02)
