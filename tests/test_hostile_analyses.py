"""Hostile input to the newest modules behind the typed layer (``charts.geometry.checks``):
each refusal a ValueError whose one-line message names the argument and its value, raised
before any work; a NaN never dropped; degenerate input given a defined answer or refused;
the plans whose cost grows without bound refused with their numbers."""
from __future__ import annotations

import math

import numpy as np
import pytest

import charts
from charts.analyses.arguments import steps_of
from charts.analyses.curvature_certificate import MAX_BOXES, certify_curvature_sign
from charts.analyses.flat_tori import MAX_TORUS_N, MAX_TORUS_STEPS, certify_flat_torus
from charts.analyses.spectrum_quantities import (entropy_with_error, kaplan_yorke_dimension,
                                                 kolmogorov_sinai_entropy,
                                                 leading_entropy_with_error)
from charts.analyses.tangency import oriented_volume, sign_changes
from charts.geometry.checks import integer, number
from charts.geometry.energy_shares import localised_fraction
from charts.geometry.topology import (MAX_CRITICAL_POINTS, critical_points,
                                      euler_characteristic)

S3 = charts.RotorSystem(3)
S4 = charts.RotorSystem(4)


def _one_line(exc_info, *words):
    text = str(exc_info.value)
    assert "\n" not in text
    for w in words:
        assert w in text, (w, text)


# 1. the Kolmogorov–Sinai entropy and the Kaplan–Yorke dimension keep a NaN

@pytest.mark.parametrize("spectrum", [[0.5, np.nan, -0.5], [np.nan, 0.1, -0.1],
                                      [0.3, 0.0, 0.0, np.nan]])
def test_a_nan_exponent_makes_the_entropy_nan(spectrum):
    assert math.isnan(kolmogorov_sinai_entropy(spectrum))
    assert math.isnan(kolmogorov_sinai_entropy(spectrum, positive=np.array(spectrum) > 0))
    assert math.isnan(kaplan_yorke_dimension(spectrum))


def test_a_nan_in_a_batch_or_the_mean_reaches_the_entropy_and_its_error():
    rows = np.array([[0.5, 0.2], [0.6, np.nan], [0.55, 0.25]])
    h, se = entropy_with_error(np.nanmean(rows, axis=0), rows)
    assert np.isfinite(h) and math.isnan(se)           # the bad batch is not skipped
    h, se = leading_entropy_with_error([0.5, np.nan], rows, 2)
    assert math.isnan(h)
    assert kolmogorov_sinai_entropy([0.5, 0.2, -0.2, -0.5]) == pytest.approx(0.7)


def test_the_mask_of_the_entropy_is_checked():
    with pytest.raises(ValueError) as e:
        kolmogorov_sinai_entropy([0.5, -0.5], positive=[1, 0])
    _one_line(e, "positive", "boolean mask")
    with pytest.raises(ValueError, match="positive"):
        kolmogorov_sinai_entropy([0.5, -0.5], positive=[True])


# 2. the localised fraction's threshold and histogram

@pytest.fixture(scope="module")
def lyapunov_result():
    return charts.lyapunov_spectrum(S3, *S3.random_state(seed=1), 4.0, t_transient=0.0,
                                    n_batches=2)


@pytest.mark.parametrize("share, words", [
    (True, ["share must be a real number", "True"]),
    ("0.4", ["share must be a real number", "'0.4'"]),
    (1.5, ["share must be a multiple of 1/100 in [0, 1]", "1.5"]),
    (-0.01, ["share must be a multiple of 1/100 in [0, 1]", "-0.01"]),
    (math.nan, ["share must be finite", "nan"]),
    (0.405, ["multiple of 1/100", "0.405"]),
    (None, ["share must be a real number", "None"])])
def test_the_share_is_a_real_number_in_0_1_on_a_bin_edge(lyapunov_result, share, words):
    with pytest.raises(ValueError) as e:
        lyapunov_result.localised_fraction(share)
    _one_line(e, *words)
    with pytest.raises(ValueError) as e:
        localised_fraction(lyapunov_result.energy_shares, share)
    _one_line(e, *words)


def test_the_share_is_checked_even_without_a_histogram(lyapunov_result):
    from dataclasses import replace
    bare = replace(lyapunov_result, energy_shares=None)
    with pytest.raises(ValueError, match="share must be a real number"):
        bare.localised_fraction("0.4")
    with pytest.raises(ValueError, match="holds no energy shares"):
        bare.localised_fraction(0.4)


