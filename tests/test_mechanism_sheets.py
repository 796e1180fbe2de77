"""The sheets of a 2-dimensional mechanism found by Newton's method (charts.mechanism.sheets),
the route of ``surface_integrals`` for a mechanism of one's own, against the closed forms of
the rotors and the triple linkage, and against the Gauss–Bonnet theorem with χ from the Morse
count on the arm of docs/mechanisms.md."""
from __future__ import annotations

import numpy as np
import pytest

import charts
from charts.geometry.topology import euler_characteristic
from charts.mechanism.instances import rotors
from charts.mechanism.sheets import newton_sheets
from charts.mechanism.surface import surface_integrals

from test_mechanism_ensembles import arm


@pytest.mark.parametrize("mech, n_grid", [(rotors(3), 24), (charts.triple_linkage(0.2), 8)],
                         ids=["rotors3", "triple_linkage"])
def test_newton_sheets_give_the_closed_forms_integrals(mech, n_grid):
    """The same area and ∫K dA as the closed-form sheets to rounding: 1e-10 relative (a missed
    or doubled branch changes them by a node's share, ~1e-3 here).  Newton may miss a point on
    a fold, where two branches meet and the chart ends: its weight there is ~0 (the partition
    of unity), so the integrals do not see it."""
    closed = surface_integrals(mech, n_grid)
    newton = surface_integrals(mech, n_grid, sheets=newton_sheets)
    assert newton.area == pytest.approx(closed.area, rel=1e-10)
    assert newton.total_curvature == pytest.approx(closed.total_curvature, rel=1e-10)
    assert closed.params["sheets_from"] == "closed form"


def test_a_users_surface_meets_gauss_bonnet_with_the_morse_count():
    """The arm on a rail (no closed form: its sheets are Newton's) has the constraint
    Σ lᵢ sin θᵢ = 0, the level set Σ lᵢ cos φᵢ = 0 of the rotor family (φ = θ − π/2), whose χ
    the Morse count gives: ∫K dA / 2π meets it within the quadrature's error at 64² (1.3e-5
    measured; 1e-3 allowed: a missed branch is off by a whole sheet's share, > 0.1)."""
    mech = arm()
    assert getattr(mech, "sheets", None) is None
    r = surface_integrals(mech, 64)
    chi = euler_characteristic([1.0, 0.8, 0.6], 0.0)
    assert chi == -4
    assert r.total_curvature / (2 * np.pi) == pytest.approx(chi, abs=1e-3)
    assert r.params["sheets_from"].startswith("Newton")


def test_newton_sheets_are_on_the_surface_and_empty_where_it_is():
    """Every point found solves F = 0 at its node's angles; nodes above which the surface has no
    point (|w1 cos t1 + w2 cos t2| > w3 for the rotors of weights (1, 1, 0.5)) have none."""
    mech = rotors(3, weights=[1.0, 1.0, 0.5])
    ta = np.array([0.0, 0.1, np.pi / 2, 2.0])
    tb = np.array([0.0, 0.2, np.pi / 2, -1.0])
    sheets = newton_sheets(mech, (0, 1), ta, tb)
    pts = np.stack(sheets)                                # (sheets, S, 3)
    found = np.isfinite(pts[..., 0])
    assert not found[:, 0].any() and not found[:, 1].any()          # cos sum 2, 1.97 > 0.5
    assert found[:, 2].sum() == 2 and found[:, 3].sum() == 2        # θ3 = ±π/2, ±arccos(…)
    q = pts[found]
    assert np.max(np.abs(mech._eval("F", q))) < 1e-12
    with pytest.raises(charts.MechanismError, match="dimension 3"):
        newton_sheets(rotors(4), (0, 1), ta, tb)


def test_the_public_name_takes_a_users_surface():
    """``charts.surface_integrals`` hands a 2-dimensional Mechanism to the mechanism's
    quadrature (the same bits), keeps the rotors' route for a RotorSystem, and refuses what is
    neither."""
    mech = arm()
    a = charts.surface_integrals(mech, 16)
    b = surface_integrals(mech, 16)
    assert a.area == b.area and a.total_curvature == b.total_curvature
    assert "sheets_from" not in charts.surface_integrals(charts.RotorSystem(3), 16).params
    with pytest.raises(TypeError, match="charts.Mechanism"):
        charts.surface_integrals("arm", 16)
    with pytest.raises(charts.MechanismError, match="sheets must be a function"):
        surface_integrals(mech, 16, sheets=3)
