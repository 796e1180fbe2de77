"""Hostile input, generated: random shapes, dtypes, NaN/inf, off-manifold points, non-tangent
and degenerate vectors, and every keyword of every public analysis set to a hostile value.

Properties (Hypothesis, a fixed number of examples per test: see ``EXAMPLES``):

* every rejection is a ``ValueError``/``TypeError`` whose message names the argument that
  was made hostile (never a ZeroDivisionError, OverflowError, IndexError, LinAlgError or a
  numba typing error);
* every accepted call returns finite numbers; every accepted state stays on the manifold
  (constraint and tangency to the integrators' accuracy) and keeps its energy.

The counts of cases are in docs/reliability.md (``pytest tests/test_hostile.py
--hypothesis-show-statistics`` prints them)."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import charts
from charts.solvers.status import StepSizeWarning

#: Examples per property (each accepted analysis call integrates t ≤ 1 at dt = 0.01).
EXAMPLES = 60
SETTINGS = settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])
SYSTEMS = {n: charts.RotorSystem(n) for n in (3, 4, 5)}
#: Accepted states: constraint and tangency after an integration (measured ≲ 1e-12 for
#: t ≤ 1; the input tolerance is 1e-8, charts.geometry.system.TOL).
ON_MANIFOLD = 1e-9

HOSTILE_VALUES = [0, 0.0, -0.0, -1, -0.01, -5, 1e-300, 1e300, math.nan, math.inf, -math.inf, 2.7,
                  0.013, True, False, "2", "x", None, [1.0], np.float32(0.1), np.int64(2),
                  np.int64(-3), 1j]
HOSTILE_NUMBERS = st.sampled_from(HOSTILE_VALUES)


def _names_it(exc: Exception, name: str) -> bool:
    return name in str(exc)


def _call(fn, name):
    """``fn()``; a rejection must be a ValueError/TypeError naming ``name``."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StepSizeWarning)
        try:
            return True, fn()
        except (ValueError, TypeError) as exc:
            assert _names_it(exc, name), f"{name}: {type(exc).__name__}: {exc}"
            return False, exc


def _state(n, seed=1, speed=1.0):
    return SYSTEMS[n].random_state(seed=seed, speed=speed)


# --------------------------------------------------------------- arrays in place of states
ARRAYS = st.one_of(
    hnp.arrays(dtype=st.sampled_from([np.float64, np.float32, np.int64, np.complex128, np.bool_]),
               shape=hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=6),
               elements=None),
    st.lists(st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=2)),
             max_size=6),
    st.sampled_from([None, "theta", 3, object()]))


@SETTINGS
@given(n=st.sampled_from([3, 4]), theta=ARRAYS)
def test_any_array_as_a_point_is_refused_naming_theta_or_is_on_the_manifold(n, theta):
    s = SYSTEMS[n]
    for method in (s.metric, s.christoffel, s.riemann, s.check_point):
        ok, out = _call(lambda: method(theta), "theta")
        if ok:
            assert abs(np.cos(np.asarray(theta, dtype=float)).sum()) <= 1e-8
            assert np.all(np.isfinite(out))


@SETTINGS
@given(n=st.sampled_from([3, 4, 5]), seed=st.integers(0, 10**6),
       offset=st.floats(-1.0, 1.0, allow_nan=False), k=st.integers(0, 4),
       bad=st.sampled_from([None, math.nan, math.inf, -math.inf]))
def test_off_manifold_and_non_finite_points_are_refused_and_projection_lands_on_it(
        n, seed, offset, k, bad):
    s = SYSTEMS[n]
    theta, u = _state(n, seed)
    off = theta.copy()
    off[k % n] += offset if bad is None else bad
    ok, _ = _call(lambda: charts.integrate(s, off, u, 0.1), "theta")
    assert ok == (bad is None and abs(np.cos(off).sum()) <= 1e-8)
    ok, p = _call(lambda: s.project_point(off), "theta")
    if bad is not None:
        assert not ok
    elif ok:                                    # Newton converged: on the manifold
        assert abs(np.cos(p).sum()) < 1e-12


@SETTINGS
@given(n=st.sampled_from([3, 4, 5]), seed=st.integers(0, 10**6),
       push=st.floats(-2.0, 2.0, allow_nan=False),
       scale=st.sampled_from([0.0, 1e-200, 1e-3, 1.0, 1e3, 1e200]))
def test_velocities_that_are_not_tangent_are_refused_naming_u(n, seed, push, scale):
    s = SYSTEMS[n]
    theta, u = _state(n, seed)
    v = scale * u + push * np.sin(theta)
    ok, res = _call(lambda: charts.integrate(s, theta, v, 0.5), "u")
    if ok:                                      # tangent within the stated tolerance
        assert abs(v @ np.sin(theta)) <= 1e-8 * max(1.0, np.linalg.norm(v))
        final = np.r_[res.theta[-1], res.u[-1]]
        assert abs(np.cos(final[:n]).sum()) < ON_MANIFOLD
        assert abs(final[n:] @ np.sin(final[:n])) < ON_MANIFOLD * max(1.0, scale)


