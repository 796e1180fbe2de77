"""integrate(): input validation, result layout, output times, chunking, progress and early stop,
the switching rule as a pure function, and the compiled steppers on an ODE with a known solution."""
import math

import numpy as np
import pytest
from numba import njit

from charts import RotorSystem
from charts.solvers.chart_formulation import DEFAULT_TAU, chart_condition_bound, leave_chart, should_leave
from charts.solvers.integrate import IntegrationResult, integrate
from charts.solvers.rk import RHS_SIG, dense_eval, dop853_dense, dop853_step, rk4_step

from scenarios import SINGULAR_N4, TOL, masses

SYS3 = RotorSystem(3)
TH3, U3 = SYS3.random_state(7)


# -- bad input ----------------------------------------------------------------------------
@pytest.mark.parametrize("kwargs, match", [
    (dict(formulation="lagrange"), "unknown formulation"),
    (dict(method="euler"), "unknown method"),
    (dict(method="rk4", dt=0.0), "dt must be positive"),
    (dict(method="rk4", dt=-0.01), "dt must be positive"),
    (dict(method="rk4", dt=float("nan")), "dt must be finite"),
    (dict(method="rk4", rtol=1e-8), "rtol/atol apply to method='dop853'"),
    (dict(method="dop853", dt=0.01), "dt applies to method='rk4'"),
    (dict(rtol=0.0), "rtol must be positive"),
    (dict(rtol=1e-17), "below"),
    (dict(atol=-1.0), "atol must be positive"),
    (dict(t_eval=[0.0, 2.0, 1.0]), "strictly increasing"),
    (dict(t_eval=[0.0, 20.0]), r"t_eval must lie in t_span = \(0, 1\)"),
    (dict(t_eval=[]), "non-empty"),
    (dict(tau=1.0), "tau must be a number in"),
    (dict(chart=3), "chart must be None or an integer"),
    (dict(formulation="ambient", chart=0), "apply to formulation='chart'"),
    (dict(transport=np.ones((2, 4))), "transport must have shape"),
    (dict(transport=np.array([1.0, 0.0, 0.0])), "not tangent"),
    (dict(chunk_steps=0), "chunk_steps"),
])
def test_bad_options_raise_valueerror(kwargs, match):
    with pytest.raises(ValueError, match=match):
        integrate(SYS3, TH3, U3, 1.0, **kwargs)


@pytest.mark.parametrize("t_final", [-1.0, float("inf"), float("nan"), "1"])
def test_bad_t_final(t_final):
    with pytest.raises(ValueError, match="t_final"):
        integrate(SYS3, TH3, U3, t_final)


def test_bad_states():
    bad = TH3.copy()
    bad[0] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        integrate(SYS3, bad, U3, 1.0)
    with pytest.raises(ValueError, match="non-finite"):
        integrate(SYS3, TH3, U3 * np.inf, 1.0)
    with pytest.raises(ValueError, match="off the manifold"):
        integrate(SYS3, TH3 + 0.01, U3, 1.0)
    with pytest.raises(ValueError, match="not tangent"):
        integrate(SYS3, TH3, U3 + np.sin(TH3), 1.0)
    with pytest.raises(ValueError, match="nonzero velocity"):
        integrate(SYS3, TH3, 0 * U3, 1.0)
    with pytest.raises(ValueError, match="shape"):
        integrate(SYS3, TH3[:2], U3[:2], 1.0)
    s4 = RotorSystem(4)
    with pytest.raises(ValueError, match="singular point"):
        integrate(s4, np.array(SINGULAR_N4), np.zeros(4) + [1, -1, 0, 0], 1.0)


# -- result layout and output times ---------------------------------------------------------
@pytest.mark.parametrize("formulation", ["chart", "ambient"])
@pytest.mark.parametrize("method", ["rk4", "dop853"])
def test_result_layout_and_exact_output_times(formulation, method):
    s = RotorSystem(4, masses("mixed", 4))
    th, u = s.random_state(3)
    P = np.array([s.project_tangent(th, np.arange(4.0)), s.project_tangent(th, np.ones(4))])
    te = np.array([0.0, 0.123, 1.0, 2.5, 3.0])
    r = integrate(s, th, u, 3.0, formulation=formulation, method=method, t_eval=te, transport=P)
    assert isinstance(r, IntegrationResult) and r.status == "finished"
    np.testing.assert_array_equal(r.t, te)  # exactly, not approximately
    assert r.theta.shape == r.u.shape == (5, 4) and r.transported.shape == (5, 2, 4)
    np.testing.assert_array_equal(r.theta[0], th)
    np.testing.assert_array_equal(r.u[0], u)
    np.testing.assert_array_equal(r.transported[0], P)  # the t = 0 sample is the input
    assert set(r.drift) == {"constraint", "tangency", "energy", "transport"}
    assert r.n_steps > 0 and r.n_rhs >= 4 * r.n_steps
    if formulation == "ambient":
        assert r.switches == []
    for t, a, b in r.switches:
        assert 0 <= t <= 3.0 and a != b


