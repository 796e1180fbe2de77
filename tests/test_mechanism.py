"""charts.mechanism: the symbolic Mechanism against the library's rotor geometry (eqs 8, 22,
the exact Riemann tensor of RotorSystem) and the triple linkage (shared/mechanisms/
triple_linkage.md): intrinsic against Gauss-equation curvature, chart against ambient
trajectories, the r → 0 limit.

Tolerances.  The two curvature routes and the library's closed forms are exact formulas
evaluated in floating point (no finite differences): they agree to a few hundred ulps of the
largest term, so 1e-11 absolute on curvatures of order 0.01–1.  The trajectories are RK4 in
charts (dt = 0.005, local error ~ dt⁵) against DOP853 at rtol 1e-11: 1e-9 over t = 1.5.
"""
import numpy as np
import pytest
import sympy as sp

from charts import RotorSystem
from charts.analyses.curvature import gaussian_curvature_eq22
from charts.flows.ambient import flow_rhs
from charts.mechanism import (Mechanism, MechanismError, integrate_ambient, integrate_chart,
                              rotors, triple_linkage)

CURV_TOL = 1e-11


@pytest.fixture(scope="module")
def rot3():
    return rotors(3)


@pytest.fixture(scope="module")
def rot4():
    return rotors(4)


@pytest.fixture(scope="module")
def linkage():
    return triple_linkage(0.2)


def plane(mech, q, seed):
    rng = np.random.default_rng(seed)
    return (mech.project_velocity(q, rng.normal(size=mech.n)),
            mech.project_velocity(q, rng.normal(size=mech.n)))


# ------------------------------------------------------------------ rotors against the library
def test_rotors3_curvature_both_routes_equal_eq22(rot3):
    for seed in range(8):
        q, _ = rot3.random_state(seed)
        K22 = float(gaussian_curvature_eq22(q))
        u, w = plane(rot3, q, seed)
        assert abs(rot3.gaussian_curvature(q) - K22) < CURV_TOL
        assert abs(rot3.gauss_equation_curvature(q, u, w) - K22) < CURV_TOL
        for chart, _ in rot3.charts(q)[:2]:       # the best two charts give the same K
            assert abs(rot3.gaussian_curvature(q, chart) - K22) < CURV_TOL


def test_rotors4_riemann_and_sectional_against_rotorsystem(rot4):
    rs = RotorSystem(4)
    for seed in range(6):
        q, _ = rot4.random_state(seed)
        u, w = plane(rot4, q, seed)
        K = rs.sectional_curvature(q, u, w)
        assert abs(rot4.sectional_curvature(q, u, w) - K) < CURV_TOL
        assert abs(rot4.gauss_equation_curvature(q, u, w) - K) < CURV_TOL
        k = rs.best_chart(q)
        chart = tuple(i for i in range(4) if i != k)
        assert rot4.best_chart(q) == chart            # the same switching rule (max |sin θ_k|)
        R = rs.riemann(q, chart=k)
        assert np.max(np.abs(rot4.riemann(q, chart) - R)) < 1e-12 * max(1.0, np.max(np.abs(R)))
        assert np.max(np.abs(rot4.metric(q, chart) - rs.metric(q, chart=k))) < 1e-13
        assert np.max(np.abs(rot4.christoffel(q, chart) - rs.christoffel(q, chart=k))) < 1e-12


def test_rotor_acceleration_is_eq8():
    m, a, c = np.array([1.0, 2.0, 0.5, 1.5]), np.array([1.0, 1.3, 0.8, 1.1]), 0.3
    mech = rotors(4, masses=m, weights=a, level=c)
    for seed in range(5):
        q, v = mech.random_state(seed, speed=1.7)
        assert abs(a @ np.cos(q) - c) < 1e-12 and abs(a @ (np.sin(q) * v)) < 1e-12
        dy = np.empty(8)
        flow_rhs(np.concatenate([q, v]), 1.0 / m, a, dy)
        np.testing.assert_allclose(mech.acceleration(q, v), dy[4:], rtol=0, atol=1e-13)


