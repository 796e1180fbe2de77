"""The family study (docs/families-study.md): the bundled sweeps are what the docs say, the named
weight patterns [sweep.weights] of sweeps, and the statistics of the small angles against
closed forms on synthetic samples:

* the law P(X < x) = A x^β fitted below x0 (`small_value_law`): the exponent and A of samples
  drawn from that law, within 4 standard errors, with errors that match the closed forms
  β/√k and √(p(1−p)/n)/x0² for independent samples and grow like √r when every sample is
  repeated r times (batch means see the correlation);
* pooling the laws of parts of a sample gives the law of the whole exactly;
* block minima against E[min of s samples] = Γ(s+1)Γ(½) / (2√A Γ(s+3/2)) for F = A x².
"""
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.special import gammaln

from charts.analyses.hyperbolicity import LAW_KEYS, angle_statistics
from charts.analyses.statistics import block_minima, pool_small_value_laws, small_value_law
from charts.geometry.system import critical_levels
from charts.runs.sweep import (SweepError, load_sweep, parse_sweep, point_columns,
                               summarize, sweep_points)
from charts.runs.sweep.spec import bundled_sweeps
from charts.runs.sweep.statistics import result_statistics
from charts.runs.sweep.table import WEIGHT_VECTOR, point_row

DOCS = Path(__file__).resolve().parents[1] / "docs" / "families-study.md"
#: statistical margin of the closed-form checks (two-sided, in standard errors)
SIGMAS = 4.0
#: relative margin of an error estimate against its closed form: the batch-means error of
#: 20 batches scatters by ~1/√(2·19) = 16 % (measured with these seeds: ratios 0.87–1.27)
SE_RTOL = 0.35


def _law_samples(rng, A, beta, size):
    """Samples with P(X < x) = A x^β on [0, A^(−1/β)]."""
    return (rng.random(size) / A) ** (1.0 / beta)


# ------------------------------------------------------------------ the bundled sweeps
def _docs_rows(n):
    """(weights, level) of the rows of the docs' tables for N = n (first table of each)."""
    text = DOCS.read_text()
    head = text.index(f"### N = {n},")
    table = text[head:].split("\n\n")[1]
    rows = set()
    for line in table.splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        rows.add((cells[0], float(cells[1])))
    return rows


@pytest.mark.parametrize("name, n, patterns, levels", [
    ("families-n4", 4, {"(1,1,1,1)", "(1,1,1,2)", "(1,2,1,2)", "(1,1,2,3)"},
     [0.0, 0.1, 0.25, 0.5, 1.0, 1.5, 1.9]),
    ("families-n5", 5, {"(1,1,1,1,1)"}, [0.0, 0.5, 1.0, 2.0, 2.9]),
])
def test_bundled_family_sweeps_are_what_the_docs_say(name, n, patterns, levels):
    sw = load_sweep(bundled_sweeps()[name])
    pts = sweep_points(sw)
    assert set(sw.weights) == patterns and sw.axes["level"] == levels
    assert len(pts) == len(patterns) * len(levels) * len(sw.seeds)
    for p in pts:
        sc = p.scene
        assert sc.system["n"] == n and sc.system["level"] == p.params["level"]
        name_of = "(" + ",".join(f"{w:g}" for w in sc.system["weights"]) + ")"
        assert name_of == p.params["weights"]
        assert sc.integrator["formulation"] == "ambient"
        assert sc.effects["curvature"]["route"] == "numerical"
        assert sc.effects["angles"]["variant"] == "restricted"
        assert all(abs(p.params["level"]) < sum(sc.system["weights"]) for p in pts)
    combos = {(p.params["weights"], p.params["level"]) for p in pts}
    assert _docs_rows(n) == combos
    # the docs' "critical" marks are the levels that are sums of ±a_i
    text = DOCS.read_text()
    for w, c in combos:
        crit = np.min(np.abs(critical_levels(json.loads(w.replace("(", "[").replace(")", "]")))
                             - c)) < 1e-12
        line = re.search(rf"^\| {re.escape(w)} \| {c:g} \| ([^|]*)\|", text, re.M).group(1)
        assert ("critical" in line) == crit, (w, c, line)


# ------------------------------------------------------------------ [sweep.weights]
BASE = {"system": {"n": 4}, "run": {"t_final": 10.0}, "effects": {"angles": {}}}


