"""``charts verdict --mechanism``: the verdict of a 2-dimensional mechanism of one's own from
its measured χ (Gauss–Bonnet on Newton's sheets), curvature and λ₁ — "not hyperbolic" where χ > 0,
"open" otherwise, never "hyperbolic" — on the console and in the JSON; a mechanism that does
not resolve, or is not a regular surface, refused before any work."""
import json

import numpy as np
import pytest

import charts
import charts.runs.verdict as verdict
import charts.runs.verdict_linkage as verdict_linkage
import charts.runs.verdict_mechanism as verdict_mechanism
from charts.cli.main import main
from charts.geometry.topology import euler_characteristic
from verdict_mechanism_factory import sphere

#: Cheap settings: 48² nodes per chart meet Gauss–Bonnet to ~4e-5 (in units of 2π) on the arm
#: and ~1.5e-5 on the sphere of angles, far inside CHI_TOLERANCE; a short λ₁ run.
FAST = ["--grid", "48", "--t-final", "300", "--seeds", "1"]
ARM = "verdict_mechanism_factory:arm"


def test_the_arm_on_the_console_and_in_the_json(tmp_path, capsys):
    out = tmp_path / "v.json"
    assert main(["verdict", "--mechanism", ARM, *FAST, "--angles", "20",
                 "--json", str(out)]) == 0
    captured = capsys.readouterr()
    assert "charts: mechanism arm on a rail: surface integrals on 48^2" in captured.err
    [line] = [x for x in captured.out.splitlines() if x.startswith("verdict: ")]
    assert line.startswith("verdict: open; evidence: statistics; why: chi = -4")
    [rep] = json.loads(out.read_text())
    assert rep["system"] == dict(kind="mechanism", name="arm on a rail", mechanism=ARM,
                                 parameters=dict(l1=1.0, l2=0.8, l3=0.6, m1=1.0, m2=1.0,
                                                 m3=0.5),
                                 coordinates=["theta1", "theta2", "theta3"], dimension=2)
    assert (rep["verdict"], rep["evidence"]) == ("open", "statistics") and rep["reason"] in line
    assert "no certificate of the sign of K exists for a general mechanism" in rep["reason"]
    assert set(rep["routes"]) == {"chart"}          # a configuration-dependent metric
    c = rep["routes"]["chart"]
    # χ against the Morse count of Σ lᵢ sin θᵢ = 0 (an independent route: the same surface
    # as Σ lᵢ cos θᵢ = 0 by θᵢ → θᵢ − π/2); 48² nodes meet it to ~4e-5, 1e-3 leaves margin
    assert c["euler_characteristic"] == euler_characteristic((1.0, 0.8, 0.6), 0.0) == -4
    assert abs(c["total_curvature"] / (2 * np.pi) + 4) < verdict.CHI_TOLERANCE
    # K > 0 on part of the arm's surface (15 % along one path: docs/mechanisms.md)
    assert c["min_curvature"] < 0 < c["max_curvature"] and 0 < c["positive_area"] < 1
    assert rep["bracket"][0] is None                 # no lower bound where K > 0 somewhere
    assert rep["bracket"][1] == pytest.approx(np.sqrt(8 * np.pi / c["area"]))
    [e] = rep["exponents"]
    assert e["lambda1"] - 3 * e["stderr"] > 0 and e["consistent"]
    [a] = rep["angles"]
    # 20 time units sampled every 0.1; an angle between subspaces lies in (0, π/2]
    assert a["n"] == 200 and 0 < a["min"] <= a["median"] <= np.pi / 2
    assert verdict.verdict_passed(rep)


def test_a_sphere_of_angles_is_not_hyperbolic():
    """cos θ₁ + cos θ₂ + cos θ₃ = 1.5 written by hand (Newton's sheets, the generic jets): a
    sphere; χ = 2 by both routes as by the Morse count, and the area equals the rotors' own
    quadrature of the same surface (closed-form sheets, their curvature formulas)."""
    rep = verdict_mechanism.mechanism_verdict(sphere(), n_grid=48, seeds=())
    assert (rep["verdict"], rep["evidence"]) == ("not hyperbolic", "theorem")
    assert "Hopf 1948" in rep["reason"]
    assert set(rep["routes"]) == {"chart", "gauss"}  # a constant metric: both routes
    rotors = charts.surface_integrals(charts.RotorSystem(3, level=1.5), 48)
    for r in rep["routes"].values():
        assert r["euler_characteristic"] == euler_characteristic((1, 1, 1), 1.5) == 2
        # the same nodes and weights by two sheet routes: Newton meets the closed forms to
        # ~1e-10 (docs/mechanisms.md), measured 3e-12 here; 1e-8 relative leaves margin
        assert r["area"] == pytest.approx(rotors.area, rel=1e-8)
        assert r["min_curvature"] > 0 and r["positive_area"] == 1.0
    assert verdict.verdict_passed(rep)


def test_the_triple_linkage_by_name_measures_as_its_own_verdict():
    """``--mechanism triple_linkage r=0.2`` resolves to the linkage of ``--triple-linkage
    0.2``: the same surface measurements; its verdict lacks the linkage's limit only."""
    mech = verdict_mechanism.resolve_mechanism("triple_linkage", ["r=0.2"])
    rep = verdict_mechanism.mechanism_verdict(mech, n_grid=48, seeds=())
    own = verdict_linkage.linkage_verdict(0.2, n_grid=48, seeds=())
    assert rep["routes"] == own["routes"] and "limit" not in rep
    assert (rep["verdict"], rep["evidence"]) == (own["verdict"], own["evidence"]) == \
        ("open", "no proof")
    assert "Hunt and MacKay" in own["reason"] and "Hunt and MacKay" not in rep["reason"]


