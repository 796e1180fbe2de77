"""The family of constraints Σ aᵢ cos θᵢ = c (weights a, level c).

* validation: bad weights/levels are refused, an empty level set is an error, an explicitly
  requested critical level warns, the paper's default stays silent;
* the paper's case (a = 1, c = 0) gives the bits of the code before the weights existed
  (a stored reference), and a = 1 given explicitly gives the same bits as weights=None;
* the limit c → 0, aᵢ → 1: a trajectory tends to the paper's one, linearly in the offset;
* the weighted ambient equations against an independent closed form (eq 8 written here with
  the weights) and finite differences (eq 17); the invariants held along a weighted run;
* the closed-form chart metric g_αβ = m_α δ_αβ + m_k a_α a_β s_α s_β / (a_k² − (c − Σ a c)²)
  against the pull-back of diag(m) by finite differences of the embedding, and the Gaussian
  curvature of that metric (SymPy, N = 3) against the Gauss equation with the weighted normal;
* the numerical curvature route (eqs 19–21 on the weighted equations) against the Gauss
  equation with the weighted normal (route b) along a weighted run at a smooth level.
"""
import warnings

import numpy as np
import pytest

from charts import RotorSystem, integrate, lyapunov_spectrum
from charts.analyses.curvature import curvature_along_trajectory
from charts.analyses.hyperbolicity import hyperbolicity_angles
from charts.flows.ambient import flow_rhs, flow_tangent_rhs
from charts.geometry.system import CriticalLevelWarning, critical_levels
from charts.solvers.tangent import TangentFlow

from scenarios import TOL

#: weights/level of the tests: N = 4 at the smooth level 0.5 (equal weights: critical values
#: 0, ±2, ±4), and an unequal pattern at a level that is not one of its critical values.
W4 = np.array([1.0, 1.3, 0.7, 1.1])
L4 = 0.4


def _h(xs):
    return [float(x).hex() for x in xs]


# ------------------------------------------------------------------------------ validation
@pytest.mark.parametrize("kw, match", [
    (dict(weights=[1.0, 1.0, 1.0]), r"weights must have shape \(4,\)"),
    (dict(weights=[1.0, 0.0, 1.0, 1.0]), "finite and positive"),
    (dict(weights=[1.0, -1.0, 1.0, 1.0]), "finite and positive"),
    (dict(weights=[1.0, np.nan, 1.0, 1.0]), "weights has non-finite entries"),
    (dict(level=np.inf), "level must be finite"),
    (dict(level="0.5"), "level must be a real number"),
    (dict(level=10 ** 400), "level must be a finite number, got an integer of 401 digits"),
    (dict(weights=[1.0, 1 + 2j, 1.0, 1.0]), "weights must be an array of real numbers"),
    (dict(weights=["1", "1", "1", "1"]), "weights must be an array of real numbers"),
    (dict(level=4.5), "empty"),
    (dict(level=-4.0), "single point"),
])
def test_bad_weights_and_levels_are_refused(kw, match):
    with pytest.raises(ValueError, match=match):
        RotorSystem(4, **kw)


def test_critical_levels_warn_only_when_asked_for():
    assert critical_levels([1, 1, 1, 1]).tolist() == [-4, -2, 0, 2, 4]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        RotorSystem(4)                      # the paper's manifold: silent (docs/families.md)
        RotorSystem(4, level=0.5)           # smooth
        RotorSystem(5, weights=np.ones(5))  # 0 is not critical for N = 5
        RotorSystem(4, weights=W4, level=L4)
        RotorSystem(4, weights=[1, 1, 1, 1])    # the paper's manifold however written:
        RotorSystem(4, weights=[2.0] * 4)       # the same system, the same (no) warning
    with pytest.warns(CriticalLevelWarning, match="critical value 0.0"):
        RotorSystem(4, weights=[1, 2, 1, 2])    # another manifold, critical at 0
    with pytest.warns(CriticalLevelWarning, match="critical value 2.0"):
        RotorSystem(4, level=2.0)
    with pytest.warns(CriticalLevelWarning, match="critical value"):
        RotorSystem(3, weights=[1.0, 1.7, 0.6], level=-0.1)  # 1 − 1.7 + 0.6