def test_every_step_output_and_t_final_zero():
    r = integrate(SYS3, TH3, U3, 2.0, method="rk4", dt=0.01)
    assert r.t[0] == 0.0 and r.t[-1] == 2.0 and r.t.size == r.n_steps + 1
    assert np.all(np.diff(r.t) > 0)
    r0 = integrate(SYS3, TH3, U3, 0.0)
    assert r0.t.tolist() == [0.0] and r0.n_steps == 0


def test_every_step_output_longer_than_one_buffer():
    # > 4096 steps: the every-step buffer is drained between chunks without losing samples
    r = integrate(SYS3, TH3, U3, 50.0, method="rk4", dt=0.01)
    assert r.t.size == r.n_steps + 1 > 4096
    np.testing.assert_allclose(np.diff(r.t), 0.01, rtol=1e-9)


@pytest.mark.parametrize("formulation", ["chart", "ambient"])
def test_chunking_does_not_change_the_solution(formulation):
    te = np.linspace(0, 10, 11)
    a = integrate(SYS3, TH3, U3, 10.0, formulation=formulation, t_eval=te)
    b = integrate(SYS3, TH3, U3, 10.0, formulation=formulation, t_eval=te, chunk_steps=3)
    np.testing.assert_array_equal(a.theta, b.theta)  # bitwise: same steps, same arithmetic
    assert a.switches == b.switches and a.n_steps == b.n_steps


def test_progress_and_early_stop_keep_samples():
    calls = []

    def progress(t, t_final):
        calls.append(t)
        return len(calls) < 3

    te = np.linspace(0, 100, 1001)
    r = integrate(SYS3, TH3, U3, 100.0, method="rk4", dt=0.01, t_eval=te, chunk_steps=500,
                  progress=progress)
    assert r.status == "stopped" and len(calls) == 3
    assert r.t[-1] <= calls[-1] + 1e-12 and r.t.size == np.searchsorted(te, calls[-1], "right")
    full = integrate(SYS3, TH3, U3, 100.0, method="rk4", dt=0.01, t_eval=te)
    np.testing.assert_array_equal(r.theta, full.theta[:r.t.size])
    assert all(np.diff(calls) > 0)


# -- the switching rule -----------------------------------------------------------------------
def test_leave_chart_rule():
    assert leave_chart(np.array([0.9, 0.5, 0.1]), 0, 0.5) == -1  # best already
    assert leave_chart(np.array([0.9, 0.5, 0.1]), 1, 0.5) == -1  # 0.5 >= 0.45: stay
    assert leave_chart(np.array([0.9, 0.4, 0.1]), 1, 0.5) == 0
    assert leave_chart(np.array([0.9, 0.4, 0.9]), 1, 0.5) == 0  # ties: lowest index
    assert should_leave(0.1, 0.9, 0.5) and not should_leave(0.5, 0.9, 0.5)
    # hysteresis: the chart chosen has ratio 1 >= tau, so the rule never leaves it at once
    rng = np.random.default_rng(0)
    for _ in range(200):
        s = rng.uniform(0, 1, 5)
        k = rng.integers(5)
        j = leave_chart(s, k, 0.5)
        if j >= 0:
            assert leave_chart(s, j, 0.5) == -1
    assert chart_condition_bound(3, 0.5) == 9.0


def test_switching_is_deterministic_and_recorded_at_exact_step_times():
    s = RotorSystem(5)
    th, u = s.random_state(6)
    a = integrate(s, th, u, 20.0, method="rk4", dt=0.01)
    b = integrate(s, th, u, 20.0, method="rk4", dt=0.01)
    assert a.switches == b.switches and len(a.switches) >= 5
    for t, frm, to in a.switches:
        i = np.searchsorted(a.t, t)
        assert a.t[i] == t  # a switch happens at a step boundary, which is a sample here
        sines = np.abs(np.sin(a.theta[i]))
        assert to == np.argmax(sines) and sines[frm] < DEFAULT_TAU * sines.max()


def test_forced_initial_chart_near_its_boundary_switches_at_t0():
    s = RotorSystem(3)
    th = np.array([1e-8, 0.0, 0.0])
    th[1] = 2.0
    th[2] = -np.arccos(-np.cos(th[0]) - np.cos(th[1]))
    th = s.project_point(th)
    u = s.project_tangent(th, np.array([1.0, 0.3, -0.2]))
    r = integrate(s, th, u, 1.0, chart=0, t_eval=[0.0, 1.0])
    assert r.switches[0][:2] == (0.0, 0)


# -- the steppers on y' = J y (harmonic oscillator), exact solution known -----------------------
@njit(RHS_SIG)
def _osc(y, par, dy):
    dy[0] = y[1]
    dy[1] = -par[0] * y[0]
    return 1.0