def _sweep(**over):
    data = {"name": "w", "scene": BASE,
            "sweep": {"seeds": [0], "parameters": {"level": [0.5], "w": [2.0, 3.0]},
                      "weights": {"(1,1,1,w)": [1, 1, 1, "w"], "(1,w,1,w)": [1, "w", 1, "w"]}}}
    data["sweep"].update(over)
    return parse_sweep(data, source="w.toml")


def test_weight_patterns_are_an_axis_with_symbols():
    pts = sweep_points(_sweep())
    assert len(pts) == 2 * 2
    assert pts[-1].params == {"weights": "(1,w,1,w)", "level": 0.5, "w": 3.0, "seed": 0}
    assert pts[-1].scene.system["weights"] == [1.0, 3.0, 1.0, 3.0]
    assert pts[0].scene.system["weights"] == [1.0, 1.0, 1.0, 2.0]
    cols = point_columns(pts)
    assert cols[3:6] == ["weights", "level", "w"]
    assert cols[-5:] == ["mass_vector", WEIGHT_VECTOR, "t_final", "error", "scene"]
    out = {"status": "complete", "stats": {}, "t_final": 10.0}
    row = dict(zip(cols, point_row(pts[-1], out, cols)))
    assert json.loads(row[WEIGHT_VECTOR]) == [1.0, 3.0, 1.0, 3.0]
    # masses and weights patterns together: both are axes, masses first
    both = _sweep(masses={"heavy": [1, 1, 1, 2]})
    p = sweep_points(both)[0]
    assert list(p.params)[:2] == ["masses", "weights"]
    assert p.scene.system["masses"] == [1.0, 1.0, 1.0, 2.0]
    # a sweep without weight patterns keeps its columns
    plain = parse_sweep({"name": "p", "scene": BASE, "sweep": {"parameters": {"level": [0.5]}}})
    assert WEIGHT_VECTOR not in point_columns(sweep_points(plain))


def test_summary_of_a_weighted_sweep_leaves_the_weight_vector_out():
    pts = sweep_points(_sweep(parameters={"level": [0.5]}, weights={"e": [1, 1, 1, 1]},
                              seeds=[0, 1]))
    cols = point_columns(pts)
    rows = []
    for p, m in zip(pts, (0.2, 0.4)):
        out = {"status": "complete", "t_final": 10.0,
               "stats": {"phi_restricted_min": m, "phi_restricted_median": m}}
        rows.append(dict(zip(cols, point_row(p, out, cols))))
    s = summarize(cols, rows, pts)
    assert WEIGHT_VECTOR not in s["stats"] and s["params"] == ["weights", "level"]
    (entry,) = s["rows"]
    assert entry["phi_restricted_min"] == 0.2 and entry["phi_restricted_median"] == \
        pytest.approx(0.3)


@pytest.mark.parametrize("change, message", [
    ({"weights": {"p": [1, 1, "q", 1]}}, "[sweep.weights] 'p': 'q' uses q, which is not a "
                                         "parameter"),
    ({"weights": {"p": [1, 1, 0, 1]}}, "[sweep.weights] 'p': 0 is not allowed"),
    ({"weights": {"p": [1, 1, 1, 1]}}, "w is not used"),
    ({"parameters": {"level": [0.5], "w": [2.0], "system.weights": [[1, 1, 1, 1]]}},
     "both set the weights"),
    ({"parameters": {"weights": [1.0]}}, "seed/masses/weights are reserved"),
])
def test_malformed_weight_patterns_are_named(change, message):
    with pytest.raises(SweepError) as exc:
        _sweep(**change)
    assert message in str(exc.value)


def test_a_weight_pattern_of_the_wrong_length_names_the_point():
    with pytest.raises(SweepError, match=r"point 0 \(weights=p, level=0.5, w=2.0, seed=0\): "
                                         r"\[system\] weights"):
        sweep_points(_sweep(weights={"p": [1, 1, "w"]}))


