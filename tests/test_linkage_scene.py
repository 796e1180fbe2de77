"""The linkage of the Appendix through scenes and sweeps: a linkage scene gives exactly the
numbers of the linkage's API (`linkage_run`, `linkage_angles`, `linkage_trajectory`), also
when interrupted and resumed; bad linkage keys are refused in one line; a sweep over ε
parses and runs; the bundled sweep is the one docs/linkage.md describes."""
import json
import re
from pathlib import Path

import numpy as np
import pytest

import charts
from charts.analyses.linkage_angles import linkage_angles
from charts.runs.paper import PAPER_EXPONENTS
from charts.runs.runner import run_scene
from charts.runs.scene import SceneError, parse_scene
from charts.runs.sweep import (bundled_sweeps, evaluate_point, load_sweep, parse_sweep,
                               summarize, summary_markdown, sweep_points)

DOCS = Path(__file__).resolve().parent.parent / "docs"
EPS = 0.05


def linkage_scene(effects, t_final=30.0, t_transient=5.0, **system):
    return parse_scene({"system": {"kind": "linkage", "eps": EPS, **system},
                        "initial": {"seed": 3},
                        "run": {"t_final": t_final, "t_transient": t_transient,
                                "checkpoint_every": 7.0},
                        "effects": effects})


FULL = {"lyapunov": {"n_batches": 4}, "curvature": {"sample_every": 1.0},
        "angles": {"sample_every": 0.5}}


def test_linkage_scene_equals_the_api_bit_for_bit(tmp_path):
    """Exponents, standard errors, every curvature sample, Σ sin²θ, the KKT health and every
    angle of the scene equal those of `linkage_run` / `linkage_angles` from the same seeded
    state, although the scene runs in checkpointed chunks (every 7.0) that do not line up
    with the batches (every 7.5)."""
    res = run_scene(linkage_scene(FULL), tmp_path / "out", quiet=True)
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        K, phi, t_phi = a["curvature_exact"], a["angles_restricted"], a["angles_t"]
    L = charts.LinkageSystem(EPS)
    q, v = L.random_state(seed=3, speed=1.0)
    api = charts.linkage_run(L, q, v, 30.0, t_transient=5.0, n_batches=4, sample_every=1.0,
                             seed=3)
    ly, lk = res["results"]["lyapunov"], res["results"]["linkage"]
    assert ly["exponents"] == api.exponents.tolist()
    assert ly["stderr"] == api.stderr.tolist()
    assert np.array_equal(K, api.K)
    assert lk["min_sin2"] == api.min_sin2 and lk["min_kkt_health"] == api.min_health
    assert ly["paper"] == list(PAPER_EXPONENTS[4])
    ang = linkage_angles(L, q, v, 30.0, t_transient=5.0, sample_every=0.5, seed=3)
    assert np.array_equal(phi, ang.phi) and np.array_equal(t_phi, ang.t)
    assert res["results"]["angles"]["forward_exponents"] == ang.forward_exponents.tolist()
    assert res["initial_state"] == {"q": q.tolist(), "v": v.tolist()}
    # the cone points of Σ cos θ = 0: two on M, four at distance 2.00 ε (docs/linkage.md)
    assert lk["cone_points_on_manifold"] == 2
    assert lk["cone_distance_min"] == pytest.approx(2 * EPS, rel=0.02)
    assert res["computation"]["state_dimension"] == 14
    if "results.nc" in res["files"]:            # the archive holds the linkage's results too
        back = charts.load(tmp_path / "out" / "results.nc")
        assert back.result["results"]["linkage"] == json.loads(json.dumps(lk))
        assert np.array_equal(back.arrays["curvature_exact"], api.K)


@pytest.mark.parametrize("dt", [0.04, 0.03])
def test_linkage_scene_that_only_sets_dt_is_the_api_call(tmp_path, dt):
    """At dt = 0.04 and 0.03, where the documented 0.1 and 1.0 are no whole number of steps,
    a linkage scene that writes dt and the times only and the API calls that leave the same
    defaults take the same steps (reorth_every, the curvature samples of linkage_run's
    sample_every, project_every 1.0 / 0.99) and give the same numbers bit for bit."""
    sc = parse_scene({"system": {"kind": "linkage", "eps": EPS}, "integrator": {"dt": dt},
                      "run": {"t_final": 6.0, "t_transient": 1.2},
                      "effects": {"lyapunov": {"n_batches": 4}, "curvature": {}, "angles": {}}})
    assert sc.integrator["project_every"] == pytest.approx(dt * round(1.0 / dt))
    res = run_scene(sc, tmp_path / "out", quiet=True)
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        K, phi, t_phi = a["curvature_exact"], a["angles_restricted"], a["angles_t"]
    L = charts.LinkageSystem(EPS)
    q, v = L.random_state(seed=0)
    api = charts.linkage_run(L, q, v, 6.0, dt=dt, t_transient=1.2, n_batches=4)
    assert api.params["reorth_every"] == sc.effects["lyapunov"]["reorth_every"]
    assert api.params["sample_every"] == sc.effects["curvature"]["sample_every"]
    assert res["results"]["lyapunov"]["exponents"] == api.exponents.tolist()
    assert res["results"]["lyapunov"]["stderr"] == api.stderr.tolist()
    assert np.array_equal(K, api.K)
    alone = charts.linkage_run(L, q, v, 6.0, dt=dt, t_transient=1.2, n_batches=4,
                               curvature=False)          # every time setting left to dt
    assert np.array_equal(alone.exponents, api.exponents)
    ang = linkage_angles(L, q, v, 6.0, dt=dt, t_transient=1.2)
    assert np.array_equal(phi, ang.phi) and np.array_equal(t_phi, ang.t)


