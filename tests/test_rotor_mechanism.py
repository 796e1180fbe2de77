"""A RotorSystem is a charts.Mechanism: its structured O(N) routes against the generic
(symbolic-jet) routes of a Mechanism on the same rotors, a chart in either form, the
Mechanism's forms of the rotor methods' arguments, pickling, and nothing derived at
construction.

Tolerances (named in TOL, each with its reason).
"""
import pickle

import numpy as np
import pytest

import charts
from charts.flows.ambient import flow_rhs, flow_tangent_rhs
from charts.analyses.mechanism_curvature import mechanism_curvature
from charts.mechanism import Mechanism, integrate_chart, rotors
from charts.mechanism.instances import _MODELS
from charts.mechanism.surface import surface_integrals

TOL = {
    # the structured kernels and the generic route (the implicit function theorem on the
    # lambdified jets, then NumPy's einsum/inv) are the same quantities by different
    # formulas: rounding of order 1e-16 amplified by the chart's condition, 1/|a_k sin θ_k|
    # up to its cube in the Riemann tensor; at the states below |a_k sin θ_k| ≥ 0.2 in the
    # best chart, so ≤ 1e3 · 1e-16 · the largest entry; 1e-11 relative leaves a margin ~100
    "routes": 1e-11,
    # eq (8) in closed form against the KKT solve of a Mechanism (a 2×2-block system of
    # order N + 1, LU): the same quantity, rounding only
    "kkt": 1e-12,
}

#: (N, masses, weights, level): the paper's case and unequal masses, weights and level.
SYSTEMS = [(3, None, None, 0.0), (4, None, None, 0.0), (5, None, None, 0.0),
           (3, [1.0, 2.0, 0.5], [1.0, 1.5, 2.0], 0.3),
           (4, [0.7, 1.0, 1.3, 2.0], [2.0, 1.0, 1.0, 1.5], -0.4),
           (5, [1.0, 3.0, 1.0, 0.5, 2.0], [1.0, 1.2, 0.8, 1.1, 0.9], 0.2)]


def _close(a, b, tol):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.max(np.abs(a - b)) <= tol * max(1.0, np.max(np.abs(b)))


def _state(system, seed):
    """A random state whose best chart is well conditioned (TOL["routes"]), and a second
    tangent vector."""
    for s in range(seed, seed + 100):
        theta, u = system.random_state(seed=s)
        if np.max(np.abs(system.weights * np.sin(theta))) >= 0.2:
            w = system.project_tangent(theta, np.random.default_rng(s).normal(size=system.n))
            return theta, u, w
    raise AssertionError("no well-conditioned state")


@pytest.mark.parametrize("n, masses, weights, level", SYSTEMS)
def test_structured_routes_meet_the_generic_routes(n, masses, weights, level):
    """Metric, Christoffel symbols, Riemann tensor and sectional curvature of the rotors'
    kernels against the Mechanism's jets (``RotorSystem.mechanism``) and the Gauss equation,
    and the ambient acceleration and its linearisation (eqs 8, 17) against the KKT solves."""
    system = charts.RotorSystem(n, masses, weights, level)
    assert isinstance(system, Mechanism)
    generic = system.mechanism
    assert type(generic) is Mechanism and np.array_equal(generic.param_values,
                                                         system.param_values)
    for seed in (1, 7):
        theta, u, w = _state(system, seed)
        k = system.best_chart(theta)
        ind = tuple(i for i in range(n) if i != k)
        for what in ("metric", "christoffel", "riemann"):
            mine = getattr(system, what)(theta, k)
            assert np.array_equal(getattr(system, what)(theta, ind), mine)    # either form
            assert _close(mine, getattr(generic, what)(theta, ind), TOL["routes"]), what
        K = system.sectional_curvature(theta, u, w)
        for other in (generic.sectional_curvature(theta, u, w, ind),
                      system.gauss_equation_curvature(theta, u, w),
                      Mechanism.sectional_curvature(system, theta, u, w)):
            assert abs(other - K) <= TOL["routes"] * max(1.0, abs(K))
        dy = np.empty(2 * n)
        flow_rhs(np.concatenate([theta, u]), system.minv, system.weights, dy)
        assert _close(system.acceleration(theta, u), dy[n:], TOL["kkt"])
        dq, dv = system.project_phase_tangent(theta, u, w, np.ones(n))
        dX = np.empty((1, 2 * n))
        flow_tangent_rhs(np.concatenate([theta, u]), np.concatenate([dq, dv])[None],
                         system.minv, system.weights, np.empty(2 * n), dX)
        assert _close(system.tangent_acceleration(theta, u, dq, dv), dX[0, n:], TOL["kkt"])