def test_points_and_tangents_of_a_weighted_system():
    s = RotorSystem(4, weights=W4, level=L4)
    th, u = s.random_state(seed=4, speed=1.5)
    assert abs(W4 @ np.cos(th) - L4) < TOL["round"]
    assert abs(u @ (W4 * np.sin(th))) < TOL["round"]
    assert abs(s.speed(u) - 1.5) < TOL["round"]
    s.check_state(th, u)
    p = s.project_point(th + 0.01)
    assert abs(W4 @ np.cos(p) - L4) < 1e-14
    with pytest.raises(ValueError, match="off the manifold"):
        RotorSystem(4, level=0.5).check_point(th)
    with pytest.raises(ValueError, match="not tangent"):
        s.check_tangent(th, np.ones(4))
    assert s.metric(th).shape == (3, 3)     # the chart side: tests/test_family_charts.py


# ------------------------------------------------------------- the paper's case, bit for bit
#: Computed with the code before weights and levels existed (the branch point of this work,
#: ``/tmp/family_ref.py`` run with that checkout first on PYTHONPATH); the new code must give
#: the same bits (multiplying by aᵢ = 1.0 and adding c = 0.0 are exact).
REF_LYAP = ['0x1.5645fb90101d0p-2', '0x1.c2f0404255f90p-3', '0x1.03969b8daf95ep-3']
#: The ambient RK4 trajectory since it takes the tangent kernel's step (stage sin/cos shifted
#: from the step's start; tests/test_ambient_tangent_identity.py): the code before weights
#: gave REF_TRAJ_LIBM (libm at every stage), 3.7e-14 away after 500 projected steps.
REF_TRAJ = ['-0x1.9820f9a4bda4dp+0', '-0x1.955000e29577ep+1', '0x1.f264a721fddf6p-2',
            '-0x1.6da993ae51495p+2', '-0x1.2cd044f7377d9p+1']
REF_TRAJ_LIBM = ['-0x1.9820f9a4bda95p+0', '-0x1.955000e29579cp+1', '0x1.f264a721fdcb1p-2',
                 '-0x1.6da993ae514bfp+2', '-0x1.2cd044f737802p+1']
#: Route (a) since it shares the first stage of its ±Δt steps and shifts sin/cos between
#: stages (libm before: the sum differs by 6.6e-14 relative, each K by ≤ 4.4e-12).
REF_CURV = ('-0x1.0d47cbd01bbadp+3', '-0x1.0d40590dd10dep+3')
#: The angles since the backward pass shifts sin/cos between RK4 stages like the tangent kernel
#: (libm before: the sums differ in the last 1–2 bits, the angles by ≤ 3e-15 relative).
REF_ANGLES = ('0x1.a7d75acb35419p+2', '0x1.443755302d2c3p+3')


@pytest.mark.parametrize("weights", [None, "ones"])
def test_paper_case_is_bit_for_bit_the_code_before_weights(weights):
    w5 = None if weights is None else np.ones(5)
    s = RotorSystem(5, masses=[1.0, 2.0, 0.5, 1.5, 1.0], weights=w5, level=0.0)
    th, u = s.random_state(seed=3)
    r = lyapunov_spectrum(s, th, u, 20.0, n_exponents=3, t_transient=0.0)
    assert _h(r.exponents) == REF_LYAP
    res = integrate(s, th, u, 5.0, formulation="ambient", method="rk4", dt=0.01, project=True)
    assert _h(res.theta[-1]) == REF_TRAJ
    flow = TangentFlow(s, th, u, 0, dt=0.01, project_every=1)   # the same step, bit for bit
    flow.advance(500)
    assert _h(flow.y[:5]) == REF_TRAJ
    libm = np.array([float.fromhex(x) for x in REF_TRAJ_LIBM])
    assert np.max(np.abs(res.theta[-1] - libm)) < 5e-14      # the change of route: 3.7e-14
    s4 = RotorSystem(4)
    th4, u4 = s4.random_state(seed=2)
    c = curvature_along_trajectory(s4, th4, u4, 2.0, t_transient=1.0)
    assert (float(np.sum(c.K_numeric)).hex(), float(np.sum(c.K_exact)).hex()) == REF_CURV
    a = hyperbolicity_angles(s4, th4, u4, 5.0, t_transient=2.0)
    assert (float(np.sum(a.phi_full)).hex(), float(np.sum(a.phi_restricted)).hex()) == REF_ANGLES