@pytest.mark.parametrize("hist, words", [
    (True, ["hist", "True"]), ("0.4", ["hist", "'0.4'"]), (3.0, ["hist", "array of counts"]),
    ([1, -2, 3, 4], ["hist", "counts >= 0", "-2"]), ([1.0, np.nan], ["hist", "non-finite"]),
    ([], ["no energy shares"]), ([0, 0, 0, 0], ["no samples"])])
def test_the_histogram_is_an_array_of_counts(hist, words):
    with pytest.raises(ValueError) as e:
        localised_fraction(hist, 0.5)
    _one_line(e, *words)


def test_valid_shares_still_answer(lyapunov_result):
    hist = np.array([1, 2, 3, 4])
    assert localised_fraction(hist, 0.5) == pytest.approx(0.7)
    assert localised_fraction(hist, np.float32(0.25)) == pytest.approx(0.9)
    assert localised_fraction(hist, 0) == 1.0 and localised_fraction(hist, 1) == 0.0
    assert 0.0 <= lyapunov_result.localised_fraction() <= 1.0


# 3. the Euler characteristic of a level set

@pytest.mark.parametrize("weights, level, words", [
    ([1.0, 1.0, 1.0], math.nan, ["level must be finite", "nan"]),
    ([1.0, 1.0, 1.0], math.inf, ["level must be finite", "inf"]),
    ([1.0, 1.0, 1.0], "0", ["level must be a real number", "'0'"]),
    ([1.0, -1.0, 1.0], 0.5, ["weights must be finite and positive", "-1.0"]),
    ([1.0, 0.0, 1.0], 0.5, ["weights must be finite and positive", "0.0"]),
    ([], 0.5, ["weights", "[]"]),
    ([[1.0, 1.0]], 0.5, ["weights must be a 1-D array", "(1, 2)"]),
    ([1.0, math.nan, 1.0], 0.5, ["weights has non-finite entries"]),
    ([True, 1.0, 1.0], 0.5, ["weights must be an array of real numbers"])])
def test_euler_characteristic_refuses_bad_weights_and_levels(weights, level, words):
    with pytest.raises(ValueError) as e:
        euler_characteristic(weights, level)
    _one_line(e, *words)


def _must_not_run(monkeypatch, module, name):
    """``module.name`` made to fail the test if it is called: the work a plan refuses."""
    def started(*args, **kwargs):
        raise AssertionError(f"{name} ran before the plan refused the work")
    monkeypatch.setattr(module, name, started)


def test_too_many_critical_points_are_refused_with_the_count_and_memory(monkeypatch):
    import charts.geometry.topology as topology
    with monkeypatch.context() as m:
        _must_not_run(m, topology, "critical_points")      # planned, not allocated
        with pytest.raises(ValueError) as e:
            euler_characteristic([1.0] * 34, 0.5)
    _one_line(e, "N = 34", "17179869184 critical points", "768 GiB", "N <= 24")
    with pytest.raises(ValueError, match="critical points"):
        critical_points([1.0] * 25)
    assert MAX_CRITICAL_POINTS == 1 << 24


def test_the_enumeration_is_itertools_order_and_the_counts_hold():
    import itertools
    a = np.array([0.7, 1.3, 0.9, 1.1])
    signs = np.array(list(itertools.product((1.0, -1.0), repeat=4)))
    values, index = critical_points(a)
    assert np.allclose(values, signs @ a) and np.array_equal(index, (signs > 0).sum(axis=1))
    assert euler_characteristic([1, 1, 1], 0.0) == -4
    assert euler_characteristic(np.array([1.0, 1.0, 5.0]), np.float32(0.0)) == 0
    # N = 5, level 0.5: below it the points with at most two signs +, indices 0, 1, 2
    assert euler_characteristic([1.0] * 5, 0.5) == 2 * (1 - 5 + 10)


# 4. the certificates' plans

@pytest.mark.parametrize("steps, words", [
    (0, ["steps must be an integer >= 1", "got 0"]),
    (-64, ["steps", "got -64"]),
    (2.5, ["steps", "got 2.5"]),
    (True, ["steps", "True"]),
    ("4096", ["steps", "'4096'"]),
    (10 ** 13, ["steps=10000000000000", "9e+13 vector steps", str(MAX_TORUS_STEPS)])])
def test_certify_flat_torus_checks_its_steps_before_any_work(steps, words, monkeypatch):
    import charts.analyses.flat_tori as flat_tori
    _must_not_run(monkeypatch, flat_tori, "antipodal_torus")
    with pytest.raises(ValueError) as e:
        certify_flat_torus(S4, steps=steps)
    _one_line(e, *words)


