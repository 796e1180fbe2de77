"""``charts verdict --triple-linkage``: the triple linkage's verdict at each rim radius r from its
measured χ, curvature and λ₁ — never "hyperbolic" at a finite r, since no theorem is certified
there — on the console, in the table and in the JSON; bad r refused before any work."""
import json

import numpy as np
import pytest

import charts.runs.verdict as verdict
import charts.runs.verdict_linkage as verdict_linkage
from charts.cli.main import main
from charts.geometry.topology import euler_characteristic

#: Cheap settings: 48² nodes per chart meet Gauss–Bonnet to ~3e-5 (in units of 2π) at r ≤ 0.2,
#: far inside CHI_TOLERANCE; a short λ₁ run (its ±3 s.e. still excludes 0 by far).
FAST = ["--grid", "48", "--t-final", "300", "--seeds", "1"]


def _report(chi=-4, totals=None, kmax=(4.8e-3, 4.8e-3), share=0.013, exponents=((0.50, 0.01),),
            level=0.0, limit_chi=-4):
    """A minimal `linkage_verdict` report for `case_verdict`: two routes reading ``chi`` from
    ``totals`` (∫K dA / 2π per route), the largest K per route, λ₁ ± s.e. per seed."""
    totals = totals or (chi + 1e-7, chi + 1e-7)
    routes = {route: dict(euler_characteristic=int(round(t)), total_curvature=2 * np.pi * t,
                          max_curvature=k, positive_area=share)
              for route, t, k in zip(("chart", "gauss"), totals, kmax)}
    return dict(system=dict(kind="triple_linkage", r=0.2, l=1.0, R=1.0), n_grid=48,
                routes=routes, limit=dict(level=level, euler_characteristic=limit_chi),
                exponents=[dict(lambda1=lam, stderr=se, t_final=300.0) for lam, se in exponents])


@pytest.mark.parametrize("kwargs, expected", [
    (dict(), ("open", "statistics")),                                # K > 0 somewhere, λ₁ > 0
    (dict(exponents=()), ("open", "no proof")),                      # nothing sampled
    (dict(exponents=((0.01, 0.01),)), ("open", "no proof")),         # λ₁ not resolved above 0
    (dict(kmax=(-1e-9, -1e-9), share=0.0), ("open", "statistics")),  # K <= 0 at the nodes only
    (dict(chi=2, kmax=(1.8, 1.8), share=1.0, level=1.5, limit_chi=2),
     ("not hyperbolic", "theorem")),                                 # a sphere (δ = 0.5)
    (dict(chi=0), ("open", "no proof")),                             # components unknown
    (dict(totals=(-3.96, -3.96)), ("open", "no proof")),             # quadrature unsettled
    (dict(totals=(-4.0, -2.0)), ("open", "no proof")),               # the routes disagree
])
def test_the_linkage_verdict_follows_the_measured_surface(kwargs, expected):
    v = verdict.case_verdict(_report(**kwargs))
    assert (v["verdict"], v["evidence"]) == expected
    assert v["verdict"] in verdict.VERDICTS and v["evidence"] in verdict.EVIDENCE
    assert v["reason"] and "\n" not in v["reason"]


@pytest.mark.parametrize("kmax", [(4.8e-3, 4.8e-3), (-1e-9, -1e-9), (-1e-9, 1e-6)])
@pytest.mark.parametrize("exponents", [(), ((0.5, 0.002), (0.49, 0.002))])
def test_a_finite_r_is_never_hyperbolic(kmax, exponents):
    """However negative the measured curvature and however clear λ₁ > 0: no certificate at a
    finite r, so never "hyperbolic"; the reason says why Hunt–MacKay's theorem does not
    transfer, and that K > 0 (when measured) rules out the curvature theorems."""
    v = verdict.case_verdict(_report(kmax=kmax, exponents=exponents))
    assert v["verdict"] == "open"
    assert "certifies no given r" in v["reason"] and "structural stability" in v["reason"]
    if max(kmax) > 0:
        assert "K > 0 on 1.3 % of the area" in v["reason"]
        assert "Anosov's theorem (K < 0)" in v["reason"]
    else:
        assert "nodes prove no sign" in v["reason"]
    if exponents:
        assert v["evidence"] == "statistics" and "do not prove" in v["reason"]


def test_sampled_angles_alone_are_statistics():
    rep = _report(exponents=())
    rep["angles"] = [dict(min=0.535, n=10000), dict(min=0.61, n=10000)]
    v = verdict.case_verdict(rep)
    assert (v["verdict"], v["evidence"]) == ("open", "statistics")
    assert "the smallest restricted angle is 0.535 rad in 20000 samples" in v["reason"]


def test_the_rotors_positive_curvature_with_a_resolved_exponent_is_statistics():
    """The same rule on the rotors' N = 3 members with K > 0 proved on a box: λ₁ resolved
    above 0 is "statistics", without it "no proof"; "open" either way."""
    rep = dict(routes=dict(chart=dict(euler_characteristic=-4)),
               certificate=dict(verdict="positive somewhere", zeros=[], charts=[{}],
                                open_boxes=0))
    assert verdict.case_verdict(rep)["evidence"] == "no proof"
    rep["exponents"] = [dict(lambda1=0.50, stderr=0.004, t_final=3000.0)]
    v = verdict.case_verdict(rep)
    assert (v["verdict"], v["evidence"]) == ("open", "statistics")


