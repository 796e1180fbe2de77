"""integrate's SciPy-style interface: t_span (backwards too), dense output across chart
switches, events (terminal, direction) against an independent route: bisection on a fine RK4
trajectory."""
import numpy as np
import pytest

from charts import RotorSystem
from charts.solvers.integrate import integrate

SYS3 = RotorSystem(3)
TH3, U3 = SYS3.random_state(7)
T = 12.0   # short enough that chaos (λ₁ = 0.5) amplifies errors by e⁶ ≈ 400 only
#: g(θ, u) of the events compared with bisection: the sections sin θᵢ = 0 and the turning
#: points uᵢ = 0 of each rotor (≥ 8 zeros in [0, T], across chart switches).
SECTIONS = [lambda th, u, i=i: np.sin(th[i]) for i in range(3)] + \
           [lambda th, u, i=i: u[i] for i in range(3)]


def section(t, y):
    """The Poincaré section sin θ₁ = 0 (θ₁ ≡ 0 mod π), as an event."""
    return np.sin(y[0])


def _event(fn, terminal=False, direction=0):
    def ev(t, y):
        return fn(t, y)
    ev.terminal, ev.direction = terminal, direction
    return ev


def _bisect_rk4(g, dt=1e-3):
    """Zeros of g(θ, u) on the RK4 trajectory at step dt: brackets on the grid, then bisection
    where the state at a time τ inside a step is one RK4 step of size τ from its start (local
    error ≈ τ⁵ ≈ 1e-15)."""
    ref = integrate(SYS3, TH3, U3, T, formulation="ambient", method="rk4", dt=dt)
    vals = np.array([g(th, u) for th, u in zip(ref.theta, ref.u)])
    roots = []
    for i in np.flatnonzero(np.sign(vals[:-1]) * np.sign(vals[1:]) < 0):
        a, b = 0.0, ref.t[i + 1] - ref.t[i]
        ga = vals[i]
        while b - a > 1e-14:
            m = 0.5 * (a + b)
            r = integrate(SYS3, ref.theta[i], ref.u[i], m, formulation="ambient", method="rk4",
                          dt=m, t_eval=[m])
            gm = g(r.theta[-1], r.u[-1])
            if np.sign(gm) == np.sign(ga):
                a, ga = m, gm
            else:
                b = m
        roots.append(ref.t[i] + 0.5 * (a + b))
    return np.array(roots)


def _as_events(gs):
    return [lambda t, y, g=g: g(y[:3], y[3:6]) for g in gs]


@pytest.fixture(scope="module")
def rk4_roots():
    return [_bisect_rk4(g) for g in SECTIONS]


def _max_error(t_events, roots):
    assert [t.shape for t in t_events] == [r.shape for r in roots]
    return max(np.max(np.abs(t - r), initial=0.0) for t, r in zip(t_events, roots))


@pytest.mark.parametrize("formulation", ["chart", "ambient"])
def test_events_match_bisection_on_fine_rk4(rk4_roots, formulation):
    """The zeros found by events= on DOP853's interpolant (rtol 1e-13) and by bisection on a
    fine RK4 trajectory (dt = 1e-3) agree to 1e-9 in time (measured: 9 zeros, max 2.6e-12)."""
    res = integrate(SYS3, TH3, U3, T, formulation=formulation, rtol=1e-13,
                    events=_as_events(SECTIONS))
    assert sum(r.size for r in rk4_roots) >= 8
    assert _max_error(res.t_events, rk4_roots) < 1e-9
    # y_events lie on their sections
    for g, Y in zip(SECTIONS, res.y_events):
        assert all(abs(g(y[:3], y[3:])) < 1e-12 for y in Y)
    if formulation == "chart":
        assert len(res.switches) >= 2   # the events lie across chart switches


def test_events_of_rk4_dense_output_converge_at_fourth_order(rk4_roots):
    """RK4 + Hermite events: the error in time falls ~16× per halving of dt (order 4; measured
    1.1e-8 → 5.4e-10, ratio 20)."""
    errs = []
    for dt in (0.02, 0.01):
        res = integrate(SYS3, TH3, U3, T, formulation="ambient", method="rk4", dt=dt,
                        events=_as_events(SECTIONS))
        errs.append(_max_error(res.t_events, rk4_roots))
    assert 10 < errs[0] / errs[1] < 32, errs


@pytest.mark.parametrize("formulation", ["chart", "ambient"])
@pytest.mark.parametrize("method, kw, tol", [("dop853", dict(rtol=1e-10), 2e-8),
                                             ("rk4", dict(dt=0.01), 1e-7)])
def test_dense_output_agrees_with_reference_across_switches(formulation, method, kw, tol):
    """sol(t) between the steps (and at them) agrees with t_eval output of an independent
    ambient DOP853 run at rtol 1e-13 to the method's accuracy; tol from measured errors
    (measured max over 1001 times: dop853 4.8e-9, rk4 at dt = 0.01 4.3e-9 — the method's own
    error, amplified ~e⁶ by the chaos, not the interpolant's); sol(t)
    equals the run's own samples at its steps and (DOP853, whose t_eval does not change the
    steps) its own t_eval output."""
    res = integrate(SYS3, TH3, U3, T, formulation=formulation, method=method, dense_output=True, **kw)
    if formulation == "chart":
        assert len(res.switches) >= 2
    tt = np.sort(np.concatenate([np.linspace(0, T, 1001),
                                 [w[0] + d for w in res.switches for d in (-1e-3, 1e-3)
                                  if 0 < w[0] + d < T]]))
    ref = integrate(SYS3, TH3, U3, T, formulation="ambient", rtol=1e-13, t_eval=tt)
    Y = res.sol(tt)
    assert Y.shape == (6, tt.size)
    err = max(np.max(np.abs(Y[:3].T - ref.theta)), np.max(np.abs(Y[3:].T - ref.u)))
    assert err < tol, err
    assert np.max(np.abs(res.sol.theta(res.t) - res.theta)) < 1e-12
    if method == "dop853":
        same = integrate(SYS3, TH3, U3, T, formulation=formulation, method=method, t_eval=tt, **kw)
        assert np.max(np.abs(res.sol.theta(tt) - same.theta)) < 1e-12
    assert np.allclose(res.sol(0.0), np.concatenate([TH3, U3]), rtol=0, atol=1e-15)