@SETTINGS
@given(n=st.sampled_from([3, 4, 5]), seed=st.integers(0, 10**6),
       speed=st.floats(1e-3, 1e3), method=st.sampled_from(["rk4", "dop853"]),
       formulation=st.sampled_from(["chart", "ambient"]), project=st.booleans())
def test_every_accepted_state_stays_on_the_manifold(n, seed, speed, method, formulation, project):
    s = SYSTEMS[n]
    theta, u = _state(n, seed, speed)
    try:
        r = charts.integrate(s, theta, u, 1.0 / speed, method=method, formulation=formulation,
                             project=project)
    except charts.SingularPointError:           # N = 4 only; the policy's own error
        assume(False)
    assert np.all(np.isfinite(r.theta)) and np.all(np.isfinite(r.u))
    assert np.abs(np.cos(r.theta).sum(1)).max() < ON_MANIFOLD
    assert np.abs((r.u * np.sin(r.theta)).sum(1)).max() < ON_MANIFOLD * speed
    E = s.energy(r.u)
    assert np.abs(E / E[0] - 1).max() < 1e-6        # RK4 at dt = 0.01/|u|: ≲ 1e-9 measured


# --------------------------------------------------------------- keywords set to hostile values
THETA, U = _state(4, 3)
S4 = SYSTEMS[4]
CALLS = {
    "integrate": (lambda **k: charts.integrate(S4, THETA, U, **{"t_final": 0.5, **k}),
                  ["t_final", "rtol", "atol", "chunk_steps", "project", "tau", "chart"]),
    "integrate rk4": (lambda **k: charts.integrate(S4, THETA, U, **{"t_final": 0.5,
                                                                    "method": "rk4", **k}),
                      ["dt", "t_eval"]),
    "lyapunov_spectrum": (
        lambda **k: charts.lyapunov_spectrum(S4, THETA, U, **{
            "t_final": 1.0, "t_transient": 0.0, "n_batches": 2, "record_every": 0.5, **k}),
        ["t_final", "dt", "n_exponents", "t_transient", "n_batches", "reorth_every",
         "project_every", "record_every", "seed", "inner", "space"]),
    "curvature_along_trajectory": (
        lambda **k: charts.curvature_along_trajectory(S4, THETA, U, **{
            "t_final": 1.0, "t_transient": 0.0, **k}),
        ["t_final", "dt", "sample_every", "t_transient", "project_every", "seed"]),
    "hyperbolicity_angles": (
        lambda **k: charts.hyperbolicity_angles(S4, THETA, U, **{
            "t_final": 1.0, "t_transient": 0.0, "sample_every": 0.5, **k}),
        ["t_final", "dt", "n_unstable", "t_transient", "sample_every", "checkpoint_every",
         "project_every", "seed"]),
    "waveform": (lambda **k: charts.waveform(S4, THETA, U, **{"t_final": 1.0, **k}),
                 ["t_final", "dt", "sample_every", "t_transient", "project_every"]),
    "power_spectrum": (lambda **k: charts.power_spectrum(**{
        "signal": np.sin(np.arange(4000) * 0.05), "dt_sample": 0.05, "segment_time": 20.0, **k}),
        ["dt_sample", "segment_time", "signal"]),
    "angle_statistics": (lambda **k: charts.angle_statistics(**{
        "phi": np.linspace(0.01, 1.0, 50), **k}), ["phi", "small"]),
}
#: Keywords whose ``None`` means "the default" (documented), so None is accepted.
NONE_OK = {"n_exponents", "n_unstable", "project_every", "dt", "rtol", "atol", "chart",
           "t_eval"}


def _finite(out) -> bool:
    if isinstance(out, tuple):
        return all(_finite(o) for o in out)
    if isinstance(out, dict):
        return all(_finite(v) for v in out.values() if not isinstance(v, str))
    if isinstance(out, (np.ndarray, float, int)):
        return bool(np.all(np.isfinite(out)))
    fields = [getattr(out, f) for f in ("exponents", "K_numeric", "phi_full", "phi_restricted",
                                        "u", "theta") if hasattr(out, f)]
    return all(np.all(np.isfinite(f)) for f in fields)


@pytest.mark.parametrize("call", sorted(CALLS))
@SETTINGS
@given(data=st.data())
def test_every_keyword_set_to_a_hostile_value_is_refused_naming_it_or_gives_finite_numbers(
        call, data):
    fn, names = CALLS[call]
    name = data.draw(st.sampled_from(names), label="argument")
    value = data.draw(st.one_of(HOSTILE_NUMBERS, ARRAYS) if name in ("signal", "phi", "t_eval")
                      else HOSTILE_NUMBERS, label="value")
    assume(not (value is None and name in NONE_OK))
    ok, out = _call(lambda: fn(**{name: value}), name)
    if ok:
        assert _finite(out), (name, value)


@pytest.mark.parametrize("call", sorted(CALLS))
def test_every_keyword_times_every_hostile_value(call):
    """The exhaustive product behind the sampled test above: each keyword of ``call`` set to
    each of ``HOSTILE_VALUES`` (one at a time)."""
    fn, names = CALLS[call]
    for name in names:
        for value in HOSTILE_VALUES:
            if value is None and name in NONE_OK:
                continue
            ok, out = _call(lambda: fn(**{name: value}), name)
            if ok:
                assert _finite(out), (name, value)
