"""Result files say what made them: the tangent vectors' seed (``vectors_seed``), the initial
state's (``state_seed``, or "given"), an ensemble's first member's (``members_seed``), the
dimension of E_u (``n_unstable``, no ``m``); files written with the old names (``params_seed``,
``params_m``) still load, under the new names and with a note.  Transient rules ("scaled",
"auto") in scenes and sweeps."""
import json

import numpy as np
import pytest

import charts
from charts.analyses.lyapunov import auto_transient
from charts.io.renamed_settings import NOTE
from charts.runs.runner import run_scene
from charts.runs.scene import SceneError, parse_scene
from charts.runs.sweep import SweepError, parse_sweep, sweep_points

xr = pytest.importorskip("xarray")

S4 = charts.RotorSystem(4)
TH, U = S4.random_state(seed=5)


def _rewritten(path, out, rename=(), drop=(), add=None):
    """The file at ``path`` written again to ``out`` as a file of the old names would be:
    attributes and variables renamed (old ← new), some dropped, some added."""
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        ds = ds.load()
    for new, old in rename:
        if new in ds.attrs:
            ds.attrs[old] = ds.attrs.pop(new)
        elif new in ds.variables:
            ds = ds.rename_vars({new: old})
    for name in drop:
        if name in ds.attrs:
            del ds.attrs[name]
        else:
            ds = ds.drop_vars(name)
    ds.attrs.update(add or {})
    ds.to_netcdf(out, engine="h5netcdf")
    return out


