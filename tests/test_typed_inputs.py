"""The one typed layer of the public surface (``charts.geometry.checks``), by property: any
value of any type given as a number, an array of numbers, masses, weights or a level is either
accepted as real finite floats or refused with a ValueError that names the argument — never
another exception from NumPy, never a silent conversion of a string, a bool or a complex."""
import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import charts
from charts.geometry.checks import finite_array, number

SCALARS = st.one_of(
    st.integers(min_value=-10 ** 500, max_value=10 ** 500), st.floats(allow_nan=True),
    st.booleans(), st.text(max_size=5), st.complex_numbers(), st.none(), st.binary(max_size=3),
    st.sampled_from([np.float32(1.5), np.int64(3), np.bool_(True), np.nan, np.inf, "1"]))
VALUES = st.one_of(SCALARS, st.lists(SCALARS, max_size=5),
                   st.lists(st.lists(SCALARS, max_size=3), max_size=3))


def _real(x):
    """A real number with a finite float value (an integer beyond a float's range is not)."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        return False
    try:
        return math.isfinite(float(x))
    except OverflowError:
        return False


@settings(max_examples=300, deadline=None, derandomize=True)
@given(VALUES)
def test_number_accepts_real_finite_numbers_only(x):
    try:
        v = number("level", x)
    except ValueError as exc:
        assert "level" in str(exc) and len(str(exc)) < 300
        assert not _real(x)
    else:
        assert _real(x) and isinstance(v, float) and v == float(x)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(VALUES)
def test_arrays_of_real_numbers_only(x):
    try:
        a = finite_array("masses", x, ndim=1)
    except ValueError as exc:
        assert "masses" in str(exc) and len(str(exc)) < 300
    else:
        assert isinstance(x, list) and all(_real(e) for e in x)
        assert a.dtype == float and np.all(np.isfinite(a)) and a.tolist() == [float(e) for e in x]


@settings(max_examples=150, deadline=None, derandomize=True)
@given(st.one_of(st.lists(SCALARS, min_size=3, max_size=3), VALUES),
       st.one_of(st.lists(SCALARS, min_size=3, max_size=3), st.none()), SCALARS)
def test_a_system_takes_real_values_or_names_the_bad_argument(masses, weights, level):
    try:
        s = charts.RotorSystem(3, masses=masses, weights=weights, level=level)
    except ValueError as exc:
        assert any(k in str(exc) for k in ("masses", "weights", "level")), str(exc)
    else:
        assert s.masses.dtype == float and np.all(s.masses > 0) and np.all(s.weights > 0)
        assert isinstance(s.level, float)


def test_work_that_cannot_fit_is_refused_before_it_starts(monkeypatch):
    """A tangent flow plans its memory first: beyond the budget (half the machine's memory;
    1 MiB here) the call is refused with the numbers and the remedy, before any allocation."""
    import pytest

    from charts.solvers import tangent
    monkeypatch.setattr(tangent, "memory_budget", lambda: 1 << 20)
    s = charts.RotorSystem(200)
    th, u = s.random_state(seed=1)
    with pytest.raises(ValueError, match=r"198 tangent vectors of N = 200 need .* GiB.*n_exponents"):
        charts.lyapunov_spectrum(s, th, u, 2.0, t_transient=0.0)
    r = charts.lyapunov_spectrum(s, th, u, 2.0, t_transient=0.0, n_exponents=3)   # 0.1 MiB
    assert r.exponents.shape == (3,)
    assert tangent.stacked_bytes(200, 198) == 7 * 199 * 400 * 8
