"""report.md of ``charts reproduce``: the verdict rule (``charts.runs.claim_rule``) on
made-up numbers, and the claims, the section on what a preset cannot show and the report
built from a made-up results.json (``charts.runs.reproduce_claims``,
``charts.runs.reproduce_report``).  The report of a real ``--quick`` run:
tests/test_reproduce.py."""
from __future__ import annotations

import copy
import math

import pytest

from charts.runs.claim_rule import (AGREE, DISAGREE, MIN_BATCHES, VERDICTS, ZERO_COUNT_SIGMA,
                                    fraction_error, paper_rounding_se, verdict)
from charts.runs.reproduce_claims import cannot_show, claims, eq22_bound
from charts.runs.reproduce_report import report_text


# ------------------------------------------------------------------------ the rule
@pytest.mark.parametrize("ours, se, paper, word", [
    (0.3819, 0.0018, 0.385, "confirmed"),         # 1.7 s.e.
    (0.385, 0.001, 0.385, "confirmed"),           # exact
    (0.390, 0.002, 0.385, "inconclusive"),        # 2.5 s.e.
    (0.3792, 0.002, 0.385, "inconclusive"),       # −2.9 s.e.: not beyond 3
    (0.395, 0.002, 0.385, "not confirmed"),       # 5 s.e.
    (0.375, 0.002, 0.385, "not confirmed"),       # −5 s.e.
])
def test_a_claimed_value_is_confirmed_within_two_and_refuted_beyond_three(ours, se, paper, word):
    v = verdict(ours, se, paper, relation="=", batches=40)
    assert v["verdict"] == word
    assert v["z"] == pytest.approx((ours - paper) / se)
    assert f"{abs(v['z']):.1f}" in v["reason"]


def test_the_papers_rounding_widens_the_error():
    """0.3835 vs 0.385 with s.e. 0.0005: 3 s.e. alone, but the paper's ± 0.0005 rounding
    (uniform: 0.00029) makes it 2.6 combined: inconclusive instead of not confirmed."""
    se_paper = paper_rounding_se(3)
    assert se_paper == pytest.approx(0.0005 / math.sqrt(3))
    assert verdict(0.3834, 0.0005, 0.385, relation="=")["verdict"] == "not confirmed"
    v = verdict(0.3834, 0.0005, 0.385, se_paper, relation="=")
    assert v["verdict"] == "inconclusive"
    assert v["z"] == pytest.approx(-0.0016 / math.hypot(0.0005, se_paper))


@pytest.mark.parametrize("ours, se, relation, word", [
    (0.12, 0.002, ">", "confirmed"),              # 60 s.e. above 0
    (0.003, 0.002, ">", "inconclusive"),          # 1.5 s.e. above: not distinguished
    (-0.003, 0.002, ">", "inconclusive"),         # 1.5 s.e. below: not refuted
    (-0.01, 0.002, ">", "not confirmed"),         # 5 s.e. below
    (2.8e-5, 1e-6, "<", "confirmed"),             # below a bound of 0 by 28 s.e.
    (6e-5, 1e-6, "<", "not confirmed"),
])
def test_a_claimed_bound_needs_two_on_its_side_and_is_refuted_beyond_three(ours, se, relation,
                                                                         word):
    bound = 5e-5 if relation == "<" else 0.0
    assert verdict(ours, se, bound, relation=relation, batches=10)["verdict"] == word


def test_too_few_samples_is_inconclusive_whatever_the_difference():
    for se in (None, math.nan):
        v = verdict(0.9, se, 0.0, relation=">")
        assert v["verdict"] == "inconclusive" and v["z"] is None
        assert "too few samples" in v["reason"]
    v = verdict(0.5, 0.001, 0.0, relation=">", batches=MIN_BATCHES - 1)
    assert v["verdict"] == "inconclusive" and str(MIN_BATCHES - 1) in v["reason"]
    assert verdict(0.5, 0.001, 0.0, relation=">", batches=MIN_BATCHES)["verdict"] == "confirmed"
    with pytest.raises(ValueError, match="relation"):
        verdict(1.0, 0.1, 1.0, relation="~")


def test_the_thresholds_and_the_words():
    assert (AGREE, DISAGREE) == (2.0, 3.0) and VERDICTS == ("confirmed", "not confirmed",
                                                           "inconclusive")
    # exactly on the thresholds: 2 is still agreement, 3 not yet a contradiction
    assert verdict(2.0, 1.0, 0.0)["verdict"] == "confirmed"
    assert verdict(3.0, 1.0, 0.0)["verdict"] == "inconclusive"
    assert verdict(3.0001, 1.0, 0.0)["verdict"] == "not confirmed"


