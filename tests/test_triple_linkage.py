"""The triple linkage of Thurston–Weeks–Hunt–MacKay (shared/mechanisms/triple_linkage.md) as a
``charts.mechanism`` instance: chart against ambient trajectories, the intrinsic against the
Gauss-equation curvature, Gauss–Bonnet on its configuration surface
(``charts.mechanism.surface_integrals``) and the limit r → 0, l = R + rδ, in which the
surface becomes the rotor surface Σ cos θᵢ = 3δ (N = 3).

Tolerances, each with its reason, in one place (`TOL`).  The χ expected is the rotor
surface's, by its Morse count (``charts.geometry.topology``: no metric, no quadrature); for
small r the linkage's surface is a smooth deformation of it, hence diffeomorphic.
"""
import numpy as np
import pytest

from charts.geometry.topology import euler_characteristic
from charts.mechanism import (integrate_ambient, integrate_chart, rotors, surface_integrals,
                              triple_linkage)
from charts.mechanism.surface import surface_nodes

TOL = {
    # the two curvature routes are exact formulas on the same jets (no finite differences):
    # they agree to rounding, a few hundred ulps of curvatures of order 0.01–1
    "curvature": 1e-11,
    # RK4 in charts has global error ~ C dt⁴; the DOP853 reference (rtol 1e-11) is ~40 times
    # below the chart error at dt = 0.02 (measured 4.4e-10 over t = 2): its order, measured
    # 3.7 (dt 0.04 → 0.02) and 3.9 (0.02 → 0.01), lies in 4 ± 0.5
    "rk4_order": (3.5, 4.5),
    "chart_vs_ambient": 1e-9,
    # the periodic trapezoidal rule with the smooth partition of unity (p = 8) on 64² nodes
    # per chart: ∫K dA / 2π − χ measured 4e-6 (r = 0.2), 1e-6 (r = 0.05); 2e-4 on 48²
    "gauss_bonnet": 1e-4,
    # the same quadrature on the rotor surface: the mechanism's and the rotor module's weights
    # are the same numbers (equal masses), so area and ∫K agree to rounding
    "same_quadrature": 1e-12,
}
GRID = 64


@pytest.mark.parametrize("params", [dict(r=0.2), dict(r=0.1, l=1.02, joint_mass=0.3),
                                    dict(r=0.3, l=0.95, inertia=2.0)])
def test_gauss_equation_equals_intrinsic_curvature_at_random_points(params):
    """At random points, one at a time and in a batch: the Gauss equation (no chart) equals
    the Riemann tensor of the induced metric, in the best chart and in the second best."""
    L = triple_linkage(**params)
    points = np.array([L.random_state(seed)[0] for seed in range(6)])
    rng = np.random.default_rng(0)
    K = []
    for q in points:
        u, w = (L.project_velocity(q, rng.normal(size=5)) for _ in range(2))
        k = L.gaussian_curvature(q)
        assert abs(L.gauss_equation_curvature(q, u, w) - k) < TOL["curvature"]
        assert abs(L.gaussian_curvature(q, L.charts(q)[1][0]) - k) < TOL["curvature"]
        K.append(k)
    assert np.max(np.abs(L.gauss_equation_curvatures(points) - K)) < TOL["curvature"]
    chart = L.best_chart(points[0])
    assert abs(L.gaussian_curvatures(points[:1], chart)[0] - K[0]) < TOL["curvature"]


def test_chart_and_ambient_trajectories_agree_to_rk4_error():
    """A massive joint and l ≠ R (the run uses three charts, one of them (x, y)): the chart
    integrator (RK4, switching charts) meets the ambient one (DOP853, projected), and the
    difference falls as dt⁴: it is RK4's own error, not a difference of the two flows."""
    L = triple_linkage(0.1, l=1.02, joint_mass=0.1)
    q, v = L.random_state(5)
    _, Qa, Va = integrate_ambient(L, q, v, 2.0, samples=4)
    err = []
    for dt in (0.04, 0.02):
        _, Qc, Vc, used = integrate_chart(L, q, v, 2.0, samples=4, dt=dt)
        err.append(max(np.max(np.abs(Qa - Qc)), np.max(np.abs(Va - Vc))))
    assert len(set(used)) >= 2
    lo, hi = TOL["rk4_order"]
    assert lo < np.log2(err[0] / err[1]) < hi, err
    assert err[1] < TOL["chart_vs_ambient"]


