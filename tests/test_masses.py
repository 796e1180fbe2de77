"""Unequal moments of inertia end to end.

* the exact (generated Riemann) and numerical (eqs 19-21) curvature routes agree, and the
  exact route equals the Gauss-equation route, for strongly unequal masses;
* the scaling law: T = ½ Σ mᵢuᵢ² fixed and m → s·m give u → u/√s on the same geodesics
  (the Christoffel symbols of s·g equal those of g), so θ_s(t) = θ(t/√s) and every
  exponent scales as λ → λ/√s;
* permuting the masses together with the angles (and velocities) changes nothing;
* every analysis runs with masses from a scene through the command line.
"""
import json

import numpy as np
import pytest

from charts import RotorSystem, integrate, lyapunov_spectrum
from charts.cli.main import main
from charts.analyses.curvature import curvature_along_trajectory

from scenarios import TOL, gauss_sectional_curvature, masses, tangent_basis

# --- tolerances, each with its reason -------------------------------------------------
#: route (a) vs (b), relative to the largest |K_ij| at the point: an O(Δt²·|K|) second
#: difference (tests/test_curvature.py); the masses below make |K| up to ~4x larger.
REL_AB_MEDIAN = 3e-4
REL_AB_99 = 3e-3
#: rounding only: exact (Riemann) route vs the Gauss-equation route.
ROUND = TOL["gauss"]
#: s = 4 is a power of two: masses·4, u/2, dt·2 scale every floating-point operation of RK4
#: exactly, so the trajectory and the leading exponent agree to rounding of the final
#: division.  The second exponent also carries the memory of the initial 2-plane, which
#: differs (the random initial vectors are normalised in the scaled metric): measured
#: 6e-7 relative at T = 400, allow 1e-5.
EXACT_LEADING = 1e-9
EXACT_SUBLEADING = 1e-5
#: two-sided statistical margin in combined standard errors (|z| > 4: probability 6e-5).
N_SIGMA = TOL["n_sigma"]

MASSES = {4: masses("heavy_last", 4), 5: masses("strong", 5)}


@pytest.mark.parametrize("n", [4, 5])
def test_curvature_routes_agree_with_unequal_masses(n):
    system = RotorSystem(n, MASSES[n])
    theta, u = system.random_state(seed=5)
    res = curvature_along_trajectory(system, theta, u, 100.0, t_transient=10.0)
    Ka, Kb = res.K_numeric, res.K_exact
    rel = np.abs(Ka - Kb).max(axis=(1, 2)) / np.abs(Kb).max(axis=(1, 2))
    assert np.median(rel) < REL_AB_MEDIAN, np.median(rel)
    assert np.percentile(rel, 99) < REL_AB_99, np.percentile(rel, 99)
    # every diagonal element (velocity x i-th Lyapunov vector) by the Gauss equation
    for s in range(0, res.t.size, 50):
        P = res.frames[s]
        np.testing.assert_allclose(P @ np.diag(system.masses) @ P.T, np.eye(n - 1), rtol=0,
                                   atol=1e-12)
        for i in range(1, n - 1):
            Kg = gauss_sectional_curvature(res.theta[s], P[0], P[i], system.masses)
            assert Kb[s, i - 1, i - 1] == pytest.approx(Kg, rel=ROUND, abs=ROUND)
    # the masses change the geometry: the same planes have other curvatures with equal masses
    # (typically by tens of per cent; require more than 1 % in the median)
    idx = range(0, res.t.size, 50)
    Keq = np.array([gauss_sectional_curvature(res.theta[s], res.frames[s][0], res.frames[s][1],
                                              np.ones(n)) for s in idx])
    Km = Kb[list(idx), 0, 0]
    assert np.median(np.abs(Keq - Km) / np.abs(Km)) > 0.01