def test_the_error_of_a_counted_fraction():
    assert fraction_error(0, 40000, None) == pytest.approx(ZERO_COUNT_SIGMA / 40000)
    assert fraction_error(2, 40000, None) is None            # counts in fewer than 2 batches
    assert fraction_error(500, 40000, 0.003) == 0.003
    # no count: the claim "fraction 0" is confirmed, "fraction > 0" inconclusive, never refuted
    se = fraction_error(0, 40000, None)
    assert verdict(0.0, se, 0.0, relation="=")["verdict"] == "confirmed"
    assert verdict(0.0, se, 0.0, relation=">")["verdict"] == "inconclusive"


# ------------------------------------------------------------------------ made-up results.json
def _angles(frac, k, n=40000, law_se=None, beta=None, beta_se=None, smallest=0.3):
    return dict(min=smallest, frac_small=frac, p001=2 * smallest, p01=3 * smallest, median=0.5,
                n=n, small=0.05, law_count=k, law_exponent=beta, law_exponent_se=beta_se,
                law_coef2=frac / 0.05 ** 2, law_coef2_se=law_se)


def _curv(n, fractions, counts, ses, gap_K, gap, samples=10000):
    c = dict(max_ab=gap, median_rel_ab=1.5e-5, fraction_positive=fractions, samples=samples,
             fraction_positive_se=ses, positive_count=counts, batches=10,
             route_gap=dict(max_abs=gap, direction=1, sample=7, K_exact=gap_K,
                            K_numerical=gap_K + gap, abs_K_p999=9.0, abs_K_max=abs(gap_K),
                            per_dt2_K2=gap / (0.01 * gap_K) ** 2, dt=0.01))
    if n == 3:
        c.update(eq22_median_rel=2.8e-5, eq22_max_abs=3.6e-5, eq22_median_rel_se=8e-7)
    return c


@pytest.fixture
def results():
    """A results.json as ``charts reproduce --quick`` writes it, every number made up."""
    seeds = lambda s: {str(n): s for n in (3, 4, 5)}            # noqa: E731
    clv = {str(n): {"restricted": {"exponents": [0.4] * (n - 2) + [0.001, -0.001]
                                   + [-0.4] * (n - 2)}} for n in (3, 4, 5)}
    return dict(
        preset="quick", elapsed_s=12.0, workers=2,
        config=dict(lyap_members=4, lyap_t=5000.0, lyap_batches=10, angle_members=2,
                    angle_t=2000.0, curv_t=1000.0, wave_t=4000.0, angle_transient=200.0),
        run=dict(lyapunov=dict(members=4, t_final=5000.0, dt=0.01, t_transient=50.0, batches=10,
                               seeds=seeds([100, 101, 102, 103])),
                 angles=dict(members=2, t_final=2000.0, dt=0.01, t_transient=200.0,
                             sample_every=0.1, seeds=seeds([200, 201])),
                 curvature=dict(members=1, t_final=1000.0, dt=0.01, t_transient=50.0,
                                sample_every=0.1, batches=10, seeds=seeds([300])),
                 waveform=dict(members=1, t_final=4000.0, dt=0.01, sample_every=0.05,
                               seeds=seeds([400]))),
        lyapunov={"3": dict(exponents=[0.5006], stderr=[0.0016], paper=[0.5]),
                  "4": dict(exponents=[0.3819, 0.2299], stderr=[0.0018, 0.0016],
                            paper=[0.385, 0.23]),
                  "5": dict(exponents=[0.2952, 0.2233, 0.1227], stderr=[0.0018, 0.0025, 0.0019],
                            paper=[0.298, 0.227, 0.121])},
        curvature={"3": _curv(3, [0.0], [0], [None], -0.97, 3.6e-5),
                   "4": _curv(4, [0.05, 0.11], [500, 1100], [0.007, 0.01], -74.0, 0.15),
                   "5": _curv(5, [0.13, 0.21, 0.30], [1300, 2100, 3000], [0.016, 0.018, 0.014],
                              0.128, 0.014)},
        angles={"3": dict(full=_angles(0.0, 0, smallest=0.27),
                          restricted=_angles(0.0, 0, smallest=0.59)),
                "4": dict(full=_angles(0.34, 13600, law_se=17.4, beta=0.75, beta_se=0.08,
                                       smallest=2e-4),
                          restricted=_angles(5e-5, 2, beta=6.7, smallest=0.04)),
                "5": dict(full=_angles(0.336, 13441, law_se=13.8, beta=1.1, beta_se=0.14,
                                       smallest=2.8e-4),
                          restricted=_angles(0.098, 3928, law_se=6.2, beta=1.14, beta_se=0.27,
                                             smallest=7.6e-4))},
        clv=clv)