def test_limit_c_to_zero_and_weights_to_one():
    """A trajectory at (a = 1 + ε·b, c = ε·c₁) tends to the paper's one, linearly in ε: the
    state is moved onto the perturbed manifold by projection, then integrated (DOP853,
    rtol 1e-12, t = 5).  Measured: difference/ε ≈ 2–6 for ε = 1e-6..1e-8, i.e. the ratio of
    consecutive differences is 100 ± 5 %."""
    s0 = RotorSystem(5)
    th, u = s0.random_state(seed=1)
    ref = integrate(s0, th, u, 5.0, formulation="ambient", rtol=1e-12, atol=1e-12).theta[-1]
    b = np.array([0.3, -0.2, 0.5, 0.1, -0.4])
    diffs = []
    for eps in (1e-6, 1e-7, 1e-8):
        s = RotorSystem(5, weights=1.0 + eps * b, level=0.7 * eps)
        the = s.project_point(th)
        ue = s.project_tangent(the, u)
        out = integrate(s, the, ue, 5.0, formulation="ambient", rtol=1e-12, atol=1e-12)
        diffs.append(np.abs(out.theta[-1] - ref).max())
    assert 0 < diffs[2] < diffs[1] < diffs[0] < 1e-4
    np.testing.assert_allclose(np.array(diffs[:2]) / np.array(diffs[1:]), 10.0, rtol=0.3)


# ----------------------------------------------------------- the weighted ambient equations
def _eq8_weighted(y, m, a):
    """Eq (8) for Σ aᵢ cos θᵢ = c, written here: u̇ᵢ = −Λ aᵢ sin θᵢ / mᵢ,
    Λ = Σ aⱼ uⱼ² cos θⱼ / Σ aⱼ² sin²θⱼ / mⱼ."""
    n = y.size // 2
    th, u = y[:n], y[n:]
    lam = np.sum(a * u ** 2 * np.cos(th)) / np.sum(a ** 2 * np.sin(th) ** 2 / m)
    return np.concatenate([u, -lam * a * np.sin(th) / m])


def test_weighted_eq8_and_eq17_against_closed_form_and_finite_differences():
    m = np.array([1.0, 2.0, 0.5, 1.5])
    s = RotorSystem(4, masses=m, weights=W4, level=L4)
    th, u = s.random_state(seed=6, speed=1.2)
    y = np.concatenate([th, u])
    f = np.empty(8)
    flow_rhs(y, s.minv, s.weights, f)
    np.testing.assert_allclose(f, _eq8_weighted(y, m, W4), rtol=0, atol=TOL["round"])
    h = 1e-6
    J = np.column_stack([(_eq8_weighted(y + h * e, m, W4) - _eq8_weighted(y - h * e, m, W4))
                         / (2 * h) for e in np.eye(8)])
    X = np.random.default_rng(0).normal(size=(3, 8))
    dy, dX = np.empty(8), np.empty_like(X)
    flow_tangent_rhs(y, X, s.minv, s.weights, dy, dX)
    np.testing.assert_allclose(dX, X @ J.T, rtol=0,
                               atol=TOL["fd_jacobian"] * np.abs(J).max() * np.abs(X).max())


def test_weighted_run_holds_the_invariants_and_gives_exponents():
    """RK4 with projection: |Σ a cos θ − c| and |Σ u a sin θ| stay at rounding; the Lyapunov
    spectrum of a weighted system at a smooth level runs through the tangent kernel."""
    s = RotorSystem(4, weights=W4, level=L4)
    th, u = s.random_state(seed=2)
    res = integrate(s, th, u, 20.0, formulation="ambient", method="rk4", dt=0.01, project=True)
    assert res.drift["constraint"] < 1e-12 and res.drift["tangency"] < 1e-12
    assert res.drift["energy"] < 1e-12
    r = lyapunov_spectrum(s, th, u, 50.0, n_exponents=2, t_transient=0.0)
    assert np.all(np.isfinite(r.exponents)) and r.exponents[0] > 0


# -------------------------------------------------------- chart metric and the Gauss equation
def _closed_form_metric(q, k, m, a, c):
    """g_αβ = m_α δ_αβ + m_k a_α a_β sin q_α sin q_β / (a_k² − (c − Σ_{γ≠k} a_γ cos q_γ)²)."""
    idx = [i for i in range(m.size) if i != k]
    sa = a[idx] * np.sin(q)
    den = a[k] ** 2 - (c - np.sum(a[idx] * np.cos(q))) ** 2
    return np.diag(m[idx]) + m[k] * np.outer(sa, sa) / den