def test_the_quadrature_is_the_rotor_modules():
    """On ``rotors(3)`` the mechanism's surface integral reproduces
    ``charts.analyses.surface_integrals`` (the shared grid and partition of unity)."""
    import charts
    from charts.analyses.surface_integrals import surface_integrals as rotor_integrals
    mine = surface_integrals(rotors(3), 32)
    theirs = rotor_integrals(charts.RotorSystem(3), 32)
    assert abs(mine.area - theirs.area) < TOL["same_quadrature"] * theirs.area
    assert abs(mine.total_curvature - theirs.total_curvature) < TOL["same_quadrature"] * 30


@pytest.mark.parametrize("params, route", [(dict(r=0.2), "chart"),
                                           (dict(r=0.2, joint_mass=0.5), "gauss"),
                                           (dict(r=0.1, l=1.05), "gauss")])
def test_gauss_bonnet_on_the_configuration_surface(params, route):
    """∫K dA = 2πχ: genus 3 (χ = −4) for |3δ| < 1, a sphere (χ = 2) for 1 < |3δ| < 3 (here
    δ = (l − R)/r = 0.5); χ of the rotor surface Σ cos θ = 3δ, by its Morse count."""
    L = triple_linkage(**params)
    delta = (L.parameter_values["l"] - L.parameter_values["R"]) / L.parameter_values["r"]
    chi = euler_characteristic([1.0, 1.0, 1.0], 3 * delta)
    assert chi == (2 if abs(3 * delta) > 1 else -4)
    s = surface_integrals(L, GRID, route=route, euler_characteristic=chi)
    assert abs(s.gauss_bonnet_error / (2 * np.pi)) < TOL["gauss_bonnet"], s
    assert s.params["euler_characteristic_from"] == "given"
    # without a χ given, the nearest integer to ∫K dA / 2π is read
    assert surface_integrals(L, 32, route="gauss").euler_characteristic == chi


def test_nodes_lie_on_the_surface_and_weights_are_positive():
    L = triple_linkage(0.15, l=1.01)
    q, dA = surface_nodes(L, 16)
    assert np.max(np.abs(L._eval("F", q))) < 1e-12 and np.all(dA > 0)


@pytest.mark.parametrize("delta, order", [(0.0, 2.0), (0.1, 1.0)])
def test_small_r_limit_meets_the_rotor_surface(delta, order):
    """l = R + rδ, r → 0: the area tends to the rotor surface's (Σ cos θ = 3δ; 92.876 at
    δ = 0) with order 2 at δ = 0 (r → −r with θ → θ + π is a symmetry of the linkage there,
    so the area is even in r) and order 1 at δ ≠ 0; ∫K dA = 2πχ of the rotor surface at every
    r (Gauss–Bonnet: its "order" is exact).  The order is the log-log slope fitted over
    r = 0.1, 0.05, 0.025: measured 1.97 (δ = 0) and 0.88 (δ = 0.1, the pairwise slopes 0.84,
    0.92 rising to 1 as the O(r²) term fades); asserted within ±0.2 (δ = 0) and ±0.25 (δ ≠ 0)
    of the expected order.  The quadrature's error in the area (3e-5 at 64²) is below 1e-3 of
    the smallest difference (0.017)."""
    chi = euler_characteristic([1.0, 1.0, 1.0], 3 * delta)
    ref = surface_integrals(rotors(3, level=3 * delta), GRID, euler_characteristic=chi)
    if delta == 0.0:
        assert abs(ref.area - 92.876) < 1e-3                 # the conventions note's value
    r = np.array([0.1, 0.05, 0.025])
    diff = []
    for x in r:
        s = surface_integrals(triple_linkage(x, l=1.0 + x * delta), GRID, route="gauss",
                              euler_characteristic=chi)
        assert abs(s.gauss_bonnet_error / (2 * np.pi)) < TOL["gauss_bonnet"]
        diff.append(abs(s.area - ref.area))
    slope = np.polyfit(np.log(r), np.log(diff), 1)[0]
    width = 0.2 if delta == 0.0 else 0.25
    assert order - width < slope < order + width, (slope, diff)