def test_linkage_scene_angle_defaults_are_linkage_angles_at_dt_003():
    """Nothing but dt = 0.03 written: the angle pass's transient and samples are those
    `linkage_angles` takes for its defaults (a transient that is a multiple of the samples;
    the scene was refused: t_transient = 50.01 is not a multiple of sample_every = 0.06)."""
    from charts.analyses.arguments import Documented
    from charts.analyses.linkage_angles import angle_steps

    sc = parse_scene({"system": {"kind": "linkage", "eps": EPS}, "integrator": {"dt": 0.03},
                      "run": {"t_final": 3.0}, "effects": {"angles": {}}})
    default = linkage_angles.__kwdefaults__
    _, transient, sample = angle_steps(0.03, 3.0, default["t_transient"],
                                       default["sample_every"])
    a = sc.effects["angles"]
    assert isinstance(default["t_transient"], Documented)
    assert (a["t_transient"], a["sample_every"]) == (transient * 0.03, sample * 0.03)
    assert (transient, sample) == (1666, 2)


def test_linkage_scene_interrupted_and_resumed_equals_uninterrupted(tmp_path):
    def stop(idx, total):
        if idx == 2:
            raise KeyboardInterrupt

    sc = linkage_scene({"lyapunov": {"n_batches": 4}}, t_final=20.0, t_transient=1.0)
    ref = run_scene(sc, tmp_path / "ref", quiet=True)
    with pytest.raises(KeyboardInterrupt):
        run_scene(sc, tmp_path / "cut", quiet=True, on_chunk=stop)
    assert json.loads((tmp_path / "cut" / "result.json").read_text())["status"] == "interrupted"
    res = run_scene(sc, tmp_path / "cut", quiet=True, resume=True)
    assert res["results"] == ref["results"]
    assert res["final_state"] == ref["final_state"]


def test_linkage_waveforms_and_drift_are_the_api_trajectory(tmp_path):
    """Waveforms only: no tangent vectors; the stored rotor velocities are those of
    `linkage_trajectory`, and the invariants stay at rounding (projection every t = 1)."""
    sc = linkage_scene({"waveforms": {"rotors": [0, 3], "t_window": 4.0},
                        "drift": {"sample_every": 0.5}}, t_final=4.0, t_transient=0.0)
    res = run_scene(sc, tmp_path / "out", quiet=True)
    assert res["computation"]["tangent_vectors"] == 0
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        U = a["waveforms_u"]
    L = charts.LinkageSystem(EPS)
    q, v = L.random_state(seed=3)
    _, states = charts.linkage_trajectory(L, q, v, 4.0, sample_every=0.01)
    assert np.array_equal(U, states[1:, [7, 10]])
    d = res["drift"]
    # between the projections (every t = 1) RK4 drifts: measured max 9.0e-12 (energy) over
    # the samples every 0.5; at t = 4, just projected, F and J v are at rounding (2e-16,
    # 7e-18), the energy keeps RK4's error (6.0e-12: the mechanism's projections do not
    # rescale the speed)
    assert max(d["max_abs_constraint"], d["max_abs_tangency"],
               d["max_abs_energy_relative"]) < 1e-10
    assert max(abs(d["constraint"]), abs(d["tangency"])) < 1e-14
    assert abs(d["energy_relative"]) < 1e-10


BAD = [
    ({"kind": "linkage", "eps": 0.7, "masses": [1, 1, 1, 1], "rhoo": 0.1},
     ["3 problems", "unknown key 'rhoo' in [system] — did you mean 'rho'?",
      "[system] eps = 0.7 is not allowed: expected a number in [1e-06, 0.5)",
      "[system] masses = [1, 1, 1, 1] is not allowed with kind = 'linkage'"]),
    ({"kind": "linkage"}, ["[system] eps is required"]),
    ({"n": 4, "eps": 0.1}, ["[system] eps = 0.1 is not allowed with kind = 'rotors'"]),
    ({"kind": "linkag", "eps": 0.1}, ["did you mean 'linkage'?"]),
    ({"kind": "linkage", "eps": 0.1, "n": 5}, ["n = 5 is not allowed with kind = 'linkage'"]),
    ({"kind": "linkage", "eps": 0.1, "disk_mass": -1.0}, ["disk_mass = -1.0 is not allowed"]),
]


