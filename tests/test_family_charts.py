"""The chart side of the family Σ aᵢ cos θᵢ = c (docs/families.md): the closed-form chart
metric against the generated (family module) and the structured kernels; the Gauss equation
with the weighted normal against the chart Riemann tensor; chart against ambient trajectories;
the paper's case a = 1, c = 0 bit for bit the stored references (default and explicit weights 1); charts used outside
their domain."""
import numpy as np
import pytest

from charts import RotorSystem, integrate
from charts.geometry import structured
from charts.geometry.kernels import chart_module

from scenarios import rel_err

#: The closed form, the generated and the structured kernels evaluate the same rational
#: functions of sin/cos in a different order: measured ≤ 3e-15 relative (largest entry) at
#: points with |C| ≤ 0.9 aₖ; 1e-12 leaves room for the metric's condition number.
KERNEL_TOL = 1e-12
#: Weights of the weighted systems (every one distinct, not all 1).
W5 = np.array([1.0, 1.6, 0.7, 1.2, 0.9])


def closed_form_metric(theta, k, m, a, c):
    """g_αβ = m_α δ_αβ + m_k a_α a_β sin θ_α sin θ_β / (a_k² − (c − Σ_{γ≠k} a_γ cos θ_γ)²),
    written here from docs/families.md."""
    idx = [i for i in range(theta.size) if i != k]
    s = a[idx] * np.sin(theta[idx])
    D = a[k] ** 2 - (c - np.sum(a[idx] * np.cos(theta[idx]))) ** 2
    return np.diag(m[idx]) + m[k] * np.outer(s, s) / D


def family(n, level, weights=None, masses=None):
    m = np.linspace(0.6, 1.8, n) if masses is None else masses
    return RotorSystem(n, masses=m, weights=weights, level=level)


def systems():
    """(N, system) for N = 3, 4, 5: a level alone, weights with a level."""
    return [family(3, 0.4), family(4, 0.5), family(5, 0.85, W5),
            family(4, -0.7, np.array([0.5, 1.5, 1.0, 2.0]))]


@pytest.mark.parametrize("index", range(4))
def test_closed_form_metric_against_generated_and_structured(index):
    s = systems()[index]
    n, d = s.n, s.n - 1
    gen = chart_module(n)
    for seed in range(6):
        theta, _ = s.random_state(seed=seed)
        for k in range(n):
            if abs(s.weights[k] * np.sin(theta[k])) < 0.2:   # well inside chart k only
                continue
            ref = closed_form_metric(theta, k, s.masses, s.weights, s.level)
            q, _ = s.to_chart(theta, theta, k)
            ml = np.append(np.delete(s.masses, k), s.masses[k])
            al = np.append(np.delete(s.weights, k), s.weights[k])
            for kern in (gen, structured):
                assert rel_err(kern.metric(q, ml, al, s.level, np.empty((d, d))), ref) < KERNEL_TOL
            assert rel_err(s.metric(theta, chart=k), ref) < KERNEL_TOL
            g = s.metric(theta, chart=k)
            assert rel_err(s.metric_inverse(theta, chart=k) @ g, np.eye(d)) < KERNEL_TOL


@pytest.mark.parametrize("index", range(4))
def test_gauss_equation_with_weighted_normal_against_chart_riemann(index):
    """K from the chart's Riemann tensor (every chart with |aₖ sin θₖ| ≥ 0.2, full array and
    curvature operator) = the Gauss equation with h = −diag(a cos θ), |∇F|² = Σ a² sin²θ/m
    (ambient, O(N)); the Riemann identities hold."""
    s = systems()[index]
    rng = np.random.default_rng(index)
    for seed in range(4):
        theta, u = s.random_state(seed=seed)
        w = s.project_tangent(theta, rng.normal(size=s.n))
        ref = s.sectional_curvature_gauss(theta, u, w)
        for k in range(s.n):
            if abs(s.weights[k] * np.sin(theta[k])) < 0.2:
                continue
            assert s.sectional_curvature(theta, u, w, chart=k) == pytest.approx(ref, rel=1e-10, abs=1e-13)
            R = s.riemann(theta, chart=k)
            x, y = np.delete(u, k), np.delete(w, k)
            g = s.metric(theta, chart=k)
            K = np.einsum("abcd,a,b,c,d->", R, x, y, x, y) / ((x @ g @ x) * (y @ g @ y) - (x @ g @ y) ** 2)
            assert K == pytest.approx(ref, rel=1e-10, abs=1e-13)
            tol = 1e-12 * np.abs(R).max()
            assert np.abs(R + R.transpose(1, 0, 2, 3)).max() < tol
            assert np.abs(R - R.transpose(2, 3, 0, 1)).max() < tol
            assert np.abs(R + R.transpose(0, 2, 3, 1) + R.transpose(0, 3, 1, 2)).max() < tol