def test_scaling_law_is_exact_for_a_power_of_two():
    """m → 4m at fixed energy: u → u/2, time → 2t; with dt → 2dt RK4 is the same map."""
    m = masses("mixed", 4)
    s1, s4 = RotorSystem(4, m), RotorSystem(4, 4 * m)
    theta, u = s1.random_state(seed=3)
    assert s4.energy(u / 2) == pytest.approx(s1.energy(u), rel=1e-15)
    r1 = integrate(s1, theta, u, 10.0, method="rk4", dt=0.01, formulation="ambient")
    r4 = integrate(s4, theta, u / 2, 20.0, method="rk4", dt=0.02, formulation="ambient")
    np.testing.assert_allclose(r4.theta[-1], r1.theta[-1], rtol=0, atol=1e-13)
    np.testing.assert_allclose(2 * r4.u[-1], r1.u[-1], rtol=0, atol=1e-13)
    l1 = lyapunov_spectrum(s1, theta, u, 400.0, dt=0.01, t_transient=50.0, n_batches=4)
    # the same RK4 map: re-orthonormalise, project and record at the same steps as the
    # defaults of the first run (every 10, 100 and 100 steps)
    l4 = lyapunov_spectrum(s4, theta, u / 2, 800.0, dt=0.02, t_transient=100.0, n_batches=4,
                           record_every=2.0, reorth_every=0.2, project_every=2.0)
    ratio = 2 * l4.exponents / l1.exponents - 1
    assert abs(ratio[0]) < EXACT_LEADING, ratio
    assert abs(ratio[1]) < EXACT_SUBLEADING, ratio


@pytest.mark.parametrize("s", [3.0, 1 / 3])
def test_scaling_law_statistically(s):
    """Same dt, a factor that is not a power of two: λ(s·m)·√s = λ(m) within error bars,
    and the unscaled values differ (so the law is what the numbers say, not a tautology)."""
    m = np.array([1.0, 1.0, 1.0, 2.0])
    base, scaled = RotorSystem(4, m), RotorSystem(4, s * m)
    theta, u = base.random_state(seed=7)
    kw = dict(dt=0.01, t_transient=50.0, n_batches=20)
    a = lyapunov_spectrum(base, theta, u, 8000.0, **kw)
    b = lyapunov_spectrum(scaled, theta, u / np.sqrt(s), 8000.0, **kw)
    lam, se = b.exponents * np.sqrt(s), b.stderr * np.sqrt(s)
    sigma = np.hypot(a.stderr, se)
    assert np.all(np.abs(lam - a.exponents) < N_SIGMA * sigma), (lam, a.exponents, sigma)
    assert np.all(np.abs(b.exponents - a.exponents) > N_SIGMA * np.hypot(a.stderr, b.stderr))


def test_permuting_masses_with_angles_changes_nothing():
    m = np.array([0.5, 1.0, 2.0, 3.0])
    perm = np.array([2, 0, 3, 1])
    a, b = RotorSystem(4, m), RotorSystem(4, m[perm])
    theta, u = a.random_state(seed=11)
    # the trajectory: permuted initial state -> permuted trajectory (rounding differs in
    # the order of the sums; 1e-16 grows like e^{0.4 t} ≈ 3e3 by t = 20)
    ra = integrate(a, theta, u, 20.0, method="rk4", dt=0.01, formulation="ambient")
    rb = integrate(b, theta[perm], u[perm], 20.0, method="rk4", dt=0.01, formulation="ambient")
    np.testing.assert_allclose(rb.theta[-1], ra.theta[-1][perm], rtol=0, atol=1e-10)
    np.testing.assert_allclose(rb.u[-1], ra.u[-1][perm], rtol=0, atol=1e-10)
    # exact sectional curvatures of permuted planes, in whichever chart is best
    rng = np.random.default_rng(0)
    for _ in range(5):
        th, v = a.random_state(seed=int(rng.integers(1 << 30)))
        w = a.project_tangent(th, rng.normal(size=4))
        Ka = a.sectional_curvature(th, v, w)
        Kb = b.sectional_curvature(th[perm], v[perm], w[perm])
        assert Kb == pytest.approx(Ka, rel=1e-9)
        # chart k of a is chart j of b with j = perm⁻¹(k); its local axes are relabelled
        for k in range(4):
            j = int(np.argsort(perm)[k])
            la = [i for i in range(4) if i != k]
            lb = [la.index(int(perm[i])) for i in range(4) if i != j]
            np.testing.assert_allclose(b.metric(th[perm], chart=j),
                                       a.metric(th, chart=k)[np.ix_(lb, lb)], rtol=1e-12)
            np.testing.assert_allclose(b.christoffel(th[perm], chart=j),
                                       a.christoffel(th, chart=k)[np.ix_(lb, lb, lb)],
                                       rtol=1e-10, atol=1e-12)
    # the exponents (independent after ~100 time units of rounding divergence)
    la = lyapunov_spectrum(a, theta, u, 8000.0, n_batches=20)
    lb = lyapunov_spectrum(b, theta[perm], u[perm], 8000.0, n_batches=20)
    sigma = np.hypot(la.stderr, lb.stderr)
    assert np.all(np.abs(la.exponents - lb.exponents) < N_SIGMA * sigma)