def test_dense_output_continuous_at_chart_switches():
    res = integrate(SYS3, TH3, U3, T, dense_output=True)
    for t_sw, _, _ in res.switches:
        if 0 < t_sw < T:
            jump = np.abs(res.sol(t_sw - 1e-12) - res.sol(t_sw + 1e-12)).max()
            assert jump < 1e-10, jump
    with pytest.raises(ValueError, match="outside the integrated interval"):
        res.sol(T + 1.0)


def test_terminal_events_stop_the_run():
    first = integrate(SYS3, TH3, U3, T, events=section).t_events[0]
    res = integrate(SYS3, TH3, U3, T, events=_event(section, terminal=True), dense_output=True)
    assert res.status == "event"
    assert res.t_events[0].tolist() == [first[0]]
    assert res.t[-1] == first[0] and np.all(np.diff(res.t) > 0)
    assert np.array_equal(res.y_events[0][0][:3], res.theta[-1])
    assert res.sol.t_max == first[0]
    two = integrate(SYS3, TH3, U3, T, events=[_event(section, terminal=2),
                                              _event(lambda t, y: t - 100.0)])
    assert np.array_equal(two.t_events[0], first[:2]) and two.t_events[1].size == 0
    # with t_eval: the samples up to the event, as in SciPy
    te = np.linspace(0, T, 81)
    ev = integrate(SYS3, TH3, U3, T, t_eval=te, events=_event(section, terminal=True))
    assert np.array_equal(ev.t, te[te <= first[0]])


def test_direction_selects_crossings():
    both = integrate(SYS3, TH3, U3, T, events=_as_events(SECTIONS), dense_output=True)

    def with_direction(d):
        evs = _as_events(SECTIONS)
        for ev in evs:
            ev.direction = d
        return integrate(SYS3, TH3, U3, T, events=evs).t_events

    up, down = with_direction(1), with_direction(-1)
    assert sum(t.size for t in up) >= 2 and sum(t.size for t in down) >= 2
    for g, tu, td, tb in zip(SECTIONS, up, down, both.t_events):
        assert np.array_equal(np.sort(np.concatenate([tu, td])), tb)
        slope = lambda t: g(*np.split(both.sol(t + 1e-6), 2)) - g(*np.split(both.sol(t - 1e-6), 2))
        assert all(slope(t) > 0 for t in tu) and all(slope(t) < 0 for t in td)


def test_backwards_integration_retraces_the_geodesic():
    """t_span = (T, 0) from the end state returns to the start (time reversal) and finds the
    same section crossings, with direction taken along the direction of integration."""
    fwd = integrate(SYS3, TH3, U3, T, rtol=1e-13, events=section)
    end = integrate(SYS3, TH3, U3, T, rtol=1e-13, t_eval=[T])
    back = integrate(SYS3, end.theta[-1], end.u[-1], t_span=(T, 0.0), rtol=1e-13,
                     events=section, dense_output=True, t_eval=[T, T / 2, 0.0])
    assert back.t.tolist() == [T, T / 2, 0.0]
    assert np.max(np.abs(back.theta[-1] - TH3)) < 1e-9
    assert np.max(np.abs(back.u[-1] - U3)) < 1e-9
    assert np.max(np.abs(np.sort(back.t_events[0]) - fwd.t_events[0])) < 1e-9
    assert np.all(np.diff(back.t_events[0]) < 0)
    assert np.allclose(back.sol(T / 2), np.concatenate([back.theta[1], back.u[1]]), atol=1e-14)
    term = _event(section, terminal=True)
    stop = integrate(SYS3, end.theta[-1], end.u[-1], t_span=(T, 0.0), rtol=1e-13, events=term)
    assert stop.status == "event" and stop.t[-1] == back.t_events[0][0]
    assert np.array_equal(stop.u[-1], stop.y_events[0][0][3:])        # u in user time
    assert np.max(np.abs(stop.u[-1] - back.sol.u(stop.t[-1]))) < 1e-12
    shifted = integrate(SYS3, TH3, U3, t_span=(5.0, 5.0 + T), rtol=1e-13, events=section)
    assert np.max(np.abs(shifted.t_events[0] - 5.0 - fwd.t_events[0])) < 1e-9


@pytest.mark.parametrize("kwargs, match", [
    (dict(t_span=(0.0, 1.0)), "either t_final"),
    (dict(events=3), "callable"),
    (dict(events=_event(section, terminal=-1)), "terminal"),
    (dict(events=_event(section, direction="up")), "direction"),
])
def test_bad_event_and_span_arguments(kwargs, match):
    with pytest.raises(ValueError, match=match):
        integrate(SYS3, TH3, U3, 1.0, **kwargs)


def test_bad_t_span_and_backward_t_eval():
    with pytest.raises(ValueError, match="t_span"):
        integrate(SYS3, TH3, U3, t_span=(0.0, float("nan")))
    with pytest.raises(ValueError, match="strictly decreasing"):
        integrate(SYS3, TH3, U3, t_span=(1.0, 0.0), t_eval=[0.0, 1.0])