def _angle_gap(a, b):
    return np.abs(np.angle(np.exp(1j * (a - b)))).max()


@pytest.mark.parametrize("system", [family(4, 0.5, masses=np.ones(4)), family(5, 0.85, W5),
                                    family(7, 1.1, np.linspace(0.7, 1.4, 7))],
                         ids=["N4-level0.5", "N5-weighted", "N7-weighted-structured"])
def test_chart_against_ambient_trajectories(system):
    """Eqs (14)+(16) in charts (switching) against eq (8) in ambient angles, DOP853 at
    rtol = atol = 1e-12 over t = 20.  Measured gap ≤ 3e-9 (N = 4, 5, 7); 1e-7 is the bound."""
    theta, u = system.random_state(seed=2)
    kw = dict(method="dop853", rtol=1e-12, atol=1e-12, t_eval=np.linspace(0, 20, 41))
    ch = integrate(system, theta, u, 20.0, formulation="chart", **kw)
    am = integrate(system, theta, u, 20.0, formulation="ambient", **kw)
    assert len(ch.switches) > 0
    assert _angle_gap(ch.theta, am.theta) < 1e-7
    assert np.abs(ch.u - am.u).max() < 1e-7
    F = (np.cos(ch.theta) * system.weights).sum(axis=1) - system.level
    assert np.abs(F).max() < 1e-12          # the chart keeps the weighted constraint exactly


# The paper's case through the chart code (N = 4 with masses 1, 2, 0.5, 1.5,
# random_state(seed=5); N = 7 equal masses, seed 1), stored from the code before the weights
# existed.  Since the sin/cos of the points inside a step are shifted from the step's start
# (charts.flows.chart.point_sincos) the two DOP853 runs end within 7.1e-15 (N = 4, t = 10) and
# 1.8e-15 (N = 7, t = 5) of those bits, the RK4 run on them: the references are now the
# shifted code's, the geometry's are the code's before the weights.
REF_CHART_DOP853 = ['0x1.25e2f6ad4adb6p+0', '0x1.c2a8c2857b78dp+1', '-0x1.abfdfb6913458p+2',
                    '-0x1.fbaff7d0444b7p+0']
REF_CHART_RK4_U = ['0x1.44597566b4da8p-1', '-0x1.1b5e7e42e11bfp-2', '-0x1.5f0eb8f548190p-1',
                   '0x1.7f9177ace745fp-2']
REF_GEOMETRY = ('-0x1.68b4bd22de614p-2', '-0x1.a49c0553b508ap-8', '0x1.5bd7e0eec90aap-8',
                '-0x1.9dfee6a2076f1p-1', '-0x1.afde6398fcb90p-4')
REF_N7 = ['0x1.c78e6a8e5d2a0p+0', '0x1.312fe05330866p+1', '-0x1.7ba1923075da8p+0',
          '0x1.4288e5acc6327p+2', '-0x1.f197a0e8d0cb8p+1', '-0x1.c2842a19d1866p-1',
          '-0x1.cc86f50ccafd1p-1']


@pytest.mark.filterwarnings("ignore::charts.geometry.system.CriticalLevelWarning")  # explicit weights 1, c = 0 (N = 4)
@pytest.mark.parametrize("weights", [None, np.ones(4)], ids=["default", "weights-1"])
def test_paper_case_chart_route_keeps_its_bits(weights):
    s = RotorSystem(4, masses=[1.0, 2.0, 0.5, 1.5], weights=weights, level=0.0)
    th, u = s.random_state(seed=5)
    r = integrate(s, th, u, 10.0, formulation="chart", method="dop853", rtol=1e-10)
    assert [float(x).hex() for x in r.theta[-1]] == REF_CHART_DOP853 and len(r.switches) == 3
    r4 = integrate(s, th, u, 2.0, formulation="chart", method="rk4", dt=0.01)
    assert [float(x).hex() for x in r4.u[-1]] == REF_CHART_RK4_U
    R = s.riemann(th, chart=0)
    w = s.project_tangent(th, np.array([1.0, -2.0, 0.5, 0.3]))
    got = (R[0, 1, 0, 1], R[0, 1, 0, 2], R[1, 2, 0, 2], s.christoffel(th).sum(),
           s.sectional_curvature(th, u, w))
    assert tuple(float(x).hex() for x in got) == REF_GEOMETRY
    s7 = RotorSystem(7)                      # structured kernels
    th7, u7 = s7.random_state(seed=1)
    r7 = integrate(s7, th7, u7, 5.0, formulation="chart", method="dop853", rtol=1e-10)
    assert [float(x).hex() for x in r7.theta[-1]] == REF_N7