def test_rotor_trajectory_equals_the_librarys_ambient_flow(rot4):
    """integrate_ambient on rotors(4) against charts.integrate(formulation="ambient") (eq 8,
    DOP853 at rtol 1e-10): measured 6e-12 over t = 1; tolerance 1e-9."""
    import charts
    rs = RotorSystem(4)
    th, u = rs.random_state(3)
    res = charts.integrate(rs, th, u, 1.0, formulation="ambient", t_eval=[0.0, 0.5, 1.0])
    _, Q, V = integrate_ambient(rot4, th, u, 1.0, samples=2)
    assert np.max(np.abs(Q - res.theta)) < 1e-9 and np.max(np.abs(V - res.u)) < 1e-9


def test_tangent_acceleration_is_eq17_and_matches_finite_differences():
    from charts.flows.ambient import flow_tangent_rhs
    m, a = np.array([1.0, 2.0, 0.5, 1.5]), np.array([1.0, 1.3, 0.8, 1.1])
    mech = rotors(4, masses=m, weights=a, level=0.3)
    rng = np.random.default_rng(0)
    for seed in range(3):
        q, v = mech.random_state(seed)
        dq, dv = rng.normal(size=4), rng.normal(size=4)
        dy, dX = np.empty(8), np.empty((1, 8))
        flow_tangent_rhs(np.concatenate([q, v]), np.concatenate([dq, dv])[None], 1.0 / m, a, dy, dX)
        np.testing.assert_allclose(mech.tangent_acceleration(q, v, dq, dv), dX[0, 4:], rtol=0,
                                   atol=1e-13)
    # a configuration-dependent metric (rods): central differences, h = 1e-6 (error ~ h²)
    L = triple_linkage(0.3, joint_mass=0.2, rod_mass=0.5)
    q, v = L.random_state(2)
    dq, dv = rng.normal(size=5), rng.normal(size=5)
    h = 1e-6
    fd = (L.acceleration(q + h * dq, v + h * dv) - L.acceleration(q - h * dq, v - h * dv)) / (2 * h)
    np.testing.assert_allclose(L.tangent_acceleration(q, v, dq, dv), fd, rtol=0, atol=1e-8)


def test_phase_tangent_projection(linkage):
    q, v = linkage.random_state(4)
    rng = np.random.default_rng(1)
    dq, dv = linkage.project_phase_tangent(q, v, rng.normal(size=5), rng.normal(size=5))
    F2 = linkage._eval("F2", q)
    J = linkage.jacobian(q)
    assert np.max(np.abs(J @ dq)) < 1e-12
    assert np.max(np.abs(J @ dv + np.einsum("cij,i,j->c", F2, v, dq))) < 1e-12
    again = linkage.project_phase_tangent(q, v, dq, dv)            # a projection: idempotent
    assert np.max(np.abs(np.concatenate(again) - np.concatenate([dq, dv]))) < 1e-12
    # the derivative of the flow's tangent map keeps tangency: (δq, δv) -> (δv, δq̈) is tangent
    # to TC to first order along the flow (checked through a short DOP853 step of both)
    h = 1e-6
    _, Qp, Vp = integrate_ambient(linkage, *_lifted(linkage, q, v, dq, dv, h), 0.2, samples=1,
                                  project=False)
    _, Qm, Vm = integrate_ambient(linkage, *_lifted(linkage, q, v, dq, dv, -h), 0.2, samples=1,
                                  project=False)
    Dq, Dv = (Qp[-1] - Qm[-1]) / (2 * h), (Vp[-1] - Vm[-1]) / (2 * h)
    p1, v1 = (Qp[-1] + Qm[-1]) / 2, (Vp[-1] + Vm[-1]) / 2
    pq, pv = linkage.project_phase_tangent(p1, v1, Dq, Dv)
    assert np.max(np.abs(pq - Dq)) < 1e-6 and np.max(np.abs(pv - Dv)) < 1e-6


