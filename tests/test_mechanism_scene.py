"""A mechanism's results saved, loaded and plotted; scenes with a [mechanism] table; sweeps
over a mechanism's parameters."""
from pathlib import Path

import numpy as np
import pytest

import charts
from charts.analyses.mechanism_lyapunov import MechanismLyapunov, lyapunov_spectrum

R = 0.3


@pytest.fixture(scope="module")
def triple():
    """A short Lyapunov run of the triple linkage at r = 0.3 from a seeded state."""
    mech = charts.triple_linkage(R)
    q, v = mech.random_state(seed=1)
    return lyapunov_spectrum(mech, q, v, 4.0, t_transient=1.0, n_batches=4, seed=5)


def test_mechanism_lyapunov_round_trip_is_bit_identical(triple, tmp_path):
    """Saved and loaded: the same type, every array the same bits and dtype, the settings
    with the provenance (the mechanism, its parameters, q0, v0, the seeds) equal; every
    array with its Fletcher-32 checksum; the one-line summary unchanged."""
    import xarray as xr

    back = charts.load(triple.save(tmp_path / "m.nc"))
    assert type(back) is MechanismLyapunov and back == triple
    for name in ("exponents", "stderr", "batches"):
        a, b = getattr(triple, name), getattr(back, name)
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), name
    assert back.energy_error == triple.energy_error
    p = back.params
    assert p == triple.params
    assert p["parameters"] == {"r": R, "l": 1.0, "R": 1.0, "I": 1.0, "m": 0.0, "mu": 0.0}
    assert (p["state_seed"], p["vectors_seed"]) == ("given", 5)
    assert p["coordinates"] == ["theta1", "theta2", "theta3", "x", "y"]
    q, v = charts.triple_linkage(R).random_state(seed=1)
    assert p["q0"] == q.tolist() and p["v0"] == v.tolist()
    assert back.summary() == triple.summary()
    ds = xr.open_dataset(tmp_path / "m.nc", engine="h5netcdf")
    assert all(ds[k].encoding.get("fletcher32") for k in ("exponents", "stderr", "batches"))
    assert ds["exponents"].attrs["units"] == "1 / time"
    # the batch ends' times: the last is the averaging time
    assert float(ds["batch_t"][-1]) == pytest.approx(4.0, abs=1e-12)
    ds.close()
    assert repr(back).startswith("MechanismLyapunov(triple_linkage(r=0.3, l=1, R=1), T = 4, λ = ")


def test_mechanism_lyapunov_plots_its_exponents_with_error_bars(triple):
    """The figure names the mechanism and its parameters; one error bar per exponent, at
    the exponent ± its standard error; one dot per batch."""
    fig, ax = triple.plot()
    assert "triple_linkage(r=0.3" in ax.get_title() and "T = 4" in ax.get_title()
    assert ax.get_ylabel() == "λ (1 / time)" and ax.get_xlabel() == "exponent"
    dots = [ln for ln in ax.lines if ln.get_marker() == "o"]
    assert len(dots) == 1 and len(dots[0].get_ydata()) == 4
    assert np.array_equal(dots[0].get_ydata(), triple.batches[:, 0])
    bar = ax.containers[0]
    lo, hi = bar.lines[1][0].get_ydata(), bar.lines[1][1].get_ydata()
    assert lo[0] == pytest.approx(triple.exponents[0] - triple.stderr[0], rel=1e-12)
    assert hi[0] == pytest.approx(triple.exponents[0] + triple.stderr[0], rel=1e-12)


# ------------------------------------------------------------------------------ scenes
from charts.runs.runner import run_scene                      # noqa: E402
from charts.runs.scene import SceneError, parse_scene, scene_to_dict   # noqa: E402