def _pullback_metric(q, k, m, a, c, branch, h=1e-6):
    """Eᵀ diag(m) E with E the embedding's Jacobian by central differences, θₖ(q) =
    ±arccos((c − Σ a_γ cos q_γ) / aₖ)."""
    idx = [i for i in range(m.size) if i != k]

    def emb(q):
        th = np.empty(m.size)
        th[idx] = q
        th[k] = branch * np.arccos((c - np.sum(a[idx] * np.cos(q))) / a[k])
        return th
    E = np.column_stack([(emb(q + h * e) - emb(q - h * e)) / (2 * h) for e in np.eye(q.size)])
    return E.T @ np.diag(m) @ E


def test_closed_form_chart_metric_is_the_pullback():
    """Measured: max |difference| / max |g| ≈ 1e-10 (central differences, h = 1e-6)."""
    m = np.array([1.0, 2.0, 0.5, 1.5])
    s = RotorSystem(4, masses=m, weights=W4, level=L4)
    for seed in range(3):
        th, _ = s.random_state(seed=seed)
        k = int(np.argmax(np.abs(np.sin(th))))
        q = np.delete(th, k)
        g = _closed_form_metric(q, k, m, W4, L4)
        gp = _pullback_metric(q, k, m, W4, L4, np.sign(np.sin(th[k])))
        assert np.abs(g - gp).max() < 1e-8 * np.abs(g).max()


def test_gauss_equation_with_weighted_normal_against_the_closed_form_metric():
    """N = 3: the Gaussian curvature of the closed-form chart metric (SymPy: Brioschi's
    formula from g and its derivatives) equals the ambient Gauss-equation route
    ``sectional_curvature_gauss`` (h = −diag(a cos θ), |∇F|² = Σ a² sin²θ / m), to rounding."""
    sp = pytest.importorskip("sympy")
    m = np.array([1.0, 2.0, 0.5])
    a = np.array([1.0, 1.7, 0.6])
    c = 0.4
    s = RotorSystem(3, masses=m, weights=a, level=c)
    q0, q1 = sp.symbols("q0 q1")
    k = 2
    sa = [a[0] * sp.sin(q0), a[1] * sp.sin(q1)]
    den = a[k] ** 2 - (c - a[0] * sp.cos(q0) - a[1] * sp.cos(q1)) ** 2
    E = m[0] + m[k] * sa[0] ** 2 / den
    F = m[k] * sa[0] * sa[1] / den
    G = m[1] + m[k] * sa[1] ** 2 / den
    # Brioschi's formula for the Gaussian curvature of E du² + 2F du dv + G dv², with the
    # derivatives taken by SymPy and the determinants in NumPy
    d = sp.diff
    terms = sp.lambdify((q0, q1), [E, F, G, d(E, q0), d(E, q1), d(F, q0), d(F, q1), d(G, q0),
                                   d(G, q1), d(E, q1, 2), d(F, q0, q1), d(G, q0, 2)], "math")

    def Kexpr(x, y):
        E_, F_, G_, Eu, Ev, Fu, Fv, Gu, Gv, Evv, Fuv, Guu = terms(x, y)
        M1 = np.array([[-Evv / 2 + Fuv - Guu / 2, Eu / 2, Fu - Ev / 2],
                       [Fv - Gu / 2, E_, F_], [Gv / 2, F_, G_]])
        M2 = np.array([[0.0, Ev / 2, Gu / 2], [Ev / 2, E_, F_], [Gu / 2, F_, G_]])
        return (np.linalg.det(M1) - np.linalg.det(M2)) / (E_ * G_ - F_ ** 2) ** 2
    rng = np.random.default_rng(0)
    checked = 0
    for seed in range(6):
        th, _ = s.random_state(seed=seed)
        if abs(np.sin(th[k])) < 0.2:
            continue
        checked += 1
        v = s.project_tangent(th, rng.normal(size=3))
        w = s.project_tangent(th, rng.normal(size=3))
        Kg = s.sectional_curvature_gauss(th, v, w)
        Ks = Kexpr(th[0], th[1])
        assert abs(Kg - Ks) < TOL["gauss"] * max(1.0, abs(Ks))
    assert checked >= 3