def _lifted(mech, q, v, dq, dv, h):
    """A point of TC at distance ~h along (δq, δv): projected onto F = 0 and ker J."""
    p = mech.project_point(q + h * dq)
    return p, mech.project_velocity(p, v + h * dv)


def test_ambient_equations_symbolic(rot3):
    v, acc, lam, eqs = rot3.ambient_equations()
    sol = sp.solve(eqs, [*acc, *lam], dict=True)[0]
    th = rot3.q
    # eqs (4)-(6), unit masses and weights: q̈ = Jᵀλ = −λ sin θ (eq 4), so λ = Λ of eq (6)
    expect = sum(vi ** 2 * sp.cos(t) for vi, t in zip(v, th)) / sum(sp.sin(t) ** 2 for t in th)
    subs = dict(zip(rot3.params, rot3.param_values))
    assert sp.simplify(sol[lam[0]].subs(subs) - expect) == 0


# ------------------------------------------------------------------ the triple linkage
def test_linkage_projection_and_tangency(linkage):
    rng = np.random.default_rng(3)
    for seed in range(5):
        q, v = linkage.random_state(seed)
        assert np.max(np.abs(linkage.constraint(q))) < 1e-12
        assert np.max(np.abs(linkage.jacobian(q) @ v)) < 1e-12
        assert abs(linkage.inner(q, v, v) - 1.0) < 1e-12             # speed 1: vᵀMv = 1
        p = linkage.project_point(q + 0.01 * rng.normal(size=5))
        assert np.max(np.abs(linkage.constraint(p))) < 1e-12
        # the rods have length l: |Q_j − Z| = 1
        th, Z = p[:3], p[3:]
        for j in range(3):
            a = 2 * np.pi * j / 3
            Q = np.array([np.cos(a), np.sin(a)]) + 0.2 * np.array([np.cos(a + th[j]), np.sin(a + th[j])])
            assert abs(np.linalg.norm(Q - Z) - 1.0) < 1e-12


@pytest.mark.parametrize("joint_mass", [0.0, 0.3])
def test_linkage_intrinsic_equals_gauss(joint_mass):
    L = triple_linkage(0.2, joint_mass=joint_mass) if joint_mass else triple_linkage(0.2)
    for seed in range(6):
        q, _ = L.random_state(seed)
        u, w = plane(L, q, seed)
        K = L.gaussian_curvature(q)
        assert abs(L.gauss_equation_curvature(q, u, w) - K) < CURV_TOL
        assert abs(L.sectional_curvature(q, u, w) - K) < CURV_TOL
        second = L.charts(q)[1][0]
        assert abs(L.gaussian_curvature(q, second) - K) < CURV_TOL   # chart-independent
        # the same point given by its chart coordinates (the branch picked by a nearby point)
        s2 = q[list(second)]
        near = q + 1e-3
        assert abs(L.gaussian_curvature(s2, second, near=near) - K) < CURV_TOL
        np.testing.assert_allclose(L.metric(s2, second, near=near), L.metric(q, second), atol=1e-13)


def test_linkage_chart_and_ambient_trajectories_agree(linkage):
    q, v = linkage.random_state(1)
    t, Qa, Va = integrate_ambient(linkage, q, v, 1.5, samples=15)
    _, Qc, Vc, used = integrate_chart(linkage, q, v, 1.5, samples=15, dt=0.005)
    assert len(set(used)) >= 2                       # the run switches charts
    assert np.max(np.abs(Qa - Qc)) < 1e-9 and np.max(np.abs(Va - Vc)) < 1e-9
    E = [linkage.energy(a, b) for a, b in zip(Qa, Va)]
    assert np.ptp(E) < 1e-10