def test_certify_flat_torus_refuses_a_proof_beyond_its_bound(monkeypatch):
    import charts.analyses.flat_tori as flat_tori
    big = charts.RotorSystem(300)
    with monkeypatch.context() as m:
        _must_not_run(m, flat_tori, "antipodal_torus")
        with pytest.raises(ValueError) as e:
            certify_flat_torus(big)
    _one_line(e, "N = 300", "dimension 299", f"N <= {MAX_TORUS_N}", "81 s")
    assert certify_flat_torus(S4, steps=np.int64(64)).params["steps"] == 64


@pytest.mark.parametrize("max_boxes", [-1, 0, 2.5, True, "10", MAX_BOXES + 1])
def test_certify_curvature_sign_checks_max_boxes(max_boxes):
    with pytest.raises(ValueError) as e:
        certify_curvature_sign(S3, max_boxes=max_boxes)
    _one_line(e, "max_boxes", f"1..{MAX_BOXES}")


# 5. the oriented volume and its crossings

def _sample():
    rng = np.random.default_rng(0)
    state = np.concatenate([[0.3, 1.2, 2.0, 0.7], rng.normal(size=4)])[None]
    return rng.normal(size=(1, 6, 8)), state, np.ones(4)


def test_a_crossing_through_an_exact_zero_counts():
    times, margins = sign_changes([0.0, 1.0, 2.0], [1.0, 0.0, -1.0])
    assert times.tolist() == [1.0] and margins.tolist() == [0.0]
    times, margins = sign_changes([0.0, 1.0, 2.0, 3.0], [1.0, 0.0, 0.0, 2.0])   # one touch
    assert times.tolist() == [1.5] and margins.tolist() == [0.0]
    times, margins = sign_changes([0.0, 1.0, 2.0, 3.0], [1.0, -1.0, 0.0, 2.0])
    assert times.tolist() == [0.5, 2.0] and margins.tolist() == [1.0, 0.0]
    assert sign_changes([0.0, 1.0], [1.0, 2.0])[0].size == 0


@pytest.mark.parametrize("t, v, words", [
    ([0.0, 1.0], [1.0, math.nan], ["v has non-finite entries"]),
    ([0.0, math.inf], [1.0, -1.0], ["t has non-finite entries"]),
    ([0.0, 1.0, 2.0], [1.0, -1.0], ["t must have shape (2,)", "(3,)"]),
    ([0.0, 1.0], "ab", ["v must be an array of real numbers"])])
def test_sign_changes_refuses_what_it_cannot_read(t, v, words):
    with pytest.raises(ValueError) as e:
        sign_changes(t, v)
    _one_line(e, *words)


def test_the_volume_of_degenerate_vectors_is_zero_never_nan():
    vectors, state, w = _sample()
    assert oriented_volume(np.zeros_like(vectors), 2, state, w).tolist() == [0.0]
    same = vectors.copy()
    same[0, 2] = same[0, 0]                              # E_u and E_cs share a direction
    assert abs(oriented_volume(same, 2, state, w)[0]) < 1e-12
    assert np.isfinite(oriented_volume(vectors, 2, state, w)).all()


@pytest.mark.parametrize("change, words", [
    (dict(states=np.zeros((1, 8))), ["states[0] is a singular point", "not defined"]),
    (dict(weights=np.zeros(4)), ["weights must be finite and positive"]),
    (dict(weights=np.ones(3)), ["weights must have shape (4,)"]),
    (dict(m=2.5), ["m must be an integer", "2.5"]),
    (dict(m=0), ["0 < m < 6", "m = 0"]),
    (dict(vectors=np.full((1, 6, 8), np.nan)), ["vectors has non-finite entries"]),
    (dict(states=np.zeros((1, 6))), ["states must have shape (1, 8)", "(1, 6)"]),
    (dict(states=np.full((1, 8), np.nan)), ["states has non-finite entries"])])
def test_oriented_volume_refuses_a_state_without_a_volume(change, words):
    vectors, state, w = _sample()
    kw = dict(vectors=vectors, m=2, states=state, weights=w, **{})
    kw.update(change)
    with pytest.raises(ValueError) as e:
        oriented_volume(kw["vectors"], kw["m"], kw["states"], kw["weights"])
    _one_line(e, *words)


# 7. messages that do not contradict themselves

