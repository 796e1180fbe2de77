"""The chart right-hand side's shared σ = a sin q, κ = a cos q (charts.flows.chart): what
`point_sincos` returns is libm's at a point away from the step's start, bit for bit, whether it
evaluates them or reuses the last point's; at the step's start (`start_sincos`) libm's; inside
the step the start's shifted, within rounding of libm's and independent of earlier steps; and
a right-hand side that reuses them equals one evaluated from a fresh work area."""
import numpy as np
from numba import njit

from charts.flows.ambient import SHIFT_MAX
from charts.flows.chart import chart_rates, local_parameters, point_sincos, start_sincos, work_area


@njit
def _point(y, par, d):
    ws, wc = point_sincos(y, par, d)
    return ws.copy(), wc.copy()


def _random_charts(rng):
    """(d, par, local weights) of a chart of a random weighted member, N = 3, 5, 8."""
    for n in (3, 5, 8):
        d = n - 1
        par = local_parameters(rng.uniform(0.5, 2.0, n), rng.uniform(0.8, 1.3, n), 0.1, n - 1)
        yield d, par, par[2 + d:2 + 2 * d]


def test_point_sincos_is_libm_at_every_point():
    rng = np.random.default_rng(7)
    for d, par, w in _random_charts(rng):
        for _ in range(20):
            y = rng.uniform(-3.0, 3.0, 2 * d)
            for _again in range(2):  # evaluated, then reused
                ws, wc = _point(y, par, d)
                assert np.array_equal(ws, w * np.sin(y[:d]))
                assert np.array_equal(wc, w * np.cos(y[:d]))


@njit
def _start(y, par, d):
    ws, wc = start_sincos(y, par, d)
    return ws.copy(), wc.copy()


def test_inside_a_step_the_start_is_shifted_to_rounding_and_only_the_start_matters():
    """|δ| ≤ SHIFT_MAX: within 4 ulp of libm's (the shift's polynomials are exact to rounding;
    measured ≤ 2 ulp); beyond it libm's bit for bit, coordinate by coordinate.  The values at a
    point inside the step do not depend on which steps came before."""
    rng = np.random.default_rng(11)
    for d, par, w in _random_charts(rng):
        for _ in range(50):
            y0 = rng.uniform(-3.0, 3.0, 2 * d)
            ws, wc = _start(y0, par, d)
            assert np.array_equal(ws, w * np.sin(y0[:d])) and np.array_equal(wc, w * np.cos(y0[:d]))
            dl = rng.uniform(-SHIFT_MAX, SHIFT_MAX, d)
            dl[0] = rng.choice([-1, 1]) * rng.uniform(1.01, 3.0) * SHIFT_MAX  # beyond the shift
            y1 = y0.copy()
            y1[:d] += dl
            ws, wc = _point(y1, par, d)
            ref_s, ref_c = w * np.sin(y1[:d]), w * np.cos(y1[:d])
            assert ws[0] == ref_s[0] and wc[0] == ref_c[0]
            assert np.all(np.abs(ws - ref_s) <= 4 * np.spacing(w)) and \
                np.all(np.abs(wc - ref_c) <= 4 * np.spacing(w))
            other = par.copy()                    # another history: a different earlier step
            _start(rng.uniform(-3.0, 3.0, 2 * d), other, d)
            _point(rng.uniform(-3.0, 3.0, 2 * d), other, d)
            _start(y0, other, d)
            ws2, wc2 = _point(y1, other, d)
            assert np.array_equal(ws, ws2) and np.array_equal(wc, wc2)


def test_right_hand_side_reusing_the_work_area_equals_a_fresh_one():
    rng = np.random.default_rng(3)
    for n, paper in ((5, True), (5, False), (8, False)):
        d = n - 1
        rhs = njit(chart_rates(n, paper))
        par = local_parameters(np.ones(n), np.ones(n), 0.0, n - 1) if paper else \
            local_parameters(rng.uniform(0.5, 2.0, n), rng.uniform(0.8, 1.3, n), 0.1, n - 1)
        for _ in range(20):
            y = np.concatenate([rng.uniform(1.0, 2.0, d) * rng.choice([-1, 1], d),
                                rng.normal(size=2 * d)])
            a = np.empty(y.size)
            rhs(y, par, a)
            ha = rhs(y, par, a)                     # the second time from the work area
            fresh = par.copy()
            fresh[-work_area(n).size:] = np.nan
            b = np.empty(y.size)
            hb = rhs(y, fresh, b)
            assert ha == hb and np.array_equal(a, b)