@pytest.mark.parametrize("system,parts", BAD)
def test_bad_linkage_keys_refused_in_one_line(system, parts):
    with pytest.raises(SceneError) as e:
        parse_scene({"system": system, "run": {"t_final": 10.0}, "effects": {"lyapunov": {}}})
    msg = str(e.value)
    assert "\n" not in msg
    for p in parts:
        assert p in msg, msg
    if system.get("kind") == "linkag":       # a bad kind is reported alone, not its keys
        assert "eps" not in msg


@pytest.mark.parametrize("extra,part", [
    ({"effects": {"clv": {}}}, "[effects] clv is not allowed with kind = 'linkage'"),
    ({"effects": {"curvature": {"route": "numerical"}}}, "route = 'numerical' is not allowed"),
    ({"effects": {"angles": {"variant": "full"}}}, "variant = 'full' is not allowed"),
    ({"effects": {"lyapunov": {"inner_product": "full"}}}, "inner_product = 'full' is not"),
    ({"integrator": {"formulation": "chart"}}, "formulation = 'chart' is not allowed"),
    ({"integrator": {"method": "dop853"}}, "method = 'dop853' is not allowed"),
    ({"initial": {"theta": [0, 0, 0, 0], "u": [0, 0, 0, 0]}}, "[initial] theta is not allowed"),
])
def test_what_a_linkage_cannot_do_is_refused(extra, part):
    d = {"system": {"kind": "linkage", "eps": 0.1}, "run": {"t_final": 10.0},
         "effects": {"lyapunov": {}}}
    d.update(extra)
    with pytest.raises(SceneError, match=re.escape(part)):
        parse_scene(d)


def test_rotor_scenes_carry_no_linkage_keys():
    """A rotor scene as run is what it was before the linkage kind (same point ids)."""
    sc = parse_scene({"system": {"n": 4}, "run": {"t_final": 10.0}, "effects": {"lyapunov": {}}})
    assert set(sc.system) == {"n", "masses", "speed"}


TINY = {"name": "tiny", "scene": {"system": {"kind": "linkage", "eps": 0.1},
                                  "run": {"t_final": 10.0, "t_transient": 1.0},
                                  "effects": {"lyapunov": {"n_batches": 2},
                                              "curvature": {"sample_every": 1.0}}},
        "sweep": {"seeds": [0], "parameters": {"eps": [0.2, 0.05]}}}


def test_sweep_over_eps_parses_and_runs(tmp_path):
    """The ε axis (``eps`` or the dotted ``system.eps``) sets [system] eps, ρ follows as 2ε;
    every point runs (evaluate_point, what a Dask worker does), and the summary carries the
    paper's limit row and the ε-study figure."""
    from charts.runs.sweep.limits import plot_limit_sweep
    from charts.runs.sweep.table import csv_line, point_columns, point_row, read_table

    pts = sweep_points(parse_sweep(TINY))
    dotted = dict(TINY, sweep={"seeds": [0], "parameters": {"system.eps": [0.2, 0.05]}})
    assert [p.scene.system for p in sweep_points(parse_sweep(dotted))] == \
        [p.scene.system for p in pts]
    assert [(p.scene.system["eps"], p.scene.system["rho"]) for p in pts] == \
        [(0.2, 0.4), (0.05, 0.1)]
    cols = point_columns(pts)
    assert {"lambda_1", "lambda_2_se", "Kpos_exact_1", "sin2_min", "kkt_health_min",
            "cone_distance_min", "cone_points_on_manifold"} <= set(cols)
    table = tmp_path / "sweep.csv"
    table.write_text(csv_line(cols) + "".join(
        csv_line(point_row(p, evaluate_point(p.raw), cols)) for p in pts))
    header, rows = read_table(table)
    assert all(r["status"] == "complete" for r in rows)
    assert [int(r["cone_points_on_manifold"]) for r in rows] == [2] * 2
    summary = summarize(header, rows, pts)
    assert [e["eps"] for e in summary["rows"]] == [0.2, 0.05]
    md = summary_markdown(summary)
    assert md.splitlines()[-1].startswith("| → 0: paper") and "| 0.385 | 0.230 |" in md
    files = plot_limit_sweep(summary, tmp_path / "fig", "tiny")
    assert [Path(f).name for f in files] == ["linkage_eps.png"]


def test_bundled_linkage_sweep_is_the_one_the_docs_describe():
    """linkage-epsilon: the ε values, seeds and times docs/linkage.md states, every row of
    its table, and the command it gives."""
    sweep = load_sweep(bundled_sweeps()["linkage-epsilon"])
    pts = sweep_points(sweep)
    eps = sweep.axes["eps"]
    assert eps == [0.2, 0.1, 0.05, 0.02, 0.01] and len(sweep.seeds) == 4
    assert len(pts) == 20 and all(p.scene.system["rho"] == 2 * p.scene.system["eps"]
                                  for p in pts)
    assert pts[0].scene.run["t_final"] == 1000.0 and pts[0].scene.run["t_transient"] == 50.0
    text = (DOCS / "linkage.md").read_text()
    assert "charts sweep linkage-epsilon" in text
    section = text[text.index("### The sweep"):]
    for e in eps:
        assert re.search(rf"^\| {e:g} \| 4 \|", section, re.M), e
    assert "`linkage-epsilon`" in (DOCS / "sweeps.md").read_text()