TRIPLE = {"mechanism": {"name": "triple_linkage", "r": R}, "initial": {"seed": 2},
          "run": {"t_final": 4.0, "t_transient": 1.0, "checkpoint_every": 0.7},
          "effects": {"lyapunov": {"n_batches": 4}, "drift": {"sample_every": 0.5},
                      "waveforms": {"t_window": 2.0}}}


def test_triple_linkage_scene_runs_to_its_files_and_equals_the_api(tmp_path):
    """A [mechanism] scene of the triple linkage runs end to end: its files, and exponents
    and standard errors bit for bit those of `lyapunov_spectrum` from the same seeded state
    (the scene runs in checkpointed chunks of 0.7 that do not line up with the batches of
    1.0); the invariants at rounding after the last projection; the mechanism recorded."""
    sc = parse_scene(TRIPLE)
    assert sc.system == {"kind": "mechanism", "mechanism": "triple_linkage",
                         "parameters": {"r": R, "l": 1.0, "R": 1.0, "inertia": 1.0,
                                        "joint_mass": 0.0, "rod_mass": 0.0},
                         "speed": 1.0, "coordinates": ["theta1", "theta2", "theta3", "x", "y"],
                         "dimension": 2}
    assert sc.effects["lyapunov"]["n_exponents"] == 1          # d − 1 on a surface
    res = run_scene(sc, tmp_path / "out", quiet=True)
    assert res["status"] == "complete"
    for name in ("result.json", "checkpoint.npz", "arrays.npz", "lyapunov.png", "drift.png",
                 "waveforms.png"):
        assert (tmp_path / "out" / name).exists(), name
    mech = charts.triple_linkage(R)
    q, v = mech.random_state(seed=2)
    api = lyapunov_spectrum(mech, q, v, 4.0, t_transient=1.0, n_batches=4, seed=2)
    ly = res["results"]["lyapunov"]
    assert ly["exponents"] == api.exponents.tolist() and ly["stderr"] == api.stderr.tolist()
    assert ly["h_ks"] == ly["exponents"][0]        # Σλ⁺ of a surface: λ₁
    assert res["initial_state"] == {"q": q.tolist(), "v": v.tolist()}
    assert res["results"]["mechanism"]["label"] == mech.name
    assert res["computation"]["state_dimension"] == 10
    d = res["drift"]
    # projected every t = 1 (the default): at t = 5 the state was just projected
    assert max(abs(d["constraint"]), abs(d["tangency"])) < 1e-13
    # RK4 between projections drifts in the energy: measured 6.7e-11 at most in this run
    # (t = 5, dt = 0.01, 10 samples); the bound leaves 15× for other platforms' rounding
    assert d["max_abs_energy_relative"] < 1e-9
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        assert a["waveforms_u"].shape == (200, 5)
    if "results.nc" in res["files"]:
        back = charts.load(tmp_path / "out" / "results.nc")
        assert back.result["results"]["lyapunov"]["exponents"] == ly["exponents"]


def test_triple_linkage_scene_resumed_equals_uninterrupted(tmp_path):
    def stop(idx, total):
        if idx == 2:
            raise KeyboardInterrupt

    sc = parse_scene(dict(TRIPLE, effects={"lyapunov": {"n_batches": 4}}))
    ref = run_scene(sc, tmp_path / "ref", quiet=True)
    with pytest.raises(KeyboardInterrupt):
        run_scene(sc, tmp_path / "cut", quiet=True, on_chunk=stop)
    res = run_scene(sc, tmp_path / "cut", quiet=True, resume=True)
    assert res["results"] == ref["results"] and res["final_state"] == ref["final_state"]


