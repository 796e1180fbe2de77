"""A Mechanism's transient named by a rule: ``t_transient="auto"`` on every analysis of a
mechanism (its pilot the mechanism's own ``lyapunov_spectrum``, the rotors' rule of
``charts.analyses.transients``), in its ensembles, its scenes and sweeps; "scaled" (the
rotors' rule, measured on the rotors only) refused pointing to "auto" or a duration."""
import numpy as np
import pytest

import charts
from charts.analyses import mechanism_lyapunov
from charts.analyses.mechanism_lyapunov import lyapunov_spectrum
from charts.mechanism.errors import MechanismError
from charts.runs.scene import SceneError, parse_scene

R = 0.2
MECH = charts.triple_linkage(R)
DT = 0.01


def pilot_duration(q, v, **settings):
    """The rule of "auto" by hand (docs/mechanisms.md, "Transients"): 15 over the smallest
    positive exponent of a pilot of 200 time units after 50, two batches, the run's
    settings, within [50, 5000], on the grid of dt."""
    lam = lyapunov_spectrum(MECH, q, v, 200.0, t_transient=50.0, n_batches=2,
                            **settings).exponents
    positive = lam[lam > 0]
    rate = max(positive.min(), positive.max() / 100)
    return round(min(5000.0, max(50.0, 15.0 / rate)) / DT) * DT


@pytest.mark.parametrize("speed,clamped", [(1.0, True), (0.25, False)])
def test_auto_is_15_e_foldings_of_the_pilot_within_the_range(speed, clamped):
    """At unit speed λ₁ ≈ 0.49 (15/λ₁ ≈ 30: the lower bound 50 holds); at speed 0.25 the
    exponent is a quarter (15/λ₁ ≈ 125, inside the range).  The run with "auto" is the run
    with that duration written, bit for bit, and records the rule."""
    q, v = MECH.random_state(seed=3, speed=speed)
    expected = pilot_duration(q, v, seed=4)
    assert (expected == 50.0) == clamped
    auto = lyapunov_spectrum(MECH, q, v, 2.0, t_transient="auto", n_batches=2, seed=4)
    assert auto.params["t_transient"] == pytest.approx(expected, abs=1e-9)
    assert auto.params["transient_rule"].startswith("auto: 15 / (smallest positive")
    written = lyapunov_spectrum(MECH, q, v, 2.0, t_transient=expected, n_batches=2, seed=4)
    assert np.array_equal(auto.exponents, written.exponents)
    assert "transient_rule" not in written.params


def test_the_rule_is_saved_with_the_result(tmp_path):
    q, v = MECH.random_state(seed=3)
    auto = lyapunov_spectrum(MECH, q, v, 1.0, t_transient="auto", n_batches=2)
    back = charts.load(auto.save(tmp_path / "auto.nc"))
    assert back.params == auto.params and back.params["transient_rule"].startswith("auto")


def test_every_analysis_takes_auto_and_records_it():
    """The curvature, the angle test and the CLVs (through the public names) take "auto",
    their pilot the spectrum's with their dt and seed; each equals the call with the
    duration written (the angles' on the grid of sample_every)."""
    q, v = MECH.random_state(seed=1)
    expected = pilot_duration(q, v, seed=2)      # (the lower bound 50: short runs, fast)
    for name, field, kw in (("curvature_along_trajectory", "K_numeric", {}),
                            ("hyperbolicity_angles", "phi_restricted", {}),
                            ("covariant_lyapunov_vectors", "phi", {"sample_every": 0.5})):
        fn = getattr(charts, name)
        auto = fn(MECH, q, v, 1.0, t_transient="auto", seed=2, **kw)
        written = fn(MECH, q, v, 1.0, t_transient=auto.params["t_transient"], seed=2, **kw)
        grid = 0.1 if name == "hyperbolicity_angles" else DT
        assert abs(auto.params["t_transient"] - expected) <= grid / 2 + 1e-9, name
        assert auto.params["transient_rule"].startswith("auto"), name
        assert np.array_equal(getattr(auto, field), getattr(written, field)), name


def test_an_ensemble_runs_one_pilot_for_every_member():
    """As the rotors' ensembles: one duration, from the first member's state and seed."""
    res = charts.lyapunov_ensemble(MECH, 2, 1.0, speed=0.25, seed=5, workers=1,
                                   t_transient="auto", n_batches=2)
    expected = pilot_duration(*MECH.random_state(seed=5, speed=0.25), seed=5)
    assert [m.params["t_transient"] for m in res.members] == pytest.approx([expected] * 2,
                                                                            abs=1e-9)
    assert res.params["transient_rule"].startswith("auto")
    assert all(m.params["transient_rule"] == res.params["transient_rule"]
               for m in res.members)


def _no_pilot(monkeypatch):
    def ran(*args, **kwargs):
        raise AssertionError("the pilot ran before every setting was checked")
    monkeypatch.setattr(mechanism_lyapunov, "auto_transient", ran)


CALLS = {
    "lyapunov_spectrum": lambda q, v, **kw: charts.lyapunov_spectrum(MECH, q, v, 10.0, **kw),
    "curvature": lambda q, v, **kw: charts.curvature_along_trajectory(MECH, q, v, 1.0, **kw),
    "angles": lambda q, v, **kw: charts.hyperbolicity_angles(MECH, q, v, 1.0, **kw),
    "clvs": lambda q, v, **kw: charts.covariant_lyapunov_vectors(MECH, q, v, 1.0, **kw),
}


