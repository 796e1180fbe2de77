"""``charts verdict`` states one verdict per case — "hyperbolic (Anosov)", "not hyperbolic" or
"open" — with the class of its evidence and why, on the console and in the JSON, derived from
the certificates' outcomes (a certificate made to fail gives "open")."""
import json

import pytest

import charts.runs.verdict as verdict
from charts.analyses.curvature_certificate import CurvatureCertificate
from charts.analyses.flat_tori import FlatTorusCertificate
from charts.cli.main import main

#: The cheap settings of the N = 3 report (the verdict does not depend on them).
FAST3 = ["--grid", "128", "--t-final", "400", "--seeds", "3"]


def _lines(text):
    return [line for line in text.splitlines() if line.startswith("verdict: ")]


def test_n3_is_hyperbolic_by_a_theorem_with_certificate(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["verdict", "--n", "3", *FAST3, "--json", str(out)]) == 0
    [line] = _lines(capsys.readouterr().out)
    assert line.startswith("verdict: hyperbolic (Anosov); evidence: theorem with certificate; "
                           "why: ")
    assert "8 isolated points" in line and "Eberlein" in line
    [rep] = json.loads(out.read_text())
    assert rep["verdict"] == "hyperbolic (Anosov)"
    assert rep["evidence"] == "theorem with certificate"
    assert rep["reason"] and rep["reason"] in line


def test_n4_is_not_hyperbolic_by_the_flat_torus(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["verdict", "--n", "4", "--json", str(out)]) == 0
    [line] = _lines(capsys.readouterr().out)
    assert line.startswith("verdict: not hyperbolic; evidence: theorem; why: ")
    assert "closed geodesic" in line and "not hyperbolic" in line
    assert "Eberlein" not in line          # its hypotheses fail here (cone points at even N)
    [rep] = json.loads(out.read_text())
    assert (rep["verdict"], rep["evidence"]) == ("not hyperbolic", "theorem")


def test_an_undecided_certificate_gives_open(tmp_path, capsys, monkeypatch):
    def undecided(system, **kwargs):
        return CurvatureCertificate("undecided", [], [], "(test)", None, 7, 0.0, {})
    monkeypatch.setattr(verdict, "certify_curvature_sign", undecided)
    out = tmp_path / "v.json"
    assert main(["verdict", "--n", "3", *FAST3, "--json", str(out)]) == 1
    [line] = _lines(capsys.readouterr().out)
    assert line.startswith("verdict: open; evidence: no proof; why: ")
    assert "undecided (7 boxes left open)" in line
    [rep] = json.loads(out.read_text())
    assert rep["verdict"] == "open" and "undecided" in rep["reason"]


def test_a_failed_torus_proof_gives_open(capsys, monkeypatch):
    def failed(system, **kwargs):
        return FlatTorusCertificate("proof failed", [[0, 1], [2, 3]], [], 2,
                                    [dict(statement="flat (test)", holds=False)], None, None, {})
    monkeypatch.setattr(verdict, "certify_flat_torus", failed)
    assert main(["verdict", "--n", "4"]) == 1
    [line] = _lines(capsys.readouterr().out)
    assert line.startswith("verdict: open; evidence: no proof; why: a step of the flat-torus "
                           "proof failed (flat (test))")


def test_no_torus_or_one_pair_leaves_n4_open(capsys):
    assert main(["verdict", "--n", "4", "--masses", "1", "2", "3", "4"]) == 0
    [line] = _lines(capsys.readouterr().out)
    assert line.startswith("verdict: open; evidence: no proof; why: there is no flat torus")


def _surface(chi, outcome, zeros=0, open_boxes=0):
    """A minimal report of `surface_verdict` for `case_verdict`."""
    return dict(routes=dict(chart=dict(euler_characteristic=chi)),
                certificate=dict(verdict=outcome, zeros=[{}] * zeros, charts=[{}],
                                 open_boxes=open_boxes))


@pytest.mark.parametrize("chi, outcome, zeros, expected", [
    (-4, "nonpositive", 8, ("hyperbolic (Anosov)", "theorem with certificate")),
    (-4, "nonpositive", 0, ("hyperbolic (Anosov)", "theorem with certificate")),   # K < 0
    (-4, "positive somewhere", 0, ("open", "no proof")),
    (-4, "undecided", 0, ("open", "no proof")),
    (0, "positive somewhere", 0, ("not hyperbolic", "theorem with certificate")),   # two tori
    (0, "undecided", 0, ("open", "no proof")),
    (2, "positive somewhere", 0, ("not hyperbolic", "theorem")),                    # a sphere
    (2, "undecided", 0, ("not hyperbolic", "theorem")),     # chi > 0 decides without it
    (0, "nonpositive", 8, ("open", "no proof")),            # inconsistent: said so
])
def test_the_surface_verdict_follows_chi_and_the_certificate(chi, outcome, zeros, expected):
    v = verdict.case_verdict(_surface(chi, outcome, zeros))
    assert (v["verdict"], v["evidence"]) == expected
    assert v["verdict"] in verdict.VERDICTS and v["evidence"] in verdict.EVIDENCE
    assert v["reason"] and "\n" not in v["reason"]


def test_statistics_alone_give_open():
    rep = dict(statistics=dict(restricted=dict(min=0.588, n=1e9)))
    v = verdict.case_verdict(rep)
    assert (v["verdict"], v["evidence"]) == ("open", "statistics")
    assert "0.588 rad in 1e+09 samples" in v["reason"]