def test_limit_c_to_zero_and_weights_to_one_of_the_chart_geometry():
    """Metric and Riemann tensor of the family module at (a = 1 + ε b, c = ε c₁) tend to the
    paper's module's, linearly in ε (ratio of consecutive differences 10 per decade)."""
    n, k, d = 5, 4, 4
    theta, _ = RotorSystem(n).random_state(seed=3)
    q, m = theta[:-1], np.linspace(0.6, 1.8, n)
    paper, fam = chart_module(n, paper=True), chart_module(n)
    one = np.ones(n)
    ref_g = paper.metric(q, m, one, 0.0, np.empty((d, d)))
    ref_R = paper.riemann(q, m, one, 0.0, np.empty((d,) * 4))
    b = np.array([0.3, -0.2, 0.5, 0.1, -0.4])
    diffs = []
    for eps in (1e-4, 1e-5, 1e-6):
        a, c = 1 + eps * b, 0.7 * eps
        diffs.append((np.abs(fam.metric(q, m, a, c, np.empty((d, d))) - ref_g).max(),
                      np.abs(fam.riemann(q, m, a, c, np.empty((d,) * 4)) - ref_R).max()))
    diffs = np.array(diffs)
    np.testing.assert_allclose(diffs[:2] / diffs[1:], 10.0, rtol=0.05)
    assert np.array_equal(fam.metric(q, m, one, 0.0, np.empty((d, d))), ref_g) or \
        rel_err(fam.metric(q, m, one, 0.0, np.empty((d, d))), ref_g) < KERNEL_TOL


def test_chart_outside_its_domain_is_a_clear_error():
    s = family(4, 0.6, np.array([1.0, 2.0, 1.0, 1.5]))
    theta, u = s.random_state(seed=1)
    # q with |Σ a cos q − c| ≥ a_k: no θ_k solves the constraint in chart 0 (a_0 = 1)
    with pytest.raises(ValueError, match=r"outside the domain of chart 0: \|sum a cos q - level\|"):
        s.from_chart(np.zeros(3), np.zeros(3), 0, 1)
    on_edge = s.project_point(np.array([0.0, 1.2, 2.0, 1.0]))   # sin θ_0 = 0 stays on the manifold
    assert abs(np.sin(on_edge[0])) < 1e-12
    with pytest.raises(ValueError, match="outside the domain of chart 0"):
        s.metric(on_edge, chart=0)
    assert s.metric(on_edge).shape == (3, 3)                     # the best chart works
    # within ~1e-8 of the edge |sin θ₀| passes the tolerance but the chart's divisor
    # D = a₀² − (Σ a cos q − c)² rounds to 0: refused as outside the chart (not inf, nan)
    near = s.project_point(np.array([1e-9, 1.2, 2.0, 1.0]))
    assert 1e-10 < abs(np.sin(near[0])) < 1e-8
    for f in (s.metric, s.christoffel, s.riemann):
        with pytest.raises(ValueError, match="outside the domain of chart 0"):
            f(near, chart=0)
    assert np.isfinite(s.riemann(near)).all()
    # round trip through every chart whose domain holds the point
    for k in range(4):
        if abs(np.sin(theta[k])) > 0.05:
            q, v = s.to_chart(theta, u, k)
            th2, u2 = s.from_chart(q, v, k, int(np.sign(np.sin(theta[k]))))
            assert _angle_gap(th2, theta) < 1e-12 and np.abs(u2 - u).max() < 1e-12


def test_exact_curvature_at_a_singular_point_is_a_clear_error():
    """Route (b) at a cone point (every sin θ = 0 on the critical level of the family
    (1, 2, 1, 2)): no chart's Riemann tensor is defined there, and the route says so instead
    of returning nan."""
    import warnings

    from charts.analyses.curvature import exact_curvature_matrix
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                  # the critical level's own warning
        s = RotorSystem(4, weights=[1.0, 2.0, 1.0, 2.0])
    with pytest.raises(ValueError, match=r"theta\[0\] = .* singular point of the manifold"):
        exact_curvature_matrix(s, np.array([0.0, 0.0, np.pi, np.pi]), np.eye(4)[:3])