def test_rk4_and_dop853_on_the_harmonic_oscillator():
    w2 = 4.0
    par = np.array([w2])
    exact = lambda t: np.array([math.cos(2 * t), -2 * math.sin(2 * t)])
    # RK4: global error ∝ h⁴
    errs = []
    hs = [0.1, 0.05, 0.025]
    for h in hs:
        y = np.array([1.0, 0.0])
        K = np.zeros((4, 2))
        tmp = np.zeros(2)
        new = np.zeros(2)
        for _ in range(int(round(2.0 / h))):
            rk4_step(_osc, y, h, par, K, tmp, new)
            y[:] = new
        errs.append(np.abs(y - exact(2.0)).max())
    order = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert 3.9 < order < 4.1  # fourth order, to the precision of a 3-point fit
    # DOP853: one step of h = 0.1 is accurate to ~h⁹, and the dense output reproduces the
    # solution inside the step to ~h⁸
    y = np.array([1.0, 0.0])
    K = np.zeros((16, 2))
    _osc(y, par, K[0])
    new = np.zeros(2)
    tmp = np.zeros(2)
    err, health = dop853_step(_osc, y, 0.1, par, K, tmp, new, 1e-10, 1e-10)
    assert np.abs(new - exact(0.1)).max() < TOL["dop853_one_step"] and health == 1.0
    F = np.zeros((7, 2))
    dop853_dense(_osc, y, new, 0.1, par, K, tmp, F)
    for x in (0.0, 0.3, 0.77, 1.0):
        out = np.zeros(2)
        dense_eval(F, y, x, out)
        assert np.abs(out - exact(0.1 * x)).max() < 1e-11


def test_dop853_tableau_is_scipys():
    """The coefficients are SciPy's (``scipy/integrate/_ivp/dop853_coefficients.py``), entry
    for entry: a transcription check of the copied tables."""
    from scipy.integrate._ivp import dop853_coefficients as ref

    import charts.solvers.dop853_coefficients as rk
    for name in ("A", "B", "C", "D", "E3", "E5"):
        np.testing.assert_array_equal(getattr(rk, name), getattr(ref, name), err_msg=name)
    assert (rk.N_STAGES, rk.N_STAGES_EXTENDED, rk.INTERPOLATOR_POWER) == \
        (ref.N_STAGES, ref.N_STAGES_EXTENDED, ref.INTERPOLATOR_POWER)


@pytest.mark.parametrize("rtol, h", [(1e-6, 0.6), (1e-10, 0.15), (1e-12, 0.1)])
def test_dop853_step_and_error_norm_equal_scipys(rtol, h):
    """One step of our DOP853 against SciPy's ``DOP853`` solver taking the same step from the
    same state: the same new state (to a few ulp) and the same scaled error norm, whose value
    decides acceptance (the error norm is compared, not merely required to be < 1)."""
    from scipy.integrate import DOP853

    w2 = 4.0
    par = np.array([w2])
    y0 = np.array([1.0, 0.3])
    ref = DOP853(lambda t, y: np.array([y[1], -w2 * y[0]]), 0.0, y0, t_bound=h, rtol=rtol,
                 atol=rtol, first_step=h)
    ref.step()
    assert ref.t == h, "SciPy rejected the step: choose a smaller h for this rtol"
    scale = rtol + np.maximum(np.abs(y0), np.abs(ref.y)) * rtol
    err_ref = ref._estimate_error_norm(ref.K, h, scale)
    K = np.zeros((16, 2))
    _osc(y0, par, K[0])
    new, tmp = np.zeros(2), np.zeros(2)
    err, _ = dop853_step(_osc, y0, h, par, K, tmp, new, rtol, rtol)
    np.testing.assert_allclose(new, ref.y, rtol=0, atol=TOL["dop853_vs_scipy_state"])
    assert 0.1 < err < 1.0          # a step near the acceptance limit, where the norm decides
    # the norm is h·|Σ_j E_j K_j| / scale, a sum that cancels down to the local error: its
    # rounding (in either implementation) is ~13 terms × |E| ≲ 1 ulp of |K|, in units of the scale
    rounding = 16 * np.finfo(float).eps * np.abs(K[:13]).max() * h / scale.min()
    assert abs(err - err_ref) <= TOL["dop853_vs_scipy_error"] * err_ref + rounding, \
        (err, err_ref, rounding)


def test_a_float32_step_is_the_decimal_it_prints():
    """``dt=np.float32(0.01)`` is 0.01 (the typed layer's reading), so t = 1 is 100 whole
    steps: 101 samples, as with the float 0.01; a string or a bool is refused naming dt."""
    import numpy as np
    import pytest

    import charts

    s = charts.RotorSystem(3)
    th, u = s.random_state(seed=1)
    a = charts.integrate(s, th, u, 1.0, method="rk4", dt=np.float32(0.01))
    b = charts.integrate(s, th, u, 1.0, method="rk4", dt=0.01)
    assert len(a.t) == len(b.t) == 101 and np.array_equal(a.theta, b.theta)
    for bad in ("0.01", True):
        with pytest.raises(ValueError, match="dt must be a real number"):
            charts.integrate(s, th, u, 1.0, method="rk4", dt=bad)
