"""Callbacks and query times are checked where they enter: an event function must return one
finite real number at every call (else the run stops with an error naming the event and the
time, instead of losing zeros silently), and dense output takes real times only."""
from __future__ import annotations

import numpy as np
import pytest

import charts

SYSTEM = charts.RotorSystem(3)
STATE = SYSTEM.random_state(seed=3)


def _run(event, t_final=20.0):
    return charts.integrate(SYSTEM, *STATE, t_final, events=event)


def _later(value, t_switch=5.0):
    """An event that is fine (sin θ₀) until t_switch, then returns ``value``."""
    def event(t, y):
        return np.sin(y[0]) if t < t_switch else value
    return event


@pytest.mark.parametrize("value", [np.nan, np.inf, None, "0.5", 1 + 2j, np.array([1.0, 2.0]),
                                   [0.5], True, 10 ** 400, np.complex128(1.0)])
def test_a_bad_event_value_stops_the_run_naming_the_event_and_the_time(value):
    with pytest.raises(ValueError, match=r"events\[0\] \(event\) returned .* at t = "):
        _run(_later(value, t_switch=0.0))
    with pytest.raises(ValueError, match=r"events\[0\] \(event\) returned .* at t = ([5-9]|1\d)"):
        _run(_later(value))            # from a later time on: caught there too


@pytest.mark.parametrize("value", [0.5, 1, np.float32(0.25), np.int64(2), np.array(0.5),
                                   np.array([0.5])])
def test_real_numbers_of_every_kind_are_accepted(value):
    res = _run(_later(value))
    assert res.status == "finished"


def test_the_zeros_of_a_good_event_are_unchanged_by_the_check():
    def section(t, y):
        return np.sin(y[0])
    res = _run(section, 200.0)
    assert len(res.t_events[0]) > 5
    assert np.all(np.abs(np.sin(res.y_events[0][:, 0])) < 1e-9)


@pytest.mark.parametrize("t", ["1.0", np.array([["1.0"]]), np.zeros((2, 2)), 1 + 0j, None,
                               [True, False]])
def test_dense_output_takes_real_times_only(t):
    res = charts.integrate(SYSTEM, *STATE, 10.0, dense_output=True)
    with pytest.raises(ValueError, match="t must be"):
        res.sol(t)


def test_dense_output_still_takes_numbers_and_lists():
    res = charts.integrate(SYSTEM, *STATE, 10.0, dense_output=True)
    assert res.sol(5).shape == (6,)
    assert res.sol([1, 2.5, 7]).shape == (6, 3)
    assert np.allclose(res.sol(0.0), np.concatenate(STATE))
