"""The chart right-hand side without eq (16) (``charts.flows.chart.chart_rates(...,
transport=False)``): what a run that transports no vector compiles.  Its geodesic rates are
the full right-hand side's bit for bit; given a vector, it answers NaN, which the loop stops
at; `integrate` takes it exactly when no vector is transported."""
import numpy as np
import pytest

import charts
from charts.flows.chart import local_parameters
from charts.solvers import chart_formulation
from charts.solvers.chart_formulation import chart_rhs


def _state(n, vectors):
    system = charts.RotorSystem(n)
    theta, u = system.random_state(seed=3)
    k = system.best_chart(theta)
    parts = [np.delete(theta, k), np.delete(u, k)] + [np.delete(u, k)] * vectors
    par = local_parameters(system.masses, system.weights, system.level, k)
    return np.concatenate(parts), par


@pytest.mark.parametrize("n", [3, 5])
def test_without_transport_the_geodesic_rates_are_the_same_bits(n):
    y, par = _state(n, 0)
    full, bare = np.empty_like(y), np.empty_like(y)
    h_full = chart_rhs(n, True, transport=True)(y, par.copy(), full)
    h_bare = chart_rhs(n, True, transport=False)(y, par.copy(), bare)
    assert h_full == h_bare
    assert np.array_equal(full, bare)


def test_a_vector_given_to_the_bare_right_hand_side_gets_nan_rates():
    y, par = _state(4, 1)
    dy = np.empty_like(y)
    chart_rhs(4, True, transport=False)(y, par, dy)
    d = 3
    assert np.isfinite(dy[:2 * d]).all() and np.isnan(dy[2 * d:]).all()


def test_integrate_compiles_eq_16_only_for_transported_vectors(monkeypatch):
    asked = []
    real = chart_formulation.chart_rhs

    def spy(n, paper=False, transport=True):
        asked.append(transport)
        return real(n, paper, transport)
    monkeypatch.setattr(chart_formulation, "chart_rhs", spy)
    system = charts.RotorSystem(3)
    theta, u = system.random_state(seed=1)
    plain = charts.integrate(system, theta, u, 1.0, method="rk4")
    carried = charts.integrate(system, theta, u, 1.0, method="rk4", transport=u)
    assert asked == [False, True]
    # fixed steps (DOP853's error control also weighs the vectors): the same state, bit for bit
    assert np.array_equal(plain.theta, carried.theta) and np.array_equal(plain.u, carried.u)