def test_numerical_curvature_route_against_weighted_gauss_route():
    """Route (a), eqs (19)–(21) on the weighted eqs (8), (17), against route (b), the Gauss
    equation with the weighted normal, at the same points and frames: the same tolerances as
    for the paper's manifold (tests/test_curvature.py: an O(Δt²·|K|) second difference)."""
    s = RotorSystem(4, weights=W4, level=L4)
    th, u = s.random_state(seed=5)
    r = curvature_along_trajectory(s, th, u, 20.0, t_transient=5.0)
    scale = np.abs(r.K_exact).max(axis=(1, 2))
    rel = np.abs(r.K_numeric - r.K_exact).max(axis=(1, 2)) / scale
    assert np.median(rel) < 3e-4 and np.quantile(rel, 0.99) < 3e-3
    assert r.params["weights"] == W4.tolist() and r.params["level"] == L4


def test_every_analysis_runs_with_weights_and_level_from_the_command_line(tmp_path, capsys):
    """A scene at a smooth level with unequal weights through the runner and the CLI."""
    import json

    from charts.cli.main import main

    scene = tmp_path / "family.toml"
    scene.write_text(
        'name = "family"\n[system]\nn = 4\nweights = [1.0, 1.3, 0.7, 1.1]\nlevel = 0.4\n'
        "[initial]\nseed = 2\n[run]\nt_final = 40.0\nt_transient = 5.0\nsample_dt = 0.05\n"
        "[effects.lyapunov]\nn_batches = 4\n[effects.curvature]\nroute = \"both\"\n"
        "[effects.angles]\nvariant = \"both\"\n[effects.drift]\n")
    assert main(["run", str(scene), "-o", str(tmp_path / "out"), "--quiet"]) == 0
    r = json.loads((tmp_path / "out" / "result.json").read_text())
    assert r["status"] == "complete"
    assert r["scene"]["system"]["weights"] == W4.tolist() and r["scene"]["system"]["level"] == L4
    th0 = np.array(r["initial_state"]["theta"])
    assert abs(W4 @ np.cos(th0) - L4) < TOL["round"]
    res = r["results"]
    assert res["lyapunov"]["exponents"][0] > 0 and "paper" not in res["lyapunov"]
    assert res["curvature"]["max_abs_route_difference"] < 1e-2
    assert res["angles"]["full"]["min"] > 0
    assert abs(r["drift"]["energy_relative"]) < 1e-8
    bad = tmp_path / "bad.toml"
    bad.write_text('[system]\nn = 4\nlevel = 5.0\n[run]\nt_final = 1.0\n')
    capsys.readouterr()
    assert main(["run", str(bad), "-o", str(tmp_path / "bad"), "--quiet"]) != 0
    assert "[system] level = 5.0 is not allowed" in capsys.readouterr().err
    chart = tmp_path / "chart.toml"      # the chart formulation on the family (was refused)
    chart.write_text('[system]\nn = 4\nlevel = 0.5\n[integrator]\nformulation = "chart"\n'
                     'method = "dop853"\n[run]\nt_final = 1.0\n[effects.drift]\n')
    assert main(["run", str(chart), "-o", str(tmp_path / "chart"), "--quiet"]) == 0
    rc = json.loads((tmp_path / "chart" / "result.json").read_text())
    assert rc["status"] == "complete" and abs(rc["drift"]["energy_relative"]) < 1e-8


def test_sweep_axes_for_level_and_weights():
    """`level` is a system axis like n and speed; weight patterns are the dotted axis
    "system.weights"; each point's scene carries them."""
    from charts.runs.sweep import parse_sweep, sweep_points

    data = {"name": "fam", "scene": {"system": {"n": 4}, "run": {"t_final": 10.0},
                                     "effects": {"lyapunov": {}}},
            "sweep": {"seeds": [0],
                      "parameters": {"level": [0.5, 1.0],
                                     "system.weights": [[1, 1, 1, 1], [1, 2, 1, 2]]}}}
    pts = sweep_points(parse_sweep(data))
    assert len(pts) == 4
    got = {(p.scene.system["level"], tuple(p.scene.system["weights"])) for p in pts}
    assert got == {(0.5, (1, 1, 1, 1)), (1.0, (1, 1, 1, 1)), (0.5, (1, 2, 1, 2)),
                   (1.0, (1, 2, 1, 2))}