def test_users_factory_runs_as_a_scene(tmp_path):
    """``"module:factory"`` with its keyword arguments: the sphere of tests/
    scene_mechanism_factory.py, the scene's exponent that of `lyapunov_spectrum` on the
    factory's mechanism."""
    from scene_mechanism_factory import sphere

    sc = parse_scene({"mechanism": {"name": "scene_mechanism_factory:sphere", "radius": 2.0},
                      "run": {"t_final": 2.0, "t_transient": 0.5},
                      "effects": {"lyapunov": {"n_batches": 2}}})
    assert sc.system["parameters"] == {"radius": 2.0, "mass": 1.0}
    res = run_scene(sc, tmp_path / "out", quiet=True)
    mech = sphere(2.0)
    api = lyapunov_spectrum(mech, *mech.random_state(seed=0), 2.0, t_transient=0.5,
                            n_batches=2)
    assert res["results"]["lyapunov"]["exponents"] == api.exponents.tolist()


@pytest.mark.parametrize("mechanism,extra,parts", [
    ({"name": "triple_linkage", "r": 0.3, "rr": 1.0}, {},
     ["unknown key 'rr' in [mechanism] — did you mean 'r'?", "allowed: R, inertia, "
      "joint_mass, l, name, r, rod_mass"]),
    ({"name": "triple_linkage"}, {}, ["[mechanism] r is required"]),
    ({"name": "triple_linkage", "r": -0.1}, {}, ["[mechanism] r = -0.1 is not allowed: r must "
                                                  "be positive"]),
    ({"name": "tripple_linkage", "r": 0.3}, {}, ["did you mean 'triple_linkage'?"]),
    ({"r": 0.3}, {}, ["[mechanism] name is required"]),
    ({"name": "scene_mechanism_factory:sphere", "radius": 1.0, "massive": 2.0}, {},
     ["unknown key 'massive' in [mechanism] — did you mean 'mass'?"]),
    ({"name": "scene_mechanism_factory:not_a_mechanism"}, {}, ["returned dict, not a "
                                                                 "charts.Mechanism"]),
    ({"name": "no_such_module_here:f"}, {}, ["the module 'no_such_module_here' cannot be "
                                             "imported"]),
    ({"name": "scene_mechanism_factory:broken"}, {},
     ["[mechanism] name = 'scene_mechanism_factory:broken': the factory failed "
      "(ZeroDivisionError: float division by zero)"]),
    ({"name": "rotors", "n": 2}, {}, ["[mechanism] n = 2 is not allowed: expected an integer "
                                      "in 3.."]),
    ({"name": "rotors"}, {}, ["[mechanism] n is required"]),
    ({"name": "linkage", "eps": 0.7}, {}, ["[mechanism] eps = 0.7 is not allowed: expected a "
                                           "number in [1e-06, 0.5)"]),
    ({"name": "triple_linkage", "r": 0.3}, {"system": {"n": 3}},
     ["[system] n is not allowed with a [mechanism] table"]),
    ({"name": "triple_linkage", "r": 0.3}, {"effects": {"clv": {}}},
     ["[effects] clv is not allowed with a [mechanism] table"]),
    ({"name": "triple_linkage", "r": 0.3}, {"effects": {"angles": {"variant": "both"}}},
     ["[effects.angles] variant = 'both' is not allowed with a [mechanism] table: only "
      "'restricted'"]),
    ({"name": "triple_linkage", "r": 0.3}, {"effects": {"curvature": {"n_directions": 2}}},
     ["n_directions = 2 is not allowed: expected 1..1"]),
    ({"name": "triple_linkage", "r": 0.3}, {"integrator": {"formulation": "chart"}},
     ["formulation = 'chart' is not allowed with a [mechanism] table"]),
    ({"name": "triple_linkage", "r": 0.3}, {"initial": {"theta": [0, 0, 0]}},
     ["[initial] theta is not allowed with a [mechanism] table"]),
    ({"name": "triple_linkage", "r": 0.3}, {"effects": {"lyapunov": {"n_exponents": 3}}},
     ["n_exponents = 3 is not allowed with inner_product = 'theta': expected 1..2 (use "
      "inner_product = 'full' for up to 4)"]),
    ({"name": "triple_linkage", "r": 0.3}, {"run": {"t_final": 1.0, "t_transient": "scaled"}},
     ["t_transient = 'scaled'", "'scaled' is the rotors' rule", "'auto'"]),
    ({"name": "rotors", "n": 4}, {"system": {"n": 4}},
     ["[system] n is not allowed beside [mechanism] n"]),
    ({"name": "linkage", "eps": 0.1, "rhoo": 0.2}, {}, ["unknown key 'rhoo' in [mechanism] — "
                                                        "did you mean 'rho'?"]),
])
def test_bad_mechanism_tables_are_refused_naming_the_key(mechanism, extra, parts):
    data = {"mechanism": mechanism, "run": {"t_final": 1.0}, "effects": {"lyapunov": {}}}
    data.update(extra)
    with pytest.raises(SceneError) as e:
        parse_scene(data)
    msg = str(e.value)
    assert "\n" not in msg
    for p in parts:
        assert p in msg, msg


