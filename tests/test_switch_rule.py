"""The chart-switching rule has one home (``switch_rule`` over ``atlas.best_sine``): the pure
function, tested alone on random draws with ties, is the one the chart integration runs
(every step of a chart RK4 run, replayed through the formulation's own hooks, switches
exactly where the pure function says), and ``RotorSystem.best_chart`` is its argmax."""
import math

import numpy as np
import pytest

from charts import RotorSystem, integrate
from charts.geometry.atlas import best_sine, eliminated_angle_sc
from charts.solvers.chart_formulation import DEFAULT_TAU, ChartFlow, leave_chart, switch_rule
from charts.solvers.rk import rk4_step
from charts.solvers.status import CAP_FRACTION


def _reference(s, k, tau):
    """The rule written independently: the first index of the largest |s|; leave chart k
    when |s_k| < τ·max."""
    a = np.abs(s)
    smax = a.max()
    j = int(np.flatnonzero(a == smax)[0])
    return (j if a[k] < tau * smax else -1), smax


def _draws(rng, count):
    """Random |a sin θ| vectors, half of them from a coarse grid (ties, also with s_k), with
    random signs, chart and τ."""
    for i in range(count):
        n = int(rng.integers(3, 9))
        s = rng.uniform(0, 1, n) if i % 2 else rng.integers(0, 4, n) / 4.0
        s *= rng.choice([-1.0, 1.0], n)
        yield s, int(rng.integers(n)), float(rng.choice([DEFAULT_TAU, 0.5, rng.uniform(0.05, 0.99)]))


def test_pure_rule_on_random_draws_with_ties():
    rng = np.random.default_rng(20)
    ties = 0
    for s, k, tau in _draws(rng, 3000):
        j_ref, smax = _reference(s, k, tau)
        local = np.delete(s, k)
        j, m = switch_rule(local, s[k], k, tau)
        assert (j, m) == (j_ref, smax)
        assert best_sine(local, s[k], k) == (int(np.argmax(np.abs(s))), smax)
        assert leave_chart(np.abs(s), k, tau) == j_ref
        if j >= 0:  # hysteresis: the chart chosen is never left at once
            assert leave_chart(np.abs(s), j, tau) == -1
        ties += np.count_nonzero(np.abs(s) == smax) > 1
    assert ties > 500


def test_best_chart_is_the_rules_argmax():
    rng = np.random.default_rng(21)
    for n, w in ((3, None), (5, None), (4, [1.0, 2.0, 0.5, 1.0])):
        s = RotorSystem(n, weights=w)
        # angles from a few values: many exact ties of |a sin θ|
        th = rng.choice([0.3, np.pi - 0.3, -0.3, 1.1, np.pi / 2, 0.0], size=(7, 40, n))
        a = np.abs(s.weights * np.sin(th))
        ref = np.argmax(a, axis=-1)  # numpy's argmax: the first of the maxima
        got = s.best_chart(th)
        assert got.shape == (7, 40) and np.array_equal(got, ref)
        for p in th[0]:
            k = s.best_chart(p)
            assert type(k) is int and k == int(np.argmax(np.abs(s.weights * np.sin(p))))
            assert leave_chart(np.abs(s.weights * np.sin(p)), k, DEFAULT_TAU) == -1


def _replay(system, theta, u, t_final, dt, project):
    """A chart RK4 run replayed step by step through ChartFlow's own hooks (as
    ``charts.solvers.loop.drive`` calls them).  Before each ``post`` the rule's inputs are
    rebuilt from the step's end state as ``post`` sees them (σ = a sin q and κ = a cos q by
    libm, ``eliminated_angle_sc``) and the pure rule's verdict is compared with what
    ``post`` logs.  Returns (switches, number of steps whose verdict was 'leave')."""
    n, d = system.n, system.n - 1
    form = ChartFlow(system, project=project, cap_fraction=CAP_FRACTION["rk4"])
    y, par, ipar = form.initial(theta, u, np.zeros((0, n)))
    rhs, _, cap, post, _, _ = form.hooks("rk4", 0)
    K, ytmp, ynew = np.zeros((16, y.size)), np.zeros(y.size), np.zeros(y.size)
    log = np.zeros((8, 3))
    t, switches = 0.0, list(form.initial_switches)
    while t < t_final:
        h = min(dt, cap(y, par, ipar))
        if h * (1.0 + 1e-9) >= t_final - t:  # as the loop lands on t_final
            h, t_new = t_final - t, t_final
        else:
            t_new = t + h
        assert rk4_step(rhs, y, h, par, K, ytmp, ynew) > 0.0
        y[:] = ynew
        t = t_new
        k, lw = int(ipar[2]), par[1 + n:1 + 2 * n]
        ws = np.array([lw[a] * math.sin(y[a]) for a in range(d)])
        wc = np.array([lw[a] * math.cos(y[a]) for a in range(d)])
        _, sk, _ = eliminated_angle_sc(wc, d, lw, par[1 + 2 * n], float(ipar[3]))
        s = np.insert(ws, k, lw[d] * sk)  # ambient order
        expect, _ = _reference(s, k, form.tau)
        assert switch_rule(ws, lw[d] * sk, k, form.tau)[0] == expect
        before = int(ipar[4])
        assert post(y, par, ipar, t, log) >= 0
        logged = [tuple(r) for r in log[before:ipar[4]]]
        assert logged == ([(t, k, expect)] if expect >= 0 else [])
        switches.extend((float(a), int(b), int(c)) for a, b, c in logged)
        ipar[4] = 0
    return switches


@pytest.mark.parametrize("n, masses, weights, level", [
    (3, None, None, 0.0), (4, [1.0, 1.7, 0.6, 1.2], None, 0.0),
    (5, [1.0, 2.0, 0.5, 1.5, 1.1], None, 0.0), (4, None, [1.0, 1.5, 0.8, 1.2], 0.3)])
def test_the_rule_that_runs_is_the_tested_one(n, masses, weights, level):
    s = RotorSystem(n, masses=masses, weights=weights, level=level)
    total = 0
    for seed in range(4):
        th, u = s.random_state(seed=seed, speed=1.0)
        project = bool(seed % 2)
        got = _replay(s, th, u, 8.0, 0.02, project)
        # the replay is the integration: the same switches, bit for bit
        ref = integrate(s, th, u, 8.0, formulation="chart", method="rk4", dt=0.02,
                        project=project, t_eval=[0.0, 8.0])
        assert got == ref.switches
        total += len(got)
    assert total >= 8