def test_every_analysis_runs_with_masses_from_the_command_line(tmp_path):
    scene = tmp_path / "masses.toml"
    scene.write_text(
        'name = "masses"\n[system]\nn = 4\nmasses = [1.0, 0.5, 1.0, 2.5]\nspeed = 1.3\n'
        "[initial]\nseed = 2\n[run]\nt_final = 60.0\nt_transient = 5.0\nsample_dt = 0.05\n"
        "[effects.waveforms]\n[effects.spectrum]\nnperseg = 256\n"
        "[effects.lyapunov]\nn_batches = 4\n[effects.curvature]\nroute = \"both\"\n"
        "[effects.angles]\nvariant = \"both\"\n[effects.drift]\n")
    assert main(["run", str(scene), "-o", str(tmp_path / "out"), "--quiet"]) == 0
    r = json.loads((tmp_path / "out" / "result.json").read_text())
    assert r["status"] == "complete"
    assert r["scene"]["system"]["masses"] == [1.0, 0.5, 1.0, 2.5]
    res = r["results"]
    assert set(res) >= {"waveforms", "spectrum", "lyapunov", "curvature", "angles"}
    assert len(res["lyapunov"]["exponents"]) == 2 and res["lyapunov"]["exponents"][0] > 0
    assert "paper" not in res["lyapunov"]          # the paper's values are for equal masses
    assert res["curvature"]["max_abs_route_difference"] < 1e-2
    # E_cs ∩ T_r ⊂ E_cs: the restricted angle is never below the full one, sample by sample
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        full, restricted = a["angles_full"], a["angles_restricted"]
    assert full.size == res["angles"]["full"]["n"] > 100
    assert np.all(restricted >= full - 1e-9)
    assert res["angles"]["full"]["min"] == full.min() > 0
    assert all(x > 0.1 for x in res["angles"]["forward_exponents"])
    # the energy is the mass-weighted one: |u|_g = speed
    u0 = np.array(r["initial_state"]["u"])
    assert np.sqrt(np.sum(np.array([1.0, 0.5, 1.0, 2.5]) * u0 ** 2)) == pytest.approx(1.3)
    assert abs(r["drift"]["energy_relative"]) < 1e-8


#: masses from equal to strongly unequal, and one random draw
SIGN_MASSES = {3: [None, masses("heavy_last", 3), masses("strong", 3), "random"],
               4: [None, masses("heavy_last", 4), [1.0, 0.25, 1.0, 0.25], "random"],
               5: [None, masses("strong", 5), "random"]}


@pytest.mark.parametrize("n", [3, 4, 5])
def test_sign_of_sectional_curvature_does_not_depend_on_masses(n):
    """Gauss equation: K(v, w) = [h(v,v)h(w,w) − h(v,w)²] / (|∇F|²_{M⁻¹} (|v|²|w|² −
    ⟨v,w⟩²)_M) with h = Hess F = −diag(cos θ), so sign K(v, w) = sign det(h on the plane)
    and no mass enters it.  Consequences checked here with the generated Riemann tensor:
    N = 3 is negatively curved for every mass distribution (h on the 2-plane T is
    indefinite); for N ≥ 4, h on T (dimension ≥ 3) has two eigenvalues of one sign, and the
    plane of their eigenvectors has K > 0 — for every mass distribution."""
    rng = np.random.default_rng(n)
    systems = [RotorSystem(n, rng.uniform(0.2, 5.0, n) if isinstance(m, str) else m)
               for m in SIGN_MASSES[n]]
    for trial in range(12):
        theta, _ = systems[0].random_state(seed=100 + trial)
        B = tangent_basis(theta)
        ev, V = np.linalg.eigh(B.T @ np.diag(-np.cos(theta)) @ B)
        if n == 3:
            assert ev[0] < 0 < ev[1]                          # indefinite on the surface
            planes = [(B[:, 0], B[:, 1])]
        else:
            pos, neg = np.flatnonzero(ev > 0), np.flatnonzero(ev < 0)
            pair = pos[:2] if len(pos) >= 2 else neg[:2]
            assert len(pair) == 2                             # pigeonhole in dimension ≥ 3
            planes = [(B @ V[:, pair[0]], B @ V[:, pair[1]])]
        x = B @ rng.normal(size=(n - 1, 3))
        planes += [(x[:, 0], x[:, 1]), (x[:, 0], x[:, 2])]   # random planes too
        for p, (v, w) in enumerate(planes):
            K = np.array([S.sectional_curvature(theta, v, w) for S in systems])
            assert np.all(np.sign(K) == np.sign(K[0])), K
            if p == 0:
                assert np.all(K < 0) if n == 3 else np.all(K > 0), K