def test_every_claim_has_its_number_error_sample_size_and_verdict(results):
    rows = claims(results)
    # 6 exponents, 3 counts of positive exponents, eq (22), N = 3's sign, 5 fractions K > 0,
    # 6 angle fractions
    assert len(rows) == 6 + 3 + 1 + 1 + 5 + 6
    for r in rows:
        assert r["verdict"] in VERDICTS and r["reason"]
        assert r["where"].startswith(("§", "abstract")) and r["paper"]
        assert "±" in r["ours"] or " of " in r["ours"] or "no s.e." in r["ours"], r
        assert "samples" in r["n"] or "batch means" in r["n"], r
    by = {r["claim"]: r for r in rows}
    assert by["N = 4: λ1"]["verdict"] == "confirmed" and by["N = 4: λ1"]["paper"] == "0.385"
    assert by["N = 3: route (a) = eq (22) to 5 significant digits (median relative "
              "difference)"]["paper"].startswith(f"< {eq22_bound():.0e}")
    restricted4 = by["N = 4 (restricted): angles near 0 occur (fraction φ < 0.05 rad)"]
    assert restricted4["verdict"] == "inconclusive" and "2 samples below" in restricted4["reason"]
    assert by["N = 3 (restricted): no angle near 0 (fraction φ < 0.05 rad)"]["verdict"] == \
        "confirmed"


def test_a_changed_number_changes_its_verdict(results):
    """Nothing is written in: move our N = 5 λ2 6 s.e. off the paper's and it is refuted."""
    r = copy.deepcopy(results)
    r["lyapunov"]["5"]["exponents"][1] = 0.227 + 6 * 0.0025
    by = {c["claim"]: c for c in claims(r)}
    assert by["N = 5: λ2"]["verdict"] == "not confirmed"
    r["curvature"]["4"]["positive_count"][0] = 0
    r["curvature"]["4"]["fraction_positive"][0] = 0.0
    assert {c["claim"]: c for c in claims(r)}[
        "N = 4: K_11 > 0 occurs (fraction K > 0)"]["verdict"] == "inconclusive"


def test_what_the_preset_cannot_show_comes_from_its_numbers(results):
    text = "\n".join(cannot_show(results))
    # the exponents' errors (0.0016–0.0025) against the paper's ± 0.0005: 25× longer runs
    assert "0.0016–0.0025" in text and "25×" in text
    # N = 4's restricted tangencies: 2 of 40000 below 0.05 rad, 50× this preset's length
    assert "N = 4's tangencies in the restricted variant" in text
    assert "2 of 40000" in text and "50×" in text and "15× closer than N = 3's" in text
    assert "N = 5 restricted" in text             # resolved: β̂ ± s.e.
    # with 1000 angles below x₀ in several batches, N = 4 restricted is resolved too
    r = copy.deepcopy(results)
    r["angles"]["4"]["restricted"].update(law_count=1000, frac_small=0.025, law_coef2_se=2.0,
                                          law_exponent=1.0, law_exponent_se=0.1)
    assert "N = 4's tangencies" not in "\n".join(cannot_show(r))


def test_the_report_states_the_rule_once_and_each_claim_in_a_row(results):
    text = report_text(results, "| N | k |", ["## Hyperbolicity by a second route", ""],
                       "charts reproduce --quick -o out")
    for section in ("## The paper's claims and our verdicts", "## Run lengths, samples and seeds",
                    "## What this preset cannot show", "## Curvature", "The two curvature routes",
                    "## Hyperbolicity by a second route"):
        assert section in text
    assert text.count("**The rule**") == 1
    rows = [line for line in text.splitlines() if line.startswith("| ") and "**" in line
            and any(f"**{w}**" in line for w in VERDICTS)]
    assert len(rows) == len(claims(results))
    for line in rows:            # seven cells: a '|' inside a cell is escaped
        assert len([c for c in line.replace("\\|", "").split("|")[1:-1]]) == 7, line
    # the N = 4 route gap: the largest |K| of the run, of order Δt²K²
    assert "N = 4: 0.15 (relative 2.0e-03) at |K| = 74, above 99.9 % of the run (the run's " \
           "largest)" in text
    assert "100, 101, 102, 103 (each N)" in text and "200 forward and 200 backward" in text


def test_the_report_says_how_much_of_its_wall_time_was_compiling(results):
    """The wall time names the compiling share recorded in results.json (compile_wall_s),
    says that none was compiled when the kernels came from the cache, and nothing for a
    results.json written before the share was recorded."""
    head = lambda r: report_text(r, "| N | k |", [], "c").splitlines()[2]   # noqa: E731
    assert "wall time 12 s on 2 worker" in head(results)
    assert "wall time 12 s (9 s of it compiling the kernels, once: a run on the filled " \
           "cache does without) on 2 worker" in head(dict(results, compile_wall_s=9.2,
                                                          compile_summed_s=14.0))
    for loaded in (dict(compile_wall_s=0.8, compile_summed_s=0.0), dict(compile_wall_s=0.0)):
        assert "wall time 12 s (the kernels loaded from numba's cache, none compiled) on 2" \
               in head(dict(results, **loaded))