def test_the_linkage_report_on_the_console_and_in_the_json(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["verdict", "--triple-linkage", "0.2", *FAST, "--angles", "20",
                 "--json", str(out)]) == 0
    captured = capsys.readouterr()
    assert "charts: triple linkage r = 0.2 (1 of 1): surface integrals" in captured.err
    [line] = [x for x in captured.out.splitlines() if x.startswith("verdict: ")]
    assert line.startswith("verdict: open; evidence: statistics; why: chi = -4")
    assert "| 0.2 | 1 | -4 |" in captured.out and "rad | open | statistics |" in captured.out
    [rep] = json.loads(out.read_text())
    assert rep["system"] == dict(kind="triple_linkage", name="triple_linkage(r=0.2, l=1, R=1)",
                                 r=0.2, l=1.0, R=1.0, inertia=1.0, joint_mass=0.0,
                                 rod_mass=0.0, delta=0.0)
    assert (rep["verdict"], rep["evidence"]) == ("open", "statistics")
    assert rep["reason"] in line
    assert set(rep["routes"]) == {"chart", "gauss"}
    for r in rep["routes"].values():
        # Gauss–Bonnet against the limit's Morse count (an independent route to χ: the
        # linkage at r = 0.2 is a regular deformation of the rotor surface); 48² nodes meet
        # it to ~3e-5 of 2π (docs/triple-linkage.md's convergence), 1e-3 leaves margin
        assert r["euler_characteristic"] == euler_characteristic((1, 1, 1), 0.0) == -4
        assert abs(r["total_curvature"] / (2 * np.pi) + 4) < 1e-3
        # K > 0 near the limit's zeros: 4.9e-3 at r = 0.2 on 192² (docs/triple-linkage.md);
        # the nodes of 48² see at most the refined maximum, and more than a tenth of it
        assert 4.9e-4 < r["max_curvature"] <= 4.9e-3 and r["positive_area"] > 0
        assert -1.0 < r["min_curvature"] < -0.9      # −0.977 refined; K ≥ −1 in the limit
    assert rep["limit"]["euler_characteristic"] == -4 and rep["limit"]["level"] == 0.0
    [e] = rep["exponents"]
    # λ₁ > 0 and below Katok's bound √(2π|χ|/A) (a theorem for χ < 0), by 3 s.e. each
    assert e["lambda1"] - 3 * e["stderr"] > 0 and e["consistent"]
    [a] = rep["angles"]
    # 20 time units sampled every 0.1; an angle between subspaces lies in (0, π/2]
    assert a["n"] == 200 and 0 < a["min"] <= a["median"] <= np.pi / 2 and a["seed"] == 1
    assert "smallest restricted angle" in rep["reason"]
    assert rep["bracket"][0] is None                 # no lower bound where K > 0 somewhere
    assert rep["bracket"][1] == pytest.approx(np.sqrt(8 * np.pi / rep["routes"]["chart"]["area"]))


def test_a_sphere_is_not_hyperbolic():
    """l = R + rδ with δ = 0.5: the surface is a sphere, as the limit Σ cos θ = 1.5 (Morse
    count 2); ∫K dA / 2π read as 2 by both routes."""
    rep = verdict_linkage.linkage_verdict(0.1, l=1.05, n_grid=48, seeds=())
    assert (rep["verdict"], rep["evidence"]) == ("not hyperbolic", "theorem")
    assert rep["limit"]["euler_characteristic"] == euler_characteristic((1, 1, 1), 1.5) == 2
    assert all(r["euler_characteristic"] == 2 for r in rep["routes"].values())
    assert verdict.verdict_passed(rep)


@pytest.mark.parametrize("argv, message", [
    (["--triple-linkage", "0"], "a rim radius must be a finite number r > 0"),
    (["--triple-linkage", "-0.1"], "a rim radius must be a finite number r > 0"),
    (["--triple-linkage", "nan"], "a rim radius must be a finite number r > 0"),
    (["--triple-linkage", "0.1,abc"], "numbers r > 0 separated by commas"),
    (["--triple-linkage", "0.1", "--rod-length", "0.5"],
     "--triple-linkage 0.1: the triple linkage does not assemble at r = 0.1, l = 0.5"),
    (["--triple-linkage", "0.1,1"], "--triple-linkage 1: the triple linkage is singular"),
    (["--triple-linkage", "0.1", "--rod-length", "-1"], "--rod-length must be"),
    (["--triple-linkage", "0.1", "--t-final", "0"], "--t-final must be positive"),
    (["--triple-linkage", "0.1", "--t-final", "0.015"], "not a whole number of steps"),
    (["--triple-linkage", "0.1", "--grid", "5"], "--grid must be an integer in 8..4096"),
    (["--rod-length", "1.1"], "give --triple-linkage"),
    (["--n", "3", "--angles", "100"], "give --triple-linkage"),
    (["--triple-linkage", "0.1", "--angles", "-5"], "--angles must be positive"),
    (["--triple-linkage", "0.1", "--statistics"], "leave out --triple-linkage"),
])
def test_bad_input_is_refused_before_any_work(argv, message, capsys):
    assert main(["verdict", *argv]) == 2
    captured = capsys.readouterr()
    assert message in captured.err and "Traceback" not in captured.err
    assert "verdict:" not in captured.out            # refused before the first report