def test_zero_d_arrays_are_the_numbers_they_hold():
    assert integer("n_grid", np.array(32), 8, 16384) == 32
    assert integer("n_grid", np.array(32.0), 8, 16384) == 32
    assert number("level", np.array(0.25)) == 0.25
    with pytest.raises(ValueError) as e:
        integer("n_grid", np.array(2.5), 8, 16384)
    _one_line(e, "n_grid must be an integer in 8..16384, got 2.5")
    with pytest.raises(ValueError) as e:
        integer("n_grid", np.array(True), 8, 16384)
    _one_line(e, "got True")
    assert charts.surface_integrals(S3, np.array(16)).n_grid == 16


def test_a_float32_step_is_the_decimal_it_prints():
    assert number("dt", np.float32(0.01)) == 0.01
    assert number("dt", np.float16(0.1)) == 0.1
    assert steps_of("t_final", 10.0, number("dt", np.float32(0.01))) == 1000
    r = charts.lyapunov_spectrum(S3, *S3.random_state(seed=1), 1.0, dt=np.float32(0.01),
                                 t_transient=0.0, n_batches=2)
    assert r.params["dt"] == 0.01


def test_the_suggested_duration_differs_from_the_one_written():
    dt = float(np.float32(0.01))                       # 0.009999999776482582 as a float64
    with pytest.raises(ValueError) as e:
        steps_of("t_final", 10.0, dt)
    text = str(e.value)
    assert "dt=0.009999999776482582" in text and "e.g. 9.99999977648258" in text
    with pytest.raises(ValueError, match=r"t_final=0.015 is not a whole number of steps "
                                         r"dt=0.01; use a multiple of dt \(e.g. 0.02\)"):
        steps_of("t_final", 0.015, 0.01)


# 8. t_transient="auto"

@pytest.mark.parametrize("kw, words", [
    (dict(t_final=-1.0), ["t_final must be positive", "-1.0"]),
    (dict(t_final=10.0, dt=0.0), ["dt must be positive", "0.0"]),
    (dict(t_final=10.0, dt=0.03), ["t_final=10 is not a whole number of steps dt=0.03"]),
    (dict(t_final=10.0, n_batches=1), ["n_batches", "got 1"]),
    (dict(t_final=10.0, n_exponents=9), ["n_exponents=9"])])
def test_auto_checks_every_setting_before_its_pilot(kw, words, monkeypatch):
    import charts.analyses.lyapunov as lyapunov
    theta, u = S4.random_state(seed=1)
    _must_not_run(monkeypatch, lyapunov, "auto_transient")     # no pilot of 250 time units
    with pytest.raises(ValueError) as e:
        charts.lyapunov_spectrum(S4, theta, u, t_transient="auto", **kw)
    _one_line(e, *words)


def test_auto_works_where_50_is_no_whole_number_of_steps():
    theta, u = S4.random_state(seed=1)
    r = charts.lyapunov_spectrum(S4, theta, u, 9.99, dt=0.03, t_transient="auto",
                                 n_batches=2)
    tr = r.params["t_transient"]
    assert 50.0 - 0.03 <= tr <= 5000.0 and abs(tr / 0.03 - round(tr / 0.03)) < 1e-6
    assert r.params["transient_rule"].startswith("auto")


# 6. charts verdict: every N, setting and output path before any work

@pytest.fixture
def no_work(monkeypatch):
    """The reports of ``charts verdict`` made to fail the test if one starts."""
    import charts.runs.verdict as verdict
    import charts.runs.verdict_linkage as verdict_linkage
    import charts.runs.verdict_statistics as verdict_statistics

    def started(*args, **kwargs):
        raise AssertionError("a report started before every argument was checked")
    for module, name in ((verdict, "surface_verdict"), (verdict, "torus_verdict"),
                         (verdict_statistics, "statistics_verdict"),
                         (verdict_linkage, "linkage_verdict")):
        monkeypatch.setattr(module, name, started)


def _refused(capsys, argv, *words):
    from charts.cli.main import main
    assert main(["verdict", *argv]) == 2          # refused before any report (`no_work`)
    err = capsys.readouterr().err.strip()
    assert err.startswith("charts: error: ") and "\n" not in err, err
    for w in words:
        assert w in err, (w, err)


