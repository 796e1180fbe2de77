"""The certified sign of the N = 3 curvature: the paper's surface is proved K ≤ 0 with zeros
exactly at the eight points θ = (±π/2, ±π/2, ±π/2) (the paper's claim after eq 22), from the
library's own symbolic chart curvature; family members where the quadrature sees K > 0 get a
proved positive box, checked against the numerical curvature there; ``charts verdict``."""
import json
import warnings

import numpy as np
import pytest
import sympy as sp

import charts
from charts.analyses.curvature_certificate import certify_curvature_sign, sign_polynomials
from charts.analyses.exact_curvature import exact_curvatures
from charts.analyses.surface_integrals import surface_integrals, tangent_frames
from charts.cli.main import main


def _system(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return charts.RotorSystem(3, **kw)


@pytest.mark.parametrize("k", [0, 1, 2])
def test_paper_sign_polynomial_is_a_negative_definite_form(k):
    """sign K = sign P with P = −(x² + xy + y²) = −((x + y/2)² + 3y²/4), x, y the chart's
    cosines, and Q = (2x² + 2xy + 2y² − 3)² — eq (22) read through the chart."""
    P, Q, x, y = sign_polynomials(_system(), k)
    assert sp.expand(P.as_expr() + x ** 2 + x * y + y ** 2) == 0
    assert sp.expand(Q.as_expr() - (2 * x ** 2 + 2 * x * y + 2 * y ** 2 - 3) ** 2) == 0


def test_paper_surface_is_certified_nonpositive_with_eight_isolated_zeros():
    cert = certify_curvature_sign(_system())
    assert cert.verdict == "nonpositive" and cert.open_boxes == 0
    assert sorted(tuple(z["value"]) for z in cert.zeros) == sorted(
        (a * np.pi / 2, b * np.pi / 2, c * np.pi / 2) for a in (1, -1) for b in (1, -1)
        for c in (1, -1))
    assert all(ch["zero"] == 4 for ch in cert.charts)   # (0, 0) is a corner of four boxes
    assert abs(charts.gaussian_curvature_eq22(np.array([[np.pi / 2] * 3]))[0]) < 1e-30


@pytest.mark.parametrize("kw", [dict(masses=[1.0, 2.0, 0.5]), dict(weights=[1.0, 1.2, 0.9])],
                         ids=["masses", "weights-level-0"])
def test_other_nonpositive_members(kw):
    """Masses and weights at level 0 keep K ≤ 0 (the second fundamental form vanishes only
    where every cosine does): certified, as the quadrature's largest K (≤ 1e-30) says."""
    s = _system(**kw)
    assert surface_integrals(s, 64).max_curvature <= 1e-30
    cert = certify_curvature_sign(s)
    assert cert.verdict == "nonpositive" and len(cert.zeros) == 8


@pytest.mark.parametrize("kw", [dict(weights=[1.0, 1.3, 0.8], level=0.2), dict(level=0.3),
                                dict(level=2.0)], ids=["family", "level-0.3", "sphere"])
def test_positive_curvature_is_proved_where_the_quadrature_sees_it(kw):
    """K > 0 somewhere (quadrature) ⇒ a proved box; at the box's centre the numerical
    curvature (generated Riemann tensor, a route without the certificate's algebra) is
    positive on the surface points above it."""
    s = _system(**kw)
    assert surface_integrals(s, 64).max_curvature > 0
    cert = certify_curvature_sign(s)
    assert cert.verdict == "positive somewhere"
    b = cert.positive_box
    k = b["chart"]
    i, j = [q for q in range(3) if q != k]
    a, c = s.weights, s.level
    x, y = np.mean(b["x"]), np.mean(b["y"])
    theta = np.empty(3)
    theta[i], theta[j] = np.arccos(x / a[i]), np.arccos(y / a[j])
    theta[k] = np.arccos((c - x - y) / a[k])
    assert abs(np.sum(a * np.cos(theta)) - c) < 1e-12
    K = exact_curvatures(s, theta[None], tangent_frames(s, theta[None]))[0, 0, 0]
    assert K > 0


def test_refusals():
    with pytest.raises(ValueError, match="N = 3"):
        certify_curvature_sign(charts.RotorSystem(4))


def test_verdict_command(tmp_path, capsys):
    out = tmp_path / "v.json"
    rc = main(["verdict", "--n", "3", "--grid", "128", "--t-final", "400", "--seeds", "3",
               "--json", str(out)])
    text = capsys.readouterr().out
    assert rc == 0, text
    [rep] = json.loads(out.read_text())
    assert rep["certificate"]["verdict"] == "nonpositive"
    assert rep["routes"]["chart"]["euler_characteristic"] == -4
    assert "Gauss-Bonnet, gauss route" in text and "K = 0 exactly at" in text
    assert main(["verdict", "--n", "3", "--level", "1"]) == 2   # a critical level: one line
    assert "critical value" in capsys.readouterr().err
