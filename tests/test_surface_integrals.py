"""Exact invariants of the N = 3 surface as tests: the Euler characteristic by a Morse count
(no metric), the Gauss–Bonnet theorem ∫K dA = 2πχ with both curvature routes for masses,
weights and smooth levels, converging as the grid refines, and the leading exponent inside the
bracket of Katok's and Osserman–Sarnak's inequalities."""
import warnings

import numpy as np
import pytest

import charts
from charts.analyses.surface_integrals import (surface_integrals, surface_nodes,
                                               tangent_frames)
from charts.geometry.topology import critical_points, euler_characteristic

# (system, χ): the paper's genus-3 surface, masses, family members of genus 3, spheres (levels
# between the two highest or the two lowest critical values) and two tori (a₃ > a₁ + a₂)
CASES = {
    "paper": (dict(n=3), -4),
    "masses": (dict(n=3, masses=[1.0, 2.0, 0.5]), -4),
    "family": (dict(n=3, weights=[1.0, 1.3, 0.8], level=0.2), -4),
    "masses-family": (dict(n=3, masses=[1.5, 0.7, 1.1], weights=[0.9, 1.2, 1.0], level=-0.4),
                      -4),
    "sphere-top": (dict(n=3, level=2.0), 2),
    "sphere-bottom": (dict(n=3, level=-1.5), 2),
    "two-tori": (dict(n=3, weights=[1.0, 1.0, 5.0]), 0),
}


def _system(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return charts.RotorSystem(**CASES[name][0])


def test_the_morse_count():
    """Critical points of Σ aᵢ cos θᵢ: 2ᴺ of them, index = number of θᵢ = 0; the counts of
    the classical surfaces; a critical level is refused; even N gives 0."""
    values, index = critical_points([1.0, 1.0, 1.0])
    assert values.size == 8 and sorted(index.tolist()) == [0, 1, 1, 1, 2, 2, 2, 3]
    assert values[index == 3].tolist() == [3.0]
    for name, (kw, chi) in CASES.items():
        assert euler_characteristic(kw.get("weights", [1.0] * 3), kw.get("level", 0.0)) == chi
    assert euler_characteristic([1.0] * 4, 0.5) == 0
    with pytest.raises(ValueError, match="critical value"):
        euler_characteristic([1.0, 1.0, 1.0], 1.0)


def test_area_element_is_the_metric_determinant():
    """The quadrature's weights divided by the partition of unity are √det g of eq (13) from
    RotorSystem.metric in the node's chart (an independent route: the generated metric)."""
    s = _system("masses-family")
    theta, dA, chart = surface_nodes(s, 16)
    h2 = (2 * np.pi / 16) ** 2
    sig = np.abs(s.weights * np.sin(theta))
    pou = sig[np.arange(chart.size), chart] ** 8 / np.sum(sig ** 8, axis=1)
    for i in range(0, chart.size, 7):
        g = s.metric(theta[i], int(chart[i]))
        assert dA[i] / (pou[i] * h2) == pytest.approx(np.sqrt(np.linalg.det(g)), rel=1e-12)


def test_frames_are_orthonormal_and_tangent():
    s = _system("masses")
    theta, _, _ = surface_nodes(s, 16)
    P = tangent_frames(s, theta)
    G = np.einsum("sai,i,sbi->sab", P, s.masses, P)
    assert np.abs(G - np.eye(2)).max() < 1e-12
    assert np.abs(np.einsum("sai,si->sa", P, s.weights * np.sin(theta))).max() < 1e-12


@pytest.mark.parametrize("name", sorted(CASES))
def test_gauss_bonnet_with_both_curvature_routes(name):
    """∫K dA → 2πχ as the grid refines, with the generated Riemann tensor (chart route) and
    the ambient Gauss equation; tolerance 1e-6 relative at n_grid = 256 (measured ≤ 1e-9; the
    error falls ~30× per doubling of the grid: the integrand is C³ where a chart ends)."""
    s = _system(name)
    chi = CASES[name][1]
    errors = {}
    for route in ("chart", "gauss"):
        errors[route] = [abs(surface_integrals(s, ng, route).gauss_bonnet_error)
                         for ng in (64, 256)]
    scale = 2 * np.pi * max(abs(chi), 1)
    for route, (coarse, fine) in errors.items():
        assert fine <= 1e-6 * scale, (route, fine)
        assert fine <= coarse or coarse <= 1e-10 * scale, (route, coarse, fine)


def test_paper_surface_values():
    """The paper's surface: K ≤ 0 at every node (eq 22), its area, and the bracket; the two
    routes agree at every node to rounding."""
    r = surface_integrals(charts.RotorSystem(3), 256)
    g = surface_integrals(charts.RotorSystem(3), 256, route="gauss")
    assert r.euler_characteristic == -4 and r.max_curvature <= 0.0 and r.positive_area == 0.0
    assert r.area == pytest.approx(92.8756146, rel=1e-8)
    assert g.total_curvature == pytest.approx(r.total_curvature, rel=1e-12)
    lower, upper = r.entropy_bracket()
    assert lower == pytest.approx(0.46709, abs=2e-5) and upper == pytest.approx(0.520198, abs=1e-6)


def test_refusals():
    with pytest.raises(ValueError, match="N = 3"):
        surface_integrals(charts.RotorSystem(4))
    with pytest.raises(ValueError, match="route"):
        surface_integrals(charts.RotorSystem(3), 16, route="numerical")
    with pytest.raises(ValueError, match="n_grid"):
        surface_integrals(charts.RotorSystem(3), 2)


@pytest.mark.parametrize("name", ["paper", "masses", "family"])
def test_leading_exponent_lies_in_the_entropy_bracket(name):
    """λ₁ at unit speed (two trajectories of T = 3000, each with its batch standard error)
    inside [⟨√(−K)⟩, √(2π|χ|/A)] by three standard errors; the family member has K > 0 on
    1 % of its area, so only Katok's upper bound applies there."""
    s = _system(name)
    lower, upper = surface_integrals(s, 128).entropy_bracket()
    assert upper is not None and (lower is None) == (name == "family")
    for seed in (1, 2):
        r = charts.lyapunov_spectrum(s, *s.random_state(seed=seed), 3000.0)
        lam, se = float(r.exponents[0]), float(r.stderr[0])
        assert lam + 3 * se < upper, (seed, lam, se, upper)
        if lower is not None:
            assert lam - 3 * se > lower, (seed, lam, se, lower)


def test_a_grid_beyond_memory_is_refused_before_it_is_built(monkeypatch):
    import charts.analyses.surface_integrals as quadrature
    import charts.solvers.tangent as tangent
    for module in (tangent, quadrature):      # the check and the remedy's largest grid
        monkeypatch.setattr(module, "memory_budget", lambda: 1 << 30)
    with pytest.raises(ValueError, match=r"2048² cells would need 2\.3 GiB, more than the 1\.0 "
                       r"GiB.*use n_grid <= 1337"):
        surface_integrals(charts.RotorSystem(3), 2048)