@pytest.mark.parametrize("argv, words", [
    (["--n", "100000"], ["N = 100000 rotors", "N <= 12"]),
    (["--n", "4", "300"], ["N = 300 rotors", "dimension 299"]),
    (["--n", "4", "3", "--grid", "5"], ["--grid must be an integer in 8..16384, got 5"]),
    (["--n", "4", "3", "--t-final", "nan"], ["--t-final must be finite, got nan"]),
    (["--n", "4", "3", "--t-final", "-1"], ["--t-final must be positive, got -1.0"]),
    (["--n", "4", "3", "--t-final", "0.015"], ["t_final=0.015 is not a whole number of steps"]),
    (["--n", "4", "3", "--seeds", "1", "-1"], ["--seeds must be an integer >= 0, got -1"]),
    (["--n", "4", "2"], ["n must be >= 3", "n=2"]),
    (["--n", "3", "--level", "1"], ["level=1.0 is a critical value"]),
    (["--n", "4", "13"], ["N = 13 rotors", "1,728 Christoffel symbols"])])
def test_verdict_checks_every_n_and_setting_before_the_first_report(capsys, no_work, argv,
                                                                     words):
    _refused(capsys, argv, *words)


def test_verdict_statistics_plans_every_system_first(capsys, no_work, tmp_path):
    base = ["--statistics", "--device", "cpu", "--samples", "400", "--members", "2"]
    _refused(capsys, base + ["--n", "3", "100000"], "N = 100000: on the CPU each member keeps",
             "MB for T = 20")
    _refused(capsys, base + ["--n", "3", "--t-transient", "nan"], "--t-transient must be finite")
    _refused(capsys, base + ["--n", "3", "--t-transient", "0.015"],
             "N = 3: t_transient=0.015 is not a whole number of steps")
    (tmp_path / "f").write_text("")
    _refused(capsys, base + ["--n", "3", "--out", str(tmp_path / "f")],
             "--out", "is a file, not a folder")
    _refused(capsys, base + ["--n", "3", "--out", str(tmp_path / "f" / "sub")],
             "is a file, so no folder can be created")


def test_verdict_json_is_checked_writable_before_any_work(capsys, no_work, tmp_path):
    (tmp_path / "f").write_text("")
    before = sorted(p.name for p in tmp_path.iterdir())
    _refused(capsys, ["--n", "4", "--json", str(tmp_path)], "--json", "is a folder, not a file")
    _refused(capsys, ["--n", "4", "--json", str(tmp_path / "no" / "v.json")],
             "the folder", "does not exist")
    _refused(capsys, ["--n", "4", "--json", str(tmp_path / "f" / "v.json")],
             "is a file, not a folder")
    _refused(capsys, ["--n", "4", "--json", str(tmp_path / ("x" * 300))], "bytes, more than")
    assert sorted(p.name for p in tmp_path.iterdir()) == before      # nothing left behind


def test_verdict_json_in_a_read_only_folder_is_refused(capsys, no_work, tmp_path, monkeypatch):
    import os
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    try:
        if os.access(ro, os.W_OK):                   # root writes anywhere: say it cannot
            import charts.runs.outdir as outdir
            monkeypatch.setattr(outdir.os, "access", lambda path, mode: False)
        _refused(capsys, ["--n", "4", "--json", str(ro / "v.json")],
                 "cannot write in the folder", str(ro))
        _refused(capsys, ["--statistics", "--n", "3", "--device", "cpu", "--out",
                          str(ro / "out")], "--out", "cannot write in the folder")
    finally:
        ro.chmod(0o755)
    assert list(ro.iterdir()) == []


def test_verdict_writes_its_json_where_it_may(tmp_path, capsys):
    import json
    from charts.cli.main import main
    out = tmp_path / "v.json"
    assert main(["verdict", "--n", "5", "--json", str(out)]) == 0
    assert json.loads(out.read_text())[0]["torus"]["verdict"] == "not hyperbolic"


def test_an_ensembles_auto_transient_checks_every_setting_before_its_pilot(monkeypatch):
    """``lyapunov_ensemble(t_transient="auto")`` refuses a bad setting before its pilot runs
    (the pilot is made to fail loudly if it is reached)."""
    import pytest

    import charts
    from charts.analyses import lyapunov

    def no_pilot(*args, **kwargs):
        raise AssertionError("the pilot ran before the settings were checked")

    monkeypatch.setattr(lyapunov, "auto_transient", no_pilot)
    S = charts.RotorSystem(3)
    for bad, match in ((dict(dt=-0.01), "dt"), (dict(n_batches=0), "n_batches"),
                       (dict(n_exponents=7), "n_exponents")):
        with pytest.raises(ValueError, match=match):
            charts.lyapunov_ensemble(S, 2, 10.0, workers=1, t_transient="auto", **bad)