def test_configuration_dependent_metric_rods():
    L = triple_linkage(0.3, joint_mass=0.2, rod_mass=0.5)
    assert not L.constant_metric
    q, v = L.random_state(2)
    t, Qa, Va = integrate_ambient(L, q, v, 1.0, samples=10)
    _, Qc, Vc, _ = integrate_chart(L, q, v, 1.0, samples=10, dt=0.005)
    assert np.max(np.abs(Qa - Qc)) < 1e-9
    assert np.ptp([L.energy(a, b) for a, b in zip(Qa, Va)]) < 1e-10
    with pytest.raises(NotImplementedError):
        L.gauss_equation_curvature(q, *plane(L, q, 0))


def test_linkage_small_r_limit_is_rotor_family():
    """l = R + rδ: at the linkage point with the same chart angles as a point θ of
    Σ cos θ = 3δ, K_linkage − K_rotor = O(r) (measured: order 1.1 at r = 0.02 → 0.01)."""
    delta = 0.1
    rs = RotorSystem(3, level=3 * delta)
    P = np.array([[np.cos(2 * np.pi * j / 3), np.sin(2 * np.pi * j / 3)] for j in range(3)])
    pts = [rs.random_state(s)[0] for s in range(4)]
    errors = []
    for r in (0.04, 0.02, 0.01):
        L = triple_linkage(r, l=1.0 + r * delta)
        e = 0.0
        for th in pts:
            u = rs.project_tangent(th, np.array([1.0, 0.3, -0.5]))
            w = rs.project_tangent(th, np.array([-0.2, 1.0, 0.4]))
            k = int(np.argmax(np.abs(np.sin(th))))
            chart = tuple(i for i in range(3) if i != k)
            q0 = np.concatenate([th, r * 2 / 3 * (np.cos(th) @ P)])   # Z = rζ + O(r²)
            q = L.lift(th[list(chart)], chart, q0)
            e = max(e, abs(L.gaussian_curvature(q) - rs.sectional_curvature(th, u, w)))
        errors.append(e)
    assert errors[0] > errors[1] > errors[2]
    order = np.log2(errors[1] / errors[2])
    assert 0.7 < order < 1.6, errors
    assert errors[2] < 5e-3


def test_linkage_small_positive_curvature_at_finite_r():
    """shared/mechanisms/triple_linkage.md, section 3: at finite r strict K < 0 fails slightly,
    max K ≈ +2e-4 at r = 0.05 and +5e-3 at r = 0.2 (l = R = 1, I = 1), near the 8 former zero
    points θᵢ ∈ {±π/2}.  Measured here: K > 0 at all 8 projected points; the local maximum
    near (π/2, π/2, −π/2) is 2.163e-4 (r = 0.05) and 4.889e-3 (r = 0.2), by both routes."""
    from scipy.optimize import minimize
    for r, lo, hi in ((0.05, 1.5e-4, 3e-4), (0.2, 4e-3, 6e-3)):
        L = triple_linkage(r)
        for signs in ((1, 1, 1), (1, 1, -1), (1, -1, -1), (-1, -1, -1)):
            q0 = L.project_point(np.array([*(np.pi / 2 * np.array(signs)), 0.0, 0.0]))
            assert L.gaussian_curvature(q0) > 0
        chart = L.best_chart(q0)
        q0 = L.project_point(np.array([np.pi / 2, np.pi / 2, -np.pi / 2, 0.0, 0.0]))
        res = minimize(lambda s: -L.gaussian_curvature(s, chart, near=q0), q0[list(chart)],
                       method="Nelder-Mead", options=dict(xatol=1e-6, fatol=1e-12))
        q = L.lift(res.x, chart, q0)
        u, w = L.tangent_basis(q).T
        assert lo < -res.fun < hi
        assert abs(L.gauss_equation_curvature(q, u, w) + res.fun) < CURV_TOL