@pytest.mark.parametrize("call", CALLS)
@pytest.mark.parametrize("kw,error,words", [
    (dict(dt=-0.01), ValueError, ["dt"]),
    (dict(seed=-1), ValueError, ["seed"]),
    (dict(project_every=0.013), ValueError, ["project_every"]),
    (dict(off=True), MechanismError, ["q0"]),
    (dict(rest=True), MechanismError, ["v0"]),
])
def test_auto_checks_every_setting_before_its_pilot(call, kw, error, words, monkeypatch):
    q, v = MECH.random_state(seed=1)
    kw = dict(kw)                                     # (the parameters are shared)
    if kw.pop("off", False):
        q = q + 0.1
    if kw.pop("rest", False):
        v = 0 * v
    _no_pilot(monkeypatch)
    with pytest.raises(error) as e:
        CALLS[call](q, v, t_transient="auto", **kw)
    for w in words:
        assert w in str(e.value)


@pytest.mark.parametrize("run,kw,words", [
    (charts.lyapunov_ensemble, dict(n_batches=1), ["n_batches"]),
    (charts.hyperbolicity_ensemble, dict(sample_every=0.3), ["sample_every"]),
    (charts.hyperbolicity_tally, dict(sample_every=0.3), ["sample_every"]),
    (charts.covariant_ensemble, dict(n_unstable=2), ["n_unstable"]),
])
def test_an_ensemble_checks_its_members_settings_before_its_pilot(run, kw, words,
                                                                   monkeypatch):
    _no_pilot(monkeypatch)
    with pytest.raises(ValueError) as e:
        run(MECH, 2, 1.0, workers=1, t_transient="auto", **kw)
    for w in words:
        assert w in str(e.value)


@pytest.mark.parametrize("call", CALLS)
@pytest.mark.parametrize("value,words", [
    ("scaled", ["'scaled' is the rotors' rule", "t_transient='auto'", "or a duration"]),
    ("atuo", ["did you mean 'auto'?"]),
])
def test_scaled_and_bad_rules_are_refused(call, value, words):
    q, v = MECH.random_state(seed=1)
    with pytest.raises(ValueError) as e:
        CALLS[call](q, v, t_transient=value)
    for w in words:
        assert w in str(e.value)
    with pytest.raises(ValueError, match="'scaled' is the rotors' rule"):
        charts.lyapunov_ensemble(MECH, 2, 1.0, workers=1, t_transient="scaled")


SCENE = {"mechanism": {"name": "triple_linkage", "r": R}, "initial": {"seed": 2},
         "system": {"speed": 0.25}, "run": {"t_final": 1.0, "t_transient": "auto"},
         "effects": {"lyapunov": {"n_batches": 2}, "angles": {"sample_every": 0.5}}}


def test_a_mechanism_scene_with_auto_runs_as_the_api(tmp_path):
    """[run] t_transient = "auto" on a [mechanism] scene: the API's duration from the
    scene's seeded state (the angle pass's on its sample_every), the rule recorded, the
    exponents those of ``lyapunov_spectrum(..., t_transient="auto")`` bit for bit."""
    from charts.runs.runner import run_scene

    sc = parse_scene(SCENE)
    q, v = MECH.random_state(seed=2, speed=0.25)
    api = lyapunov_spectrum(MECH, q, v, 1.0, t_transient="auto", n_batches=2, seed=2)
    assert sc.run["t_transient"] == pytest.approx(api.params["t_transient"], abs=1e-9)
    assert abs(sc.effects["angles"]["t_transient"] - api.params["t_transient"]) <= 0.25
    assert sc.transient_rule == api.params["transient_rule"]
    res = run_scene(sc, tmp_path / "out", quiet=True)
    assert res["status"] == "complete"
    assert res["results"]["lyapunov"]["exponents"] == api.exponents.tolist()
    assert res["transient_rule"] == api.params["transient_rule"]


def test_a_sweep_over_a_mechanism_takes_auto():
    """Each point's scene resolves "auto" from its own mechanism (here r)."""
    from charts.runs.sweep import parse_sweep, sweep_points

    base = {k: v for k, v in SCENE.items() if k != "effects"}
    base["effects"] = {"lyapunov": {"n_batches": 2}}
    pts = sweep_points(parse_sweep({"name": "auto-r", "scene": base,
                                    "sweep": {"seeds": [2], "parameters": {"r": [0.1, R]}}}))
    for p in pts:
        mech = charts.triple_linkage(p.params["r"])
        api = lyapunov_spectrum(mech, *mech.random_state(seed=2, speed=0.25), 1.0,
                                t_transient="auto", n_batches=2, seed=2)
        assert p.scene.run["t_transient"] == pytest.approx(api.params["t_transient"],
                                                           abs=1e-9)


@pytest.mark.parametrize("value,words", [
    ("scaled", ["[run] t_transient", "'scaled' is the rotors' rule", "'auto'"]),
    ("atuo", ["[run] t_transient", "did you mean 'auto'?"])])
def test_a_mechanism_scene_refuses_scaled_and_bad_rules(value, words):
    with pytest.raises(SceneError) as e:
        parse_scene(dict(SCENE, run={"t_final": 1.0, "t_transient": value}))
    for w in words:
        assert w in str(e.value)
