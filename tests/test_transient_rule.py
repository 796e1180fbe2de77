"""The transient rule (``t_transient="auto"``, ``charts.analyses.lyapunov.auto_transient``)
removes the bias of the smallest exponent that a short transient leaves in short runs, at a
size CI affords: N = 5, 128 members of T = 50, against a reference of 16 members of
T = 2000 (errors across the members; the seeds are fixed, so the numbers are too)."""
import numpy as np
import pytest

import charts
from charts.analyses.arguments import Documented
from charts.analyses.lyapunov import AUTO_TRANSIENT_RANGE, auto_transient
from charts.analyses.transients import SCALED_RULE, scaled_transient

SYSTEM = charts.RotorSystem(5)


def _smallest(ens):
    E = np.array([m.exponents[-1] for m in ens.members])
    return E.mean(), E.std(ddof=1) / np.sqrt(E.size)


def test_the_rule_removes_the_bias_of_the_smallest_exponent():
    """Measured: transient 10 gives λ₃ = 0.1015 ± 0.0037 against the reference 0.1217 ±
    0.0015 (5σ low); the rule's transient (about 250 here) gives 0.1214 ± 0.0044.  Asserted:
    the short transient more than 3σ off, the rule within 2σ (combined errors)."""
    kw = dict(workers=2, seed=1, n_batches=4)
    ref = _smallest(charts.lyapunov_ensemble(SYSTEM, 16, 2000.0, t_transient=100.0, **kw))
    short = _smallest(charts.lyapunov_ensemble(SYSTEM, 128, 50.0, t_transient=10.0, **kw))
    auto = charts.lyapunov_ensemble(SYSTEM, 128, 50.0, t_transient="auto", **kw)
    rule = _smallest(auto)
    assert abs(short[0] - ref[0]) > 3 * np.hypot(short[1], ref[1])
    assert abs(rule[0] - ref[0]) < 2 * np.hypot(rule[1], ref[1])
    tr = auto.members[0].params["t_transient"]
    assert AUTO_TRANSIENT_RANGE[0] <= tr <= AUTO_TRANSIENT_RANGE[1]
    assert auto.params["t_transient"] == tr and auto.params["transient_rule"].startswith("auto")


def test_the_rule_on_one_run_and_its_arguments():
    th, u = SYSTEM.random_state(seed=3)
    r = charts.lyapunov_spectrum(SYSTEM, th, u, 5.0, t_transient="auto")
    assert r.params["transient_rule"].startswith("auto")
    assert r.params["t_transient"] == pytest.approx(float(auto_transient(SYSTEM, th, u)), abs=0.01)
    with pytest.raises(ValueError, match="t_transient must be a duration, 'scaled' or 'auto'"):
        charts.lyapunov_spectrum(SYSTEM, th, u, 5.0, t_transient="long")


def test_the_default_leaves_the_smallest_exponent_unbiased():
    """The default ("scaled": 5 N² / speed, 125 at N = 5) against a long reference: measured
    λ₃ = 0.1197 ± 0.0024 (512 members of T = 50) against 0.1212 ± 0.0009 (64 members of
    T = 2000), 0.6σ; the old default of 50 gave 0.1155 ± 0.0023, 2.3σ low
    (charts.analyses.transients).  Asserted: the default within 2σ (combined errors)."""
    kw = dict(workers=2, seed=1, n_batches=4)
    ref = _smallest(charts.lyapunov_ensemble(SYSTEM, 64, 2000.0, t_transient=100.0, **kw))
    default = charts.lyapunov_ensemble(SYSTEM, 512, 50.0, **kw)
    got = _smallest(default)
    assert abs(got[0] - ref[0]) < 2 * np.hypot(got[1], ref[1])
    assert default.params["t_transient"] == 125.0
    assert default.params["transient_rule"].startswith("scaled")


def test_the_scaled_rule():
    """5 N² / speed, at least 50 and without an upper bound (15 e-foldings of the measured
    λ_{N−2} up to N = 64): N = 3 keeps the old 50 (one positive exponent), the times scale as
    1/speed, and lyapunov_spectrum's default is the rule."""
    assert [scaled_transient(n, 1.0) for n in (3, 4, 5, 8, 32, 64)] == [50, 80, 125, 320,
                                                                       5120, 20480]
    assert scaled_transient(5, 2.0) == 62.5 and isinstance(scaled_transient(5, 1.0), Documented)
    th, u = SYSTEM.random_state(seed=3, speed=0.5)
    r = charts.lyapunov_spectrum(SYSTEM, th, u, 1.0, n_batches=2)
    assert r.params["t_transient"] == pytest.approx(250.0)
    assert r.params["transient_rule"] == SCALED_RULE
    with pytest.raises(ValueError, match="did you mean 'scaled'"):
        charts.lyapunov_spectrum(SYSTEM, th, u, 1.0, t_transient="scald")


def test_auto_checks_the_run_before_its_pilot(monkeypatch):
    """A bad t_final or dt is refused before the pilot runs (in the API, an ensemble and a
    scene), and "auto" works at a step of which 50 is no whole number (dt = 0.03)."""
    import charts.analyses.lyapunov as lyapunov
    from charts.runs.scene import SceneError, parse_scene

    def no_pilot(*a, **k):
        raise AssertionError("the pilot ran before the run's settings were checked")
    th, u = SYSTEM.random_state(seed=4)
    with monkeypatch.context() as m:
        m.setattr(lyapunov, "auto_transient", no_pilot)
        with pytest.raises(ValueError, match="t_final"):
            charts.lyapunov_spectrum(SYSTEM, th, u, 2.0, dt=0.03, t_transient="auto")
        with pytest.raises(ValueError, match="dt"):
            charts.lyapunov_spectrum(SYSTEM, th, u, 2.0, dt=-0.01, t_transient="auto")
        with pytest.raises(ValueError, match="t_final"):
            charts.lyapunov_ensemble(SYSTEM, 2, 2.0, dt=0.03, t_transient="auto", workers=1)
        with pytest.raises(SceneError, match="t_final"):
            parse_scene({"system": {"n": 5}, "initial": {"seed": 11}, "integrator": {"dt": 0.03},
                         "run": {"t_final": 2.0, "t_transient": "auto"},
                         "effects": {"lyapunov": {}}})
    r = charts.lyapunov_spectrum(SYSTEM, th, u, 2.01, dt=0.03, t_transient="auto", n_batches=2,
                                 reorth_every=0.03)
    steps = r.params["t_transient"] / 0.03
    assert steps == pytest.approx(round(steps)) and r.params["t_transient"] >= 50