# ------------------------------------------------------------------ the small-angle law
@pytest.mark.parametrize("A, beta", [(4.0, 2.0), (30.0, 3.0), (1.5, 1.0)])
def test_small_value_law_against_the_law_it_is_drawn_from(A, beta):
    rng = np.random.default_rng(7)
    n, x0 = 200_000, 0.1
    law = small_value_law(_law_samples(rng, A, beta, n), x0, n_batches=20)
    p = A * x0 ** beta                                     # P(X < x0)
    assert law["n"] == n and law["x0"] == x0
    assert abs(law["count"] - n * p) < SIGMAS * math.sqrt(n * p * (1 - p))
    k = law["count"]
    assert abs(law["exponent"] - beta) < SIGMAS * law["exponent_se"]
    assert law["exponent_se"] == pytest.approx(beta / math.sqrt(k), rel=SE_RTOL)
    coef2_se = math.sqrt(p * (1 - p) / n) / x0 ** 2
    assert law["coef2_se"] == pytest.approx(coef2_se, rel=SE_RTOL)
    if beta == 2.0:
        assert abs(law["coef2"] - A) < SIGMAS * law["coef2_se"]


def test_small_value_law_errors_see_correlated_samples():
    """Every sample repeated r = 9 times (a tangency passage sampled 9 times): the
    estimates are unchanged, and so are the batch-means errors (there are still only the
    independent samples of the original), √9 = 3 times what the formulas for 9 times as many
    independent samples would say."""
    rng = np.random.default_rng(3)
    x = _law_samples(rng, 4.0, 2.0, 40_000)
    one = small_value_law(x, 0.1, n_batches=20)
    rep = small_value_law(np.repeat(x, 9), 0.1, n_batches=20)
    assert rep["exponent"] == pytest.approx(one["exponent"], rel=1e-12)
    assert rep["coef2"] == pytest.approx(one["coef2"], rel=1e-12)
    assert rep["exponent_se"] == pytest.approx(one["exponent_se"], rel=SE_RTOL)
    assert rep["coef2_se"] == pytest.approx(one["coef2_se"], rel=SE_RTOL)
    p = rep["count"] / rep["n"]
    naive_beta = rep["exponent"] / math.sqrt(rep["count"])
    naive_coef = math.sqrt(p * (1 - p) / rep["n"]) / 0.1 ** 2
    assert rep["exponent_se"] / naive_beta == pytest.approx(3.0, rel=SE_RTOL)
    assert rep["coef2_se"] / naive_coef == pytest.approx(3.0, rel=SE_RTOL)


def test_no_error_from_one_batch_holding_the_small_samples():
    """Where one batch holds every sample below x0, the batch-means errors are undefined
    (NaN), not 0: the ratio estimator's residual then vanishes by construction.  From two such
    batches on they are finite and positive; the estimates themselves are unchanged."""
    x = np.full(1000, 0.5)
    x[10:13] = [0.01, 0.02, 0.05]                     # all in the first of 10 batches
    one = small_value_law(x, 0.1, n_batches=10)
    assert one["count"] == 3 and one["exponent"] == pytest.approx(3 / np.log(0.1 / x[10:13]).sum())
    assert math.isnan(one["exponent_se"]) and math.isnan(one["coef2_se"])
    x[510] = 0.03                                      # a second batch holds one
    two = small_value_law(x, 0.1, n_batches=10)
    assert two["exponent_se"] > 0 and two["coef2_se"] > 0
    pooled = pool_small_value_laws([one, two])         # an unknown part: an unknown whole
    assert math.isnan(pooled["exponent_se"]) and math.isnan(pooled["coef2_se"])


def test_pooled_laws_equal_the_law_of_the_whole_sample():
    rng = np.random.default_rng(11)
    x = _law_samples(rng, 4.0, 2.0, 90_000)
    whole = small_value_law(x, 0.1, n_batches=30)
    parts = [small_value_law(p, 0.1, n_batches=10) for p in np.split(x, 3)]
    pooled = pool_small_value_laws(parts)
    assert pooled["count"] == whole["count"] and pooled["n"] == whole["n"]
    assert pooled["exponent"] == pytest.approx(whole["exponent"], rel=1e-12)
    assert pooled["coef2"] == pytest.approx(whole["coef2"], rel=1e-12)
    assert pooled["exponent_se"] == pytest.approx(whole["exponent_se"], rel=SE_RTOL)
    assert pooled["coef2_se"] == pytest.approx(whole["coef2_se"], rel=SE_RTOL)
    # a part without samples below x0 adds samples but no count
    empty = small_value_law(np.full(1000, 0.5), 0.1, n_batches=10)
    assert empty["count"] == 0 and math.isnan(empty["exponent"])
    more = pool_small_value_laws(parts + [empty])
    assert more["n"] == whole["n"] + 1000 and more["exponent"] == pooled["exponent"]
    assert math.isnan(empty["coef2_se"])                # no sample: its own error undefined,
    assert more["exponent_se"] == pooled["exponent_se"]  # but it adds no spread to the pool
    assert more["coef2_se"] == pytest.approx(pooled["coef2_se"] * whole["n"] / more["n"],
                                             rel=1e-12)
    with pytest.raises(ValueError, match="share one x0"):
        pool_small_value_laws([whole, small_value_law(x, 0.05, 10)])