def test_gaussian_curvature_and_surface_of_three_rotors():
    """N = 3: K by the Mechanism's intrinsic route equals the sectional curvature of the
    rotors' kernels; the surface integrals run on a RotorSystem and give the generic rotor
    Mechanism's numbers (the same nodes and the same curvature route: the same bits)."""
    system = charts.RotorSystem(3)
    theta, u, w = _state(system, 2)
    K = system.gaussian_curvature(theta)
    assert abs(K - system.sectional_curvature(theta, u, w)) <= TOL["routes"]
    assert system.gaussian_curvature(theta, 0) == pytest.approx(K, rel=TOL["routes"])
    mine = surface_integrals(system, n_grid=16)
    ref = surface_integrals(rotors(3), n_grid=16)
    assert (mine.area, mine.total_curvature) == (ref.area, ref.total_curvature)
    assert mine.euler_characteristic == -4


def test_functions_written_for_a_mechanism_run_on_a_rotor_system():
    """The chart integrator and the sectional curvatures along a trajectory (both take the
    best chart as a Mechanism's tuple) on a RotorSystem: the chart route gives the generic
    rotor Mechanism's bits (the same lift, jets and charts), the curvature its numbers (the
    same trajectory; the exact curvatures from the Riemann tensor of the rotors' kernels
    against the jets': TOL["routes"])."""
    system = charts.RotorSystem(3)
    theta, u = system.random_state(seed=2)
    mine = integrate_chart(system, theta, u, 1.0, samples=2)
    ref = integrate_chart(rotors(3), theta, u, 1.0, samples=2)
    assert np.array_equal(mine[1], ref[1]) and mine[3] == ref[3]
    system = charts.RotorSystem(4)
    theta, u = system.random_state(seed=2)
    mine = mechanism_curvature(system, theta, u, 0.5, t_transient=0.0)
    ref = mechanism_curvature(rotors(4), theta, u, 0.5, t_transient=0.0)
    assert _close(mine.K_exact, ref.K_exact, TOL["routes"])


def test_chart_forms_and_mechanism_forms_of_the_arguments():
    system = charts.RotorSystem(4, weights=[1.0, 2.0, 1.5, 1.0], level=0.3)
    theta, u, w = _state(system, 3)
    k = system.best_chart(theta)
    ind = [i for i in range(4) if i != k]
    assert system._chart_of(theta, None) == tuple(ind)
    assert np.array_equal(system.metric(theta, ind[::-1]), system.metric(theta, k))
    assert np.array_equal(system.metric(theta[ind], k, near=theta), system.metric(theta, k))
    assert np.allclose(system.lift(theta[ind], k, theta), theta, atol=1e-12)
    assert system.chart_names(k) == tuple(f"theta{i + 1}" for i in ind)
    q, v = system.to_chart(theta, u, tuple(ind))
    back = system.from_chart(q, v, tuple(ind), int(np.sign(np.sin(theta[k]))))
    assert np.allclose(back[0], theta, atol=1e-12) and np.allclose(back[1], u, atol=1e-12)
    for bad in ((0, 1), (0, 1, 1), (0, 1, 9), 4, 1.5):
        with pytest.raises(ValueError, match="chart"):
            system.metric(theta, bad)
    assert system.energy(theta, u) == float(system.energy(u))
    assert system.check_point(theta, tol=1e-10) is not None
    with pytest.raises(ValueError, match="off the manifold"):
        system.check_point(theta + 1e-9, tol=1e-10)
    with pytest.raises(ValueError, match="tol"):
        system.check_point(theta, tol=-1.0)
    with pytest.raises(ValueError, match="not tangent"):
        system.check_tangent(theta, u + 1e-9 * system.weights * np.sin(theta), tol=1e-12)
    with pytest.raises(AttributeError, match="no_such"):
        system.no_such_attribute


def test_pickle_carries_the_rotor_fields_only():
    system = charts.RotorSystem(3, masses=[1.0, 2.0, 3.0])
    size = len(pickle.dumps(system))
    theta, u = system.random_state(seed=1)
    system.acceleration(theta, u)                      # the generic twin now exists
    copy = pickle.loads(pickle.dumps(system))
    assert len(pickle.dumps(system)) == size and "_mechanism" not in copy.__dict__
    assert repr(copy) == repr(system) and copy.describe() == system.describe()
    assert np.array_equal(copy.acceleration(theta, u), system.acceleration(theta, u))


def test_construction_derives_nothing():
    """RotorSystem(64) and its structured routes make no symbolic model and derive nothing
    (the generic twin is made on first use of a method that needs it)."""
    system = charts.RotorSystem(64)
    theta, u = system.random_state(seed=0)
    w = system.project_tangent(theta, np.ones(64))
    system.check_point(theta, tol=1e-8)
    system.sectional_curvature(theta, u, w, tuple(range(63)))
    system.energy(theta, u)
    assert "_mechanism" not in system.__dict__
    model = _MODELS.get(("rotors", 64))
    assert model is None or not {"J", "F2", "F3", "dM", "d2M", "_num"} & set(model.__dict__)