def test_rotors_and_linkage_tables_are_their_system_scenes():
    """[mechanism] rotors and linkage are read as the [system] of their structured routes:
    the same scene as run (same point ids), the same numbers."""
    run = {"run": {"t_final": 10.0}, "effects": {"lyapunov": {}}}
    pairs = [({"mechanism": {"name": "rotors", "n": 4, "masses": [1, 2, 1, 2]}},
              {"system": {"n": 4, "masses": [1, 2, 1, 2]}}),
             ({"mechanism": {"name": "linkage", "eps": 0.05}, "system": {"speed": 2.0}},
              {"system": {"kind": "linkage", "eps": 0.05, "speed": 2.0}})]
    for table, system in pairs:
        a, b = parse_scene({**table, **run}), parse_scene({**system, **run})
        assert scene_to_dict(a) == scene_to_dict(b)


# ------------------------------------------------------------------------------ sweeps
from charts.runs.sweep import (evaluate_point, parse_sweep, summarize,   # noqa: E402
                               summary_markdown, sweep_points)


def test_sweep_over_r_writes_the_table_with_the_entropy(tmp_path):
    """Two values of the triple linkage's r (a plain axis ``r`` of the base's [mechanism]
    table, or the dotted ``mechanism.r``): each point is the scene with that r; the table
    has λ₁ ± s.e. and Σλ⁺ (h_ks, its s.e.) per point, the summary their means over seeds
    with the limit row r → 0 (the paper's N = 3 λ₁ = 0.500) and the limit study's figure."""
    from charts.runs.sweep.limits import plot_limit_sweep
    from charts.runs.sweep.report import plot_sweep
    from charts.runs.sweep.table import csv_line, point_columns, point_row, read_table

    base = {"mechanism": {"name": "triple_linkage", "r": 0.3},
            "run": {"t_final": 2.0, "t_transient": 0.5},
            "effects": {"lyapunov": {"n_batches": 2}}}
    sweep = {"name": "tiny-r", "scene": base,
             "sweep": {"seeds": [0, 1], "parameters": {"r": [0.1, 0.3]}}}
    pts = sweep_points(parse_sweep(sweep))
    dotted = dict(sweep, sweep={"seeds": [0, 1], "parameters": {"mechanism.r": [0.1, 0.3]}})
    assert [p.scene.system for p in sweep_points(parse_sweep(dotted))] == \
        [p.scene.system for p in pts]
    assert [p.scene.system["parameters"]["r"] for p in pts] == [0.1, 0.1, 0.3, 0.3]
    cols = point_columns(pts)
    assert {"lambda_1", "lambda_1_se", "h_ks", "h_ks_se"} <= set(cols)
    table = tmp_path / "sweep.csv"
    table.write_text(csv_line(cols) + "".join(
        csv_line(point_row(p, evaluate_point(p.raw), cols)) for p in pts))
    header, rows = read_table(table)
    assert all(r["status"] == "complete" for r in rows)
    for p, r in zip(pts, rows):                  # each row is the API call at its r and seed
        mech = charts.triple_linkage(p.params["r"])
        api = lyapunov_spectrum(mech, *mech.random_state(seed=p.params["seed"]), 2.0,
                                t_transient=0.5, n_batches=2, seed=p.params["seed"])
        assert float(r["lambda_1"]) == pytest.approx(api.exponents[0], rel=1e-12)
        assert float(r["h_ks"]) == float(r["lambda_1"])    # a surface: Σλ⁺ = λ₁
        assert float(r["h_ks_se"]) == float(r["lambda_1_se"])
    summary = summarize(header, rows, pts)
    assert summary["limit"] == "triple_linkage"
    assert [e["r"] for e in summary["rows"]] == [0.1, 0.3]
    for e in summary["rows"]:
        lam = [float(r["lambda_1"]) for r in rows if float(r["r"]) == e["r"]]
        assert e["h_ks"] == pytest.approx(np.mean(lam), rel=1e-12) and e["h_ks_se"] > 0
    md = summary_markdown(summary)
    assert "| r | seeds | lambda_1 | h_ks |" in md
    assert md.splitlines()[-1].startswith("| → 0 (l = R): paper N = 3") and "| 0.500 | 0.500 |" in md
    files = plot_limit_sweep(summary, tmp_path / "fig", "tiny-r")
    assert [Path(f).name for f in files] == ["triple_linkage_r.png"]
    names = {Path(f).name for f in plot_sweep(summary, tmp_path / "all", "tiny-r")}
    assert {"lambda_1.png", "h_ks.png", "triple_linkage_r.png"} <= names