def test_linkage_gauss_bonnet():
    """∫K dA = 2πχ = −8π (genus 3; the conventions note, section 3) at r = 0.2, l = R = I = 1,
    massless joint: the metric is then the Euclidean one of θ, and the surface is an immersed
    surface of T³.  The sum over the three angle charts (θ_a, θ_b) of the θ-torus (midpoint
    grid 16 × 16), over the sheets above each node: Z from the rods a, b (the intersection
    nearer the centre), θ_k from rod k (two or none), with the partition of unity
    ψ_k = |n_k|⁴/Σ n⁴ (n the unit normal in θ-space), so ψ_k dA = |n_k|³/Σ n⁴ dθ_a dθ_b is
    bounded at the folds.  Measured: χ = −3.998 (16²), −3.999 (32²); area 92.0 (at r = 0.05:
    92.82, the note's limit 92.87)."""
    r, l, N = 0.2, 1.0, 16
    L = triple_linkage(r)
    alpha = 2 * np.pi * np.arange(3) / 3
    P = np.stack([np.cos(alpha), np.sin(alpha)], 1)
    hinge = lambda j, t: P[j] + r * np.array([np.cos(alpha[j] + t), np.sin(alpha[j] + t)])
    h = 2 * np.pi / N
    grid = (np.arange(N) + 0.5) * h
    total = area = 0.0
    for k in range(3):
        a, b = [i for i in range(3) if i != k]
        for ta in grid:
            for tb in grid:
                A, B = hinge(a, ta), hinge(b, tb)
                d = np.linalg.norm(B - A)
                if d >= 2 * l:
                    continue
                mid, perp = (A + B) / 2, np.array([A[1] - B[1], B[0] - A[0]]) / d
                Z = min((mid + s * np.sqrt(l * l - d * d / 4) * perp for s in (1, -1)),
                        key=np.linalg.norm)
                D = P[k] - Z
                c = (l * l - D @ D - r * r) / (2 * r * np.linalg.norm(D))
                if abs(c) >= 1:
                    continue
                for phi in np.arctan2(D[1], D[0]) + np.array([1, -1]) * np.arccos(c):
                    th = np.empty(3)
                    th[[a, b, k]] = ta, tb, phi - alpha[k]
                    q = L.check_point(np.concatenate([th, Z]), tol=1e-12)
                    T = L.tangent_basis(q)[:3]
                    n = np.cross(T[:, 0], T[:, 1])
                    n /= np.linalg.norm(n)
                    w = abs(n[k]) ** 3 / np.sum(n ** 4) * h * h
                    total += L.gaussian_curvature(q) * w
                    area += w
    assert abs(total / (2 * np.pi) + 4) < 0.01, total / (2 * np.pi)
    assert abs(area - 92.0) < 0.2


# ------------------------------------------------------------------ validation
def test_invalid_inputs():
    x, y = sp.symbols("x y")
    with pytest.raises(MechanismError, match="neither a coordinate"):
        Mechanism(["x", "y"], [x ** 2 + y ** 2 - sp.Symbol("a")], masses=[1, 1])
    with pytest.raises(MechanismError, match="exactly one"):
        Mechanism(["x", "y"], [x ** 2 + y ** 2 - 1])
    with pytest.raises(MechanismError, match="distinct"):
        Mechanism(["x", "x"], [x - 1], masses=[1, 1])
    with pytest.raises(MechanismError, match="constraints"):
        Mechanism(["x", "y"], [x, y], masses=[1, 1])
    with pytest.raises(MechanismError, match="symmetric"):
        Mechanism(["x", "y"], [x ** 2 + y ** 2 - 1], sp.Matrix([[1, x], [0, 1]]))
    with pytest.raises(MechanismError, match="one entry per coordinate"):
        Mechanism(["x", "y"], [x ** 2 + y ** 2 - 1], masses=[1])
    with pytest.raises(MechanismError, match="real number"):
        Mechanism(["x", "y"], [x ** 2 + y ** 2 - sp.Symbol("a")], masses=[1, 1],
                  parameters={"a": "one"})
    circle = Mechanism(["x", "y"], [x ** 2 + y ** 2 - 1], masses=[1, 1])
    with pytest.raises(MechanismError, match="rank"):
        circle.check_rank([0.0, 0.0])
    with pytest.raises(MechanismError, match="off the constraint"):
        circle.metric([0.5, 0.5])
    with pytest.raises(MechanismError, match="gaussian_curvature is for 2-dimensional"):
        circle.gaussian_curvature([1.0, 0.0])
    with pytest.raises(MechanismError, match="not tangent"):
        circle.sectional_curvature([1.0, 0.0], [1.0, 0.0], [0.0, 1.0])
    sphere = Mechanism(["x", "y", "z"], [x ** 2 + y ** 2 + sp.Symbol("z") ** 2 - 1], masses=[1, 1, 1])
    with pytest.raises(MechanismError, match="chart coordinates need"):
        sphere.metric([0.1, 0.2])
    with pytest.raises(MechanismError, match="a chart is"):
        circle.metric([1.0, 0.0], chart=(0, 1))
    cone = Mechanism(["x", "y", "z"], [x ** 2 + y ** 2 - sp.Symbol("z") ** 2], masses=[1, 1, 1])
    with pytest.raises(MechanismError, match="singular point"):
        cone.project_point([0.0, 0.0, 0.0])   # on F = 0, but the vertex


