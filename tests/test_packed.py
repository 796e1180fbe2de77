"""Named fields of the packed parameter arrays (``charts.jit.packed``): the layout arithmetic, and
the formulations' layouts agreeing with what the chart equations read."""
from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from charts.flows.chart import HEAD, WORK, local_parameters
from charts.jit.packed import layout, pack, put, size, value, view
from charts.solvers.ambient_formulation import PAR as AMBIENT_PAR
from charts.solvers.chart_formulation import PAR as CHART_PAR

FIELDS = layout(("n", 0, 1), ("a", 1, 0), ("b", 2, -1), ("x", 0, 1), ("tail", 3, -3))


@pytest.mark.parametrize("n", [3, 4, 7])
def test_fields_tile_the_array_in_order(n):
    """Each field starts where the one before ends; the array is exactly their sum."""
    stops = 0
    for name in ("n", "a", "b", "x", "tail"):
        oa, ob, la, lb = FIELDS[name]
        assert oa * n + ob == stops
        stops += la * n + lb
    assert size(FIELDS, n) == stops == 1 + n + (2 * n - 1) + 1 + (3 * n - 3)


@njit
def _read(par, n, fa, fx, ftail):
    put(par, n, fx, 7.5)
    t = view(par, n, ftail)
    t[0] = -1.0
    return view(par, n, fa).sum(), value(par, n, fx)


def test_compiled_views_read_and_write_the_packed_fields():
    n = 5
    par = pack(FIELDS, n, n=n, a=np.arange(n), b=2.0, tail=np.arange(3 * n - 3))
    total, x = _read(par, n, FIELDS["a"], FIELDS["x"], FIELDS["tail"])
    assert total == np.arange(n).sum() and x == 7.5
    oa, ob, _, _ = FIELDS["tail"]
    assert par[oa * n + ob] == -1.0 and par[-1] == 3 * n - 4
    assert np.all(view(par, n, FIELDS["b"]) == 2.0)


@pytest.mark.parametrize("n", [3, 6])
def test_a_chart_par_begins_with_the_head_the_equations_read_and_ends_with_the_work_area(n):
    for name in ("n", "masses", "weights", "level"):
        assert CHART_PAR[name] == HEAD[name]
    oa, ob, la, lb = CHART_PAR["work"]
    assert (oa + la) * n + ob + lb == size(CHART_PAR, n)     # the work area is last
    assert la * n + lb == WORK * (n - 1)
    # rates' own parameters have the same head and the same work area at the end
    p = local_parameters(np.arange(1.0, n + 1), np.ones(n), 0.5, 0)
    assert p.size == size(HEAD, n) + WORK * (n - 1) and p[0] == n
    assert value(p, n, HEAD["level"]) == 0.5


def test_the_ambient_layout_is_the_size_the_formulation_allocates():
    from charts import RotorSystem
    from charts.solvers.ambient_formulation import AmbientFlow
    s = RotorSystem(4, masses=[1.0, 2.0, 3.0, 4.0])
    th, u = s.random_state(seed=0)
    y, par, ipar = AmbientFlow(s, project=True).initial(th, u, np.zeros((0, 4)))
    assert par.size == size(AMBIENT_PAR, 4)
    assert np.array_equal(view(par, 4, AMBIENT_PAR["masses"]), s.masses)
    assert np.array_equal(view(par, 4, AMBIENT_PAR["minv"]), s.minv)
    assert np.isnan(view(par, 4, AMBIENT_PAR["projected"])).all()