def test_a_single_run_names_its_seeds(tmp_path):
    r = charts.lyapunov_spectrum(S4, TH, U, 2.0, t_transient=1.0, n_batches=2, seed=3)
    assert r.params["vectors_seed"] == 3 and r.params["state_seed"] == "given"
    assert "seed" not in r.params
    path = r.save(tmp_path / "l.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert ds.attrs["params_vectors_seed"] == 3 and ds.attrs["params_state_seed"] == "given"
        assert "params_seed" not in ds.attrs and "state_seed" in ds.attrs["comment"]
    assert charts.load(path) == r


def test_clv_results_name_the_unstable_dimension(tmp_path):
    v = charts.covariant_lyapunov_vectors(S4, TH, U, 2.0, t_transient=1.0)
    assert v.params["n_unstable"] == 2 and "m" not in v.params
    old = _rewritten(v.save(tmp_path / "v.nc"), tmp_path / "old.nc",
                     rename=[("params_vectors_seed", "params_seed")],
                     drop=["params_state_seed"], add={"params_m": 2})
    back = charts.load(old)
    assert back.params["n_unstable"] == 2 and back.params["vectors_seed"] == 0
    assert "m" not in back.params and "seed" not in back.params
    assert back.params[NOTE].startswith("seed -> vectors_seed; m -> n_unstable")
    assert np.array_equal(back.phi, v.phi)


def test_an_ensemble_records_each_members_state_seed(tmp_path):
    e = charts.lyapunov_ensemble(S4, 3, 2.0, t_transient=1.0, n_batches=2, workers=1, seed=7)
    assert e.params["members_seed"] == 7 and "seed" not in e.params
    assert [m.params["state_seed"] for m in e.members] == [7, 8, 9]
    assert [m.params["vectors_seed"] for m in e.members] == [7, 8, 9]
    th, u = S4.random_state(seed=8)
    assert e.members[1].params["theta0"] == pytest.approx(th.tolist(), abs=1e-12)
    path = e.save(tmp_path / "e.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert ds["member.params.state_seed"].values.tolist() == [7, 8, 9]
        assert ds.attrs["params_members_seed"] == 7
    assert charts.load(path) == e
    # the same file with the names of before: read as the new ones, with the note
    old = _rewritten(path, tmp_path / "old.nc",
                     rename=[("params_members_seed", "params_seed"),
                             ("member.params.vectors_seed", "member.params.seed")],
                     drop=["member.params.state_seed"])
    back = charts.load(old)
    assert back.params["members_seed"] == 7 and "seed" not in back.params
    assert "seed -> members_seed" in back.params[NOTE]
    assert [m.params["vectors_seed"] for m in back.members] == [7, 8, 9]
    assert [m.params["state_seed"] for m in back.members] == [7, 8, 9]
    assert np.array_equal(back.exponents, e.exponents)


def test_a_tally_names_its_members_seeds(tmp_path):
    t = charts.hyperbolicity_tally(S4, 3, 2.0, t_transient=1.0, seed=2, workers=1,
                                   device="cpu")
    assert t.params["members_seed"] == 2 and "seed" not in t.params
    assert "vectors_seed" not in t.params and t.seeds.tolist() == [2, 3, 4]
    path = t.save(tmp_path / "t.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert ds["state_seed"].values.tolist() == [2, 3, 4]
    old = _rewritten(path, tmp_path / "old.nc", rename=[("params_members_seed", "params_seed"),
                                                        ("state_seed", "seed")])
    back = charts.load(old)
    assert back.seeds.tolist() == [2, 3, 4] and back.params["members_seed"] == 2


def test_a_scene_records_its_state_seed_and_transient_rule(tmp_path):
    base = {"system": {"n": 4}, "run": {"t_final": 1.0, "t_transient": "scaled"},
            "effects": {"lyapunov": {"n_batches": 2}}}
    res = run_scene(parse_scene({**base, "initial": {"seed": 3}}), tmp_path / "a", quiet=True)
    assert res["state_seed"] == 3 and res["transient_rule"].startswith("scaled")
    assert res["scene"]["run"]["t_transient"] == 80.0
    given = {**base, "initial": {"theta": TH.tolist(), "u": U.tolist()},
             "run": {"t_final": 1.0, "t_transient": 0.5}}
    res = run_scene(parse_scene(given), tmp_path / "b", quiet=True)
    assert res["state_seed"] == "given" and "transient_rule" not in res
    assert json.loads((tmp_path / "b" / "result.json").read_text())["state_seed"] == "given"


def test_auto_in_a_scene_is_the_apis_auto():
    sc = parse_scene({"system": {"n": 5}, "initial": {"seed": 6},
                      "run": {"t_final": 2.0, "t_transient": "auto"},
                      "effects": {"lyapunov": {}, "angles": {}}})
    S = charts.RotorSystem(5)
    th, u = S.random_state(seed=6)
    want = float(auto_transient(S, th, u, seed=6))
    assert sc.run["t_transient"] == pytest.approx(want, abs=0.006)
    assert sc.effects["angles"]["t_transient"] == sc.run["t_transient"]     # written: every pass's
    assert sc.transient_rule.startswith("auto")


@pytest.mark.parametrize("where, value, says", [
    ("run", "atuo", "[run] t_transient = 'atuo' is not allowed — did you mean 'auto'?"),
    ("run", "long", "expected a number of time units, or one of 'scaled', 'auto'"),
    ("angles", "scald", "[effects.angles] t_transient = 'scald' is not allowed — did you mean "
                        "'scaled'?")])
def test_a_misspelt_rule_is_refused(where, value, says):
    data = {"system": {"n": 4}, "run": {"t_final": 1.0}, "effects": {"angles": {}}}
    if where == "run":
        data["run"]["t_transient"] = value
    else:
        data["effects"]["angles"]["t_transient"] = value
    with pytest.raises(SceneError) as err:
        parse_scene(data)
    assert says in str(err.value)


def test_the_linkage_refuses_the_rules():
    with pytest.raises(SceneError, match="not allowed for the linkage"):
        parse_scene({"system": {"kind": "linkage", "eps": 0.1},
                     "run": {"t_final": 1.0, "t_transient": "auto"},
                     "effects": {"lyapunov": {}}})


def test_auto_in_a_sweep():
    base = {"system": {"n": 4}, "run": {"t_final": 1.0, "t_transient": "auto"},
            "effects": {"lyapunov": {"n_batches": 2}}}
    pts = sweep_points(parse_sweep({"name": "t", "scene": base, "sweep": {"seeds": [1, 2]}},
                                   source="t.toml"))
    for p, seed in zip(pts, (1, 2)):
        want = float(auto_transient(S4, *S4.random_state(seed=seed), seed=seed))
        assert p.scene.run["t_transient"] == pytest.approx(want, abs=0.006)
        assert p.scene.transient_rule.startswith("auto")
    axis = {"name": "t", "scene": {**base, "run": {"t_final": 1.0}},
            "sweep": {"seeds": [1], "parameters": {"run.t_transient": ["scaled", 3.0]}}}
    assert [p.scene.run["t_transient"] for p in sweep_points(parse_sweep(axis))] == [80.0, 3.0]
    bad = {"name": "t", "scene": {**base, "run": {"t_final": 1.0, "t_transient": "otto"}},
           "sweep": {"seeds": [1]}}
    with pytest.raises(SweepError, match="did you mean 'auto'"):
        sweep_points(parse_sweep(bad, source="t.toml"))


def test_the_cli_option_takes_a_rule():
    import argparse

    from charts.cli.verdict_statistics import transient_of as _transient_of
    from charts.runs.cli_parser import transient_arg
    assert transient_arg("auto") == "auto" and transient_arg("12.5") == 12.5
    with pytest.raises(argparse.ArgumentTypeError, match="did you mean 'scaled'"):
        transient_arg("scaeld")
    assert _transient_of("scaled", charts.RotorSystem(5)) == 125.0
    assert _transient_of(30.0, S4) == 30.0