def test_with_parameters_shares_the_derivation():
    a, b = triple_linkage(0.1), triple_linkage(0.3, l=1.2, joint_mass=0.5)
    assert a._num is b._num and a.J is b.J                  # derived once
    assert a.parameter_values["r"] == 0.1 and b.parameter_values == {
        "r": 0.3, "l": 1.2, "R": 1.0, "I": 1.0, "m": 0.5, "mu": 0.0}
    q, _ = b.random_state(0)
    assert np.max(np.abs(b.constraint(q))) < 1e-12 and np.max(np.abs(a.constraint(q))) > 1e-3
    with pytest.raises(MechanismError, match="not a parameter"):
        a.with_parameters(rr=1.0)
    with pytest.raises(MechanismError, match="positive"):
        triple_linkage(-0.1)


def test_circle_is_flat_and_sphere_has_curvature_one_over_radius_squared():
    x, y, z, a = sp.symbols("x y z a")
    sphere = Mechanism(["x", "y", "z"], [x ** 2 + y ** 2 + z ** 2 - a ** 2], masses=[1, 1, 1],
                       parameters={"a": 2.0})
    for seed in range(3):
        q, _ = sphere.random_state(seed)
        assert abs(np.linalg.norm(q) - 2.0) < 1e-12
        assert abs(sphere.gaussian_curvature(q) - 0.25) < 1e-12
        assert abs(sphere.gauss_equation_curvature(q, *plane(sphere, q, seed)) - 0.25) < 1e-12


def test_docs_example_arm_on_a_rail():
    """docs/mechanisms.md's own mechanism (a configuration-dependent metric): its first code
    block runs; K is the same in every well-conditioned chart (no Gauss route for this metric).
    Rounding grows steeply as a chart's score σ falls (the third derivatives of the chart
    map scale as σ⁻⁵): measured 1e-14 at σ = 0.39, 6e-13 at 0.26, 1.5e-10 at 0.12; hence
    charts within 0.3 of the best score."""
    import contextlib
    import io
    import re
    from pathlib import Path
    text = (Path(__file__).resolve().parent.parent / "docs" / "mechanisms.md").read_text()
    block = re.findall(r"```python\n(.*?)```", text, re.S)[0]
    ns, out = {}, io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(block, "docs/mechanisms.md", "exec"), ns)
    arm = ns["arm"]
    assert not arm.constant_metric
    err = float(re.search(r"max \|q_ambient − q_chart\| = (\S+)", out.getvalue()).group(1))
    assert err < 1e-8
    for seed in range(3):
        q, _ = arm.random_state(seed)
        ranked = arm.charts(q)
        K = [arm.gaussian_curvature(q, c) for c, score in ranked if score > 0.3 * ranked[0][1]]
        assert len(K) >= 2 and np.ptp(K) < 1e-10 * max(1.0, abs(K[0]))
