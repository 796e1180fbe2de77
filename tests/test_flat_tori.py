"""Certified non-hyperbolicity for N ≥ 4: the antipodal torus (pairs θⱼ = θᵢ + π, the rest at
π/2) proved flat and totally geodesic by the library's symbolic chart geometry, and the
monodromy of its closed geodesic showing the in-torus Jacobi fields (bounded and linear)."""
import warnings

import numpy as np
import pytest
import sympy as sp

import charts
from charts.analyses.flat_tori import _symbolic_proof, antipodal_torus, certify_flat_torus
from charts.analyses.exact_curvature import exact_curvatures
from charts.cli.main import main


@pytest.mark.parametrize("n", [4, 5, 6])
def test_paper_manifolds_hold_a_flat_totally_geodesic_torus(n):
    cert = certify_flat_torus(charts.RotorSystem(n))
    assert cert.verdict == "not hyperbolic" and cert.dimension == n // 2
    assert all(step["holds"] for step in cert.proof) and len(cert.proof) == 5
    m = cert.monodromy
    # RK4 with 4096 steps per period: the torus is invariant to rounding, the closed geodesic
    # closes to the step's error (straight lines: RK4 is exact up to the multiplier's rounding)
    assert m["max_distance_from_torus"] < 1e-10 and m["return_error"] < 1e-10
    assert m["jordan_residual"] < 1e-10 and m["position_residual"] < 1e-12
    # transverse to the torus the orbit is hyperbolic (a ± pair of exponents)
    ex = m["transverse_exponents"]
    assert len(ex) >= 2 and ex[0] == pytest.approx(-ex[-1], rel=1e-8) and ex[-1] > 0.1


def test_masses_pair_up_or_leave_no_torus():
    s = charts.RotorSystem(4, masses=[1.0, 2.0, 1.0, 2.0])
    assert antipodal_torus(s) == ([(0, 2), (1, 3)], [])
    assert certify_flat_torus(s).verdict == "not hyperbolic"
    assert certify_flat_torus(charts.RotorSystem(4, masses=[1.0, 2.0, 3.0, 4.0])).verdict == \
        "no antipodal torus"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert antipodal_torus(charts.RotorSystem(4, level=0.5)) is None


def test_n3_gives_a_closed_geodesic_only():
    """One pair: T is a circle, no contradiction with the Anosov property of N = 3."""
    cert = certify_flat_torus(charts.RotorSystem(3))
    assert cert.verdict == "no conclusion" and cert.dimension == 1


def test_a_set_off_the_level_set_fails_the_proof():
    """The proof can fail: pairs at θⱼ = θᵢ + π/2 are not on Σ cos θ = 0, nor geodesic."""
    s = charts.RotorSystem(4)
    steps = _symbolic_proof(s, [(0, 1), (2, 3)], [], offset=sp.pi / 2)
    assert not steps[0]["holds"] and not steps[2]["holds"]


def test_torus_planes_are_flat_by_the_numerical_routes():
    """Independent of the symbolic proof: the sectional curvature of the torus's tangent
    plane, from the generated Riemann tensor and from the Gauss equation, is 0 at random
    points of the torus (to rounding)."""
    s = charts.RotorSystem(4)
    rng = np.random.default_rng(0)
    t = rng.uniform(-np.pi, np.pi, size=(20, 2))
    t = t[np.all(np.abs(np.sin(t)) > 0.1, axis=1)]            # away from the cone points
    theta = np.stack([t[:, 0], t[:, 0] + np.pi, t[:, 1], t[:, 1] + np.pi], axis=1)
    P = np.zeros((theta.shape[0], 2, 4))
    P[:, 0, [0, 1]] = P[:, 1, [2, 3]] = 1 / np.sqrt(2)
    for route in ("chart", "gauss"):
        K = exact_curvatures(s, theta, P, route)
        assert np.abs(K).max() < 1e-12, route


def test_verdict_command_for_n4(capsys):
    assert main(["verdict", "--n", "4"]) == 0
    out = capsys.readouterr().out
    assert "not hyperbolic" in out and "FAILED" not in out
    assert main(["verdict", "--n", "4", "5", "--masses", "1", "1", "1", "1"]) == 2