def test_a_toml_file_names_the_mechanism_as_a_scene_does(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text('[mechanism]\nname = "verdict_mechanism_factory:sphere"\nlevel = 2.0\n')
    mech = verdict_mechanism.resolve_mechanism(str(path))
    assert mech.parameter_values == {"c": 2.0}
    with pytest.raises(ValueError, match="give no KEY=VALUE beside a file"):
        verdict_mechanism.resolve_mechanism(str(path), ["level=2"])


def _report(chi=-2, total=None, kmax=0.5, exponents=((0.4, 0.01),)):
    """A minimal `mechanism_verdict` report for `case_verdict`: one route reading ``chi`` from
    ``total`` (∫K dA / 2π), the largest K, λ₁ ± s.e. per seed."""
    total = chi + 1e-7 if total is None else total
    routes = dict(chart=dict(euler_characteristic=int(round(total)),
                             total_curvature=2 * np.pi * total, max_curvature=kmax,
                             positive_area=0.1 if kmax > 0 else 0.0))
    return dict(system=dict(kind="mechanism", name="m"), n_grid=48, routes=routes,
                exponents=[dict(lambda1=lam, stderr=se, t_final=300.0) for lam, se in exponents])


@pytest.mark.parametrize("kwargs, expected", [
    (dict(), ("open", "statistics")),                        # χ < 0, λ₁ resolved above 0
    (dict(exponents=()), ("open", "no proof")),              # nothing sampled
    (dict(kmax=-1e-9), ("open", "statistics")),              # K <= 0 at the nodes only
    (dict(chi=0), ("open", "statistics")),                   # χ = 0: the same rule as χ < 0
    (dict(chi=0, exponents=((0.01, 0.01),)), ("open", "no proof")),
    (dict(chi=2, kmax=1.0), ("not hyperbolic", "theorem")),  # a sphere: Hopf
    (dict(total=-1.9), ("open", "no proof")),                # the quadrature does not settle χ
])
def test_the_mechanism_verdict_follows_the_measured_surface(kwargs, expected):
    v = verdict.case_verdict(_report(**kwargs))
    assert (v["verdict"], v["evidence"]) == expected
    assert v["reason"] and "\n" not in v["reason"]
    if v["verdict"] == "open" and "does not settle" not in v["reason"]:
        assert "no certificate of the sign of K exists" in v["reason"]


@pytest.fixture
def no_work(monkeypatch):
    """The mechanism's report made to fail the test if it starts."""
    def started(*args, **kwargs):
        raise AssertionError("a report started before every argument was checked")
    monkeypatch.setattr(verdict_mechanism, "mechanism_verdict", started)


@pytest.mark.parametrize("argv, message", [
    (["verdict_mechanism_factory:pendulum"], "1-dimensional configuration space"),
    (["rotors", "n=4"],
     "--mechanism rotors n=4: rotors(n=4) has a 3-dimensional configuration space"),
    (["scene_mechanism_factory:sphere"], "fewer than two periodic coordinates"),
    (["no_such_module_here:f"], "the module 'no_such_module_here' cannot be imported"),
    (["verdict_mechanism_factory:nothing"], "has no 'nothing'"),
    (["verdict_mechanism_factory:sphere", "lvl=2"], "unknown key 'lvl'"),
    (["verdict_mechanism_factory:sphere", "level"], "a parameter is KEY=VALUE"),
    (["verdict_mechanism_factory:sphere", "name=1"], "name is the mechanism itself"),
    (["triple_lnkage"], "did you mean 'triple_linkage'"),
    (["missing.toml"], "cannot be read as TOML"),
])
def test_a_spec_that_does_not_resolve_is_refused_before_any_work(argv, message, capsys,
                                                                  no_work):
    assert main(["verdict", "--mechanism", *argv, *FAST]) == 2
    captured = capsys.readouterr()
    assert message in captured.err and "Traceback" not in captured.err, captured.err
    assert "verdict:" not in captured.out


@pytest.mark.parametrize("argv, message", [
    (["--grid", "5"], "--grid must be an integer in 8..4096"),
    (["--t-final", "0.015"], "not a whole number of steps"),
    (["--angles", "-5"], "--angles must be positive"),
    (["--statistics"], "leave out --triple-linkage and --mechanism"),
    (["--rod-length", "1.1"], "give --triple-linkage"),
])
def test_bad_settings_are_refused_before_any_work(argv, message, capsys, no_work):
    assert main(["verdict", "--mechanism", ARM, *argv]) == 2
    captured = capsys.readouterr()
    assert message in captured.err and "Traceback" not in captured.err, captured.err


def test_the_api_refuses_a_mechanism_that_is_not_a_surface():
    from verdict_mechanism_factory import pendulum
    with pytest.raises(ValueError, match="1-dimensional configuration space.*dimension 2"):
        verdict_mechanism.mechanism_verdict(pendulum())
    with pytest.raises(ValueError, match="n_grid must be an integer"):
        verdict_mechanism.mechanism_verdict(sphere(), n_grid=4)
    with pytest.raises(ValueError, match="seeds must be"):
        verdict_mechanism.mechanism_verdict(sphere(), seeds=1)
    with pytest.raises(ValueError, match="progress must be a callable"):
        verdict_mechanism.mechanism_verdict(sphere(), progress=1)
    with pytest.raises(ValueError, match="t_final must be"):
        verdict_mechanism.mechanism_verdict(sphere(), t_final=float("nan"))