def test_triple_linkage_curvature_and_angles_in_a_scene(tmp_path):
    """Curvature (both routes) and the angle test on the generic route.  On a surface the
    plane of v̂ and its one normal direction is the tangent plane: K(v̂, e₁) is the Gaussian
    curvature at the sample, an independent route (``Mechanism.gaussian_curvature``, the
    intrinsic formula in a chart); route (b) meets it to rounding, route (a), a central
    difference in dt, to its O(dt²) (measured 1.6e-5 here at dt = 0.01 and |K| < 0.83; the
    bound 1e-4 leaves 6×).  The angles are those of
    `mechanism_angles` from the same state, bit for bit."""
    from charts.analyses.mechanism_angles import mechanism_angles

    sc = parse_scene({"mechanism": {"name": "triple_linkage", "r": R}, "initial": {"seed": 2},
                      "run": {"t_final": 2.0, "t_transient": 1.0},
                      "effects": {"curvature": {"sample_every": 0.5},
                                  "angles": {"sample_every": 0.5}}})
    assert sc.effects["angles"]["variant"] == "restricted"
    assert sc.effects["curvature"]["n_directions"] == 1
    res = run_scene(sc, tmp_path / "out", quiet=True)
    mech = charts.triple_linkage(R)
    with np.load(tmp_path / "out" / "arrays.npz") as a:
        Kn, Ke, phi, t_phi = (a[k] for k in ("curvature_numerical", "curvature_exact",
                                            "angles_restricted", "angles_t"))
    assert Ke.shape == Kn.shape == (4, 1)
    Y = np.array(res["final_state"]["q"])                   # (the last sample's state)
    K = mech.gaussian_curvature(mech.project_point(Y))
    assert Ke[-1, 0] == pytest.approx(K, abs=1e-10)
    assert np.max(np.abs(Kn - Ke)) < 1e-4
    q, v = mech.random_state(seed=2)
    api = mechanism_angles(mech, q, v, 2.0, t_transient=1.0, sample_every=0.5, seed=2)
    assert np.array_equal(phi, api.phi_restricted)
    assert np.array_equal(t_phi, api.t - 1.0)
    assert res["results"]["angles"]["forward_exponents"] == api.forward_exponents.tolist()
    assert "restricted" in res["results"]["angles"] and "full" not in res["results"]["angles"]