@pytest.mark.parametrize("bad, match", [
    (dict(samples=[]), "non-empty 1-D"),
    (dict(samples=[0.1, -0.2]), "> 0"),
    (dict(samples=[0.1, np.nan]), "finite"),
    (dict(x0=0.0), "x0 must be"),
    (dict(n_batches=0), "n_batches"),
    (dict(n_batches=2.0), "n_batches"),
])
def test_small_value_law_refuses_bad_input(bad, match):
    kw = dict(samples=np.linspace(0.01, 1, 50), x0=0.1, n_batches=5) | bad
    with pytest.raises(ValueError, match=match):
        small_value_law(**kw)


def test_block_minima_against_the_closed_form_of_the_quadratic_law():
    rng = np.random.default_rng(5)
    A = 4.0
    x = _law_samples(rng, A, 2.0, (4, 100_000))
    for b in block_minima(x, [1, 10, 100, 1000]):
        s = b["size"]
        exact = math.exp(gammaln(s + 1) - gammaln(s + 1.5)) * math.sqrt(math.pi) / (2 * math.sqrt(A))
        assert b["blocks"] == 4 * (100_000 // s)
        assert abs(b["mean"] - exact) < SIGMAS * b["se"], (s, b, exact)
    # rows are independent series: no block straddles two of them
    two = np.vstack([np.full(5, 1.0), np.full(5, 2.0)])
    assert block_minima(two, [5])[0]["mean"] == 1.5
    assert block_minima(two[0], [2])[0]["blocks"] == 2
    with pytest.raises(ValueError, match="sizes"):
        block_minima(two, [6])


def test_angle_statistics_report_the_law_and_the_sweep_reads_it():
    rng = np.random.default_rng(2)
    phi = _law_samples(rng, 4.0, 2.0, 20_000)
    st = angle_statistics(phi)
    law = small_value_law(phi, st["small"], n_batches=10)
    assert {f"law_{k}": law[k] for k in LAW_KEYS} == {k: st[k] for k in st if k.startswith("law_")}
    zero = angle_statistics(np.array([0.0, 0.3, 0.2]))
    assert all(zero[f"law_{k}"] is None for k in LAW_KEYS)
    one = angle_statistics(np.array([1.0]))
    assert one["law_count"] == 0 and one["law_exponent"] is None and one["law_coef2"] == 0.0
    # an undefined statistic is an empty cell in the sweep table, not a failed point
    res = {"results": {"angles": {"restricted": zero}}}
    got = result_statistics(res, None)
    assert got["phi_restricted_law_exponent"] is None and got["phi_restricted_min"] == 0.0
    assert got["phi_restricted_n"] == 3


def test_ensembles_keep_the_weights_and_the_level():
    """Every member of an ensemble runs the family member asked for (the same numbers as
    the direct call on the same random state), not the paper's manifold."""
    from charts import RotorSystem, lyapunov_ensemble, lyapunov_spectrum

    s = RotorSystem(4, weights=[1, 1, 1, 2], level=0.5)
    e = lyapunov_ensemble(s, 2, 5.0, seed=3, workers=1)
    assert e.params["weights"] == [1.0, 1.0, 1.0, 2.0] and e.params["level"] == 0.5
    for i, m in enumerate(e.members):
        assert m.params["weights"] == [1.0, 1.0, 1.0, 2.0] and m.params["level"] == 0.5
        direct = lyapunov_spectrum(s, *s.random_state(seed=3 + i), 5.0, seed=3 + i)
        assert np.array_equal(m.exponents, direct.exponents)
