"""Every result type round-trips through save/load (NetCDF) with identical arrays and
attributes; load returns the saved type; a missing extra gives an error that names it."""
import json
import sys

import numpy as np
import pytest

import charts
from charts.io.archive import KINDS, load
from charts.version import source_version
from charts.runs.netcdf_results import SceneResult, SweepTable

SYS4 = charts.RotorSystem(4)
TH4, U4 = SYS4.random_state(0)
SYS3 = charts.RotorSystem(3)
TH3, U3 = SYS3.random_state(7)


def _section(t, y):
    return np.sin(y[0])


@pytest.fixture(scope="module")
def results():
    w = charts.waveform(SYS4, TH4, U4, 60.0)
    return {
        "trajectory": charts.integrate(SYS3, TH3, U3, 12.0, events=[_section, lambda t, y: y[3]],
                                       transport=SYS3.project_tangent(TH3, np.array([1.0, 0, 0]))),
        "trajectory_plain": charts.integrate(SYS4, TH4, U4, 2.0, method="rk4", formulation="ambient"),
        # a starting chart that the best one (3) replaces at t = 1.17: the switches tell them apart
        "trajectory_chart": charts.integrate(SYS4, TH4, U4, 2.0, method="rk4", chart=2,
                                             t_eval=np.linspace(0.0, 2.0, 21)),
        "lyapunov": charts.lyapunov_spectrum(SYS4, TH4, U4, 20.0, t_transient=1.0),
        "curvature": charts.curvature_along_trajectory(SYS4, TH4, U4, 3.0, t_transient=1.0),
        "angles": charts.hyperbolicity_angles(SYS4, TH4, U4, 5.0, t_transient=5.0),
        "covariant": charts.covariant_lyapunov_vectors(SYS4, TH4, U4, 2.0, t_transient=2.0,
                                                       keep_vectors=True),
        "waveform": w,
        "spectrum": charts.power_spectrum(w.u[:, 0], w.dt_sample, segment_time=10.0),
        "ensemble": charts.lyapunov_ensemble(SYS4, 2, 10.0, t_transient=1.0, workers=1),
        "angle_ensemble": charts.hyperbolicity_ensemble(SYS4, 2, 5.0, t_transient=5.0, workers=1),
        "angle_tally": charts.hyperbolicity_tally(SYS4, 2, 5.0, t_transient=5.0, workers=1),
    }


def _same(a, b, where):
    """Deep equality: arrays equal in value and dtype, dicts/lists element by element."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        assert isinstance(a, np.ndarray) and isinstance(b, np.ndarray), where
        assert a.dtype == b.dtype and a.shape == b.shape, (where, a.dtype, b.dtype)
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), where
    elif isinstance(a, dict):
        assert isinstance(b, dict) and a.keys() == b.keys(), where
        for k in a:
            _same(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, (list, tuple)) and not isinstance(a, str):
        assert type(a) is type(b) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{where}[{i}]")
    elif hasattr(a, "__dict__") and not isinstance(a, (int, float, str)):
        fields = {k: v for k, v in vars(a).items() if k != "sol"}
        _same(fields, {k: v for k, v in vars(b).items() if k != "sol"}, where)
    else:
        assert a == b and type(a) is type(b), (where, a, b)


@pytest.mark.parametrize("name", ["trajectory", "trajectory_plain", "trajectory_chart", "lyapunov",
                                  "curvature", "angles", "covariant", "waveform", "spectrum",
                                  "ensemble", "angle_ensemble", "angle_tally"])
def test_round_trip_identical(results, name, tmp_path):
    res = results[name]
    path = res.save(tmp_path / f"{name}.nc")
    back = load(path)
    assert type(back) is type(res)
    if name == "spectrum":
        _same(tuple(res), tuple(back), name)
        assert back.params == res.params
    elif name.endswith("ensemble"):
        assert len(back) == len(res)
        for i, (m, mb) in enumerate(zip(res, back)):
            _same(m, mb, f"member {i}")
        _same(res.exponents, back.exponents, "exponents")
        _same(res.stderr, back.stderr, "stderr")
        assert back.params == res.params
    else:
        _same(res, back, name)
    assert back == res and not back != res          # == compares values (arrays included)


def test_every_result_type_prints_as_one_short_line(results):
    """Every type of `KINDS` prints as one line that names it and its main numbers (the
    system, the span, the exponents or minima), never its arrays: a run of many samples, a
    spectrum of 62 exponents, a scene of many arrays or a table of many columns too."""
    import importlib

    from charts.analyses.hyperbolicity import AngleResult
    from charts.analyses.mechanism_lyapunov import lyapunov_spectrum as mechanism_lyapunov
    L = charts.LinkageSystem(0.1)
    every = dict(results, linkage=charts.linkage_run(L, *L.random_state(seed=2), 2.0,
                                                     t_transient=0.0, n_batches=2),
                 wide=_tiny_lyapunov({"n": 64, "t_final": 10.0}),
                 mechanism_lyapunov=mechanism_lyapunov(charts.triple_linkage(0.3),
                                                       *charts.triple_linkage(0.3).random_state(1),
                                                       2.0, t_transient=0.0, n_batches=2),
                 mechanism_angles=charts.hyperbolicity_angles(
                     charts.triple_linkage(0.3), *charts.triple_linkage(0.3).random_state(1),
                     1.0, t_transient=0.0),
                 scene=SceneResult({"scene": {"name": "tiny"}, "status": "complete"},
                                   {f"array_{i}": np.zeros(3) for i in range(40)}, "name = 'tiny'"),
                 sweep=SweepTable({f"column_{i}": np.arange(5) for i in range(40)}))
    every["wide"].exponents, every["wide"].stderr = np.linspace(0.3, 0.01, 62), np.full(62, 1e-3)
    classes = {getattr(importlib.import_module(m), c) for m, c in
               (path.split(":") for path in KINDS.values())}
    assert classes == {type(r) for r in every.values()}       # one of each kind
    for name, res in every.items():
        text = repr(res)
        assert len(text) < 300 and "\n" not in text and text.startswith(f"{type(res).__name__}("), \
            (name, text)
        assert "array(" not in text and "[[" not in text, (name, text)
    assert repr(results["lyapunov"]).startswith("LyapunovResult(N = 4, T = 20, λ = ")
    assert "(58 more)" in repr(every["wide"])
    assert "2 AngleResult members" in repr(results["angle_ensemble"])
    assert "100 angles of 2 members" in repr(results["angle_tally"])
    assert repr(every["sweep"]) == "SweepTable(5 points, 40 columns)"
    angles = results["angles"]
    assert f"{angles.t.size} samples, t = {angles.t[0]:g}…{angles.t[-1]:g}" in repr(angles)
    assert AngleResult.__repr__ is charts.LyapunovResult.__repr__     # one home


def test_results_compare_by_value(results):
    import copy
    for name, res in results.items():
        assert res == copy.deepcopy(res), name
    changed = copy.deepcopy(results["lyapunov"])
    changed.exponents[0] = np.nextafter(changed.exponents[0], 1.0)
    assert changed != results["lyapunov"]
    ens = copy.deepcopy(results["ensemble"])
    ens.members[1].batches[0, 0] += 1e-12                # a member's field, deep inside
    assert ens != results["ensemble"]
    assert results["lyapunov"] != results["angles"]      # another type: not equal, no error
    with pytest.raises(TypeError):
        hash(results["lyapunov"])                        # mutable results are not hashable


def test_ensembles_plot_themselves(results):
    from matplotlib.collections import LineCollection  # noqa: F401  (matplotlib present)
    ens = results["ensemble"]
    fig, ax = ens.plot()
    dots = [ln for ln in ax.lines if ln.get_marker() == "o"]
    assert len(dots) == ens.exponents.size and all(len(d.get_xdata()) == len(ens) for d in dots)
    assert [t.get_text() for t in ax.get_xticklabels()] == ["λ1", "λ2"]
    fig, ax = ens.plot(kind="spectrum")
    assert ax.get_xlabel() == "i / (N − 2)"
    with pytest.raises(ValueError, match="'members' or 'spectrum'"):
        ens.plot(kind="histogram")
    angles = results["angle_ensemble"]
    fig, axes = angles.plot()
    pooled = sum(len(m.phi_full) for m in angles)
    assert f"{pooled} samples" in axes[0].get_title() and "2 members pooled" in fig._suptitle.get_text()


def test_datasets_have_named_dims_units_and_stamps(results):
    for name, res in results.items():
        ds = res.to_xarray()
        assert ds.attrs["charts_kind"] in KINDS and ds.attrs["charts_version"] == source_version()
        for v in list(ds.data_vars.values()) + list(ds.coords.values()):
            assert "units" in v.attrs, (name, v.name)
            assert not any(d.startswith("dim_") for d in v.dims), (name, v.dims)
    # indices the paper counts from 1 are 1…k in the files; rotors count from 0
    assert list(results["curvature"].to_xarray()["direction"].values) == [1, 2]
    assert list(results["angles"].to_xarray()["vector"].values)[0] == 1
    cov = results["covariant"].to_xarray()
    assert cov["clv"].values[0] == 1 and cov["component"].values[0] == "theta_0"
    assert list(cov["component_units"].values[[0, -1]]) == ["rad", "rad / time"]
    assert list(results["trajectory"].to_xarray()["rotor"].values) == [0, 1, 2]
    ds = results["lyapunov"].to_xarray()
    assert ds["exponents"].attrs["units"] == "1 / time"
    assert "λ₁ the largest" in ds["exponents"].attrs["long_name"]
    assert "2N−2" in ds["full_spectrum"].attrs["long_name"]
    assert list(ds["spectrum_index"].values) == list(range(1, ds.sizes["spectrum_index"] + 1))
    assert "from 1" in ds["spectrum_index"].attrs["long_name"]          # as exponent
    assert ds.attrs["params_t_final"] == 20.0 and "params" not in ds.attrs   # no JSON copy
    # an ensemble's title names what its members hold and the function that ran them
    assert results["ensemble"].to_xarray().attrs["title"] == (
        "charts: ensemble of Lyapunov spectra of independent trajectories "
        "(charts.lyapunov_ensemble)")
    assert "(charts.hyperbolicity_ensemble)" in results["angle_ensemble"].to_xarray().attrs["title"]


def test_scene_writes_netcdf_beside_result_json(tmp_path):
    text = """name = "tiny"
[system]
n = 3
[initial]
seed = 1
[integrator]
dt = 0.01
[run]
t_final = 20.0
t_transient = 1.0
sample_dt = 0.1
[effects.lyapunov]
[effects.drift]
[effects.curvature]
route = "both"
"""
    src = tmp_path / "tiny.toml"
    src.write_text(text)
    scene = charts.load_scene(src)
    out = tmp_path / "out"
    result = charts.run_scene(scene, out, quiet=True)
    assert "results.nc" in result["files"] and (out / "results.nc").exists()
    back = load(out / "results.nc")
    assert isinstance(back, SceneResult)
    assert back.scene_text == text
    with np.load(out / "arrays.npz") as npz:
        assert sorted(npz.files) == sorted(back.arrays)
        for k in npz.files:
            assert np.array_equal(npz[k], back.arrays[k]) and npz[k].dtype == back.arrays[k].dtype
    on_disk = json.loads((out / "result.json").read_text())
    assert back.result["results"] == on_disk["results"]
    assert back.result["scene"] == on_disk["scene"]
    ds = back.to_xarray()
    assert ds["lyapunov_history"].dims == ("lyapunov_record", "exponent")
    assert list(ds["exponent"].values) == list(range(1, ds.sizes["exponent"] + 1))  # λ₁ first
    assert ds["drift_t"].attrs["units"] == "time"
    assert ds["curvature_exact"].dims == ("curvature_sample", "direction")
    back.save(tmp_path / "again.nc")
    again = load(tmp_path / "again.nc")
    _same(back.arrays, again.arrays, "arrays")
    assert again.result == back.result


def test_sweep_table_round_trip(tmp_path):
    csv = tmp_path / "sweep.csv"
    csv.write_text("index,point_id,status,n,lyap_1,error\n0,a1,ok,3,0.5001,\n1,b2,failed,4,,boom\n")
    table = SweepTable.from_csv(csv)
    assert table.columns["index"].dtype.kind == "i" and table.columns["n"].tolist() == [3, 4]
    assert np.isnan(table.columns["lyap_1"][1]) and table.columns["status"].tolist() == ["ok", "failed"]
    back = load(table.save(tmp_path / "sweep.nc"))
    assert isinstance(back, SweepTable) and list(back.columns) == list(table.columns)
    _same(table.columns, back.columns, "columns")
    assert back.attrs == table.attrs


def test_sweep_table_columns_have_units_and_empty_text_stays_text(tmp_path):
    csv = tmp_path / "sweep.csv"
    csv.write_text("index,status,lambda_1,lambda_1_se,Kmean_exact_1,phi_full_min,t_final,"
                   "lambda_2,error\n0,ok,0.5,0.01,-0.2,0.03,20.0,,\n1,ok,0.4,0.02,-0.1,0.02,20.0,,\n")
    table = SweepTable.from_csv(csv)
    assert table.columns["error"].tolist() == ["", ""]                 # text, not NaN
    assert np.isnan(table.columns["lambda_2"]).all()                   # a number column, empty
    import xarray as xr
    with xr.open_dataset(table.save(tmp_path / "sweep.nc"), engine="h5netcdf") as ds:
        units = {k: v.attrs["units"] for k, v in ds.data_vars.items()}
        assert ds["error"].values.tolist() == ["", ""]
    assert units == {"index": "1", "status": "1", "lambda_1": "1 / time",
                     "lambda_1_se": "1 / time", "Kmean_exact_1": "1 / rad^2",
                     "phi_full_min": "rad", "t_final": "time", "lambda_2": "1 / time",
                     "error": "1"}
    back = load(tmp_path / "sweep.nc")
    assert back.columns["error"].tolist() == ["", ""] and back.columns["error"].dtype.kind == "U"


def test_missing_extra_is_named(monkeypatch, results, tmp_path):
    monkeypatch.setitem(sys.modules, "xarray", None)
    with pytest.raises(ImportError, match=r"charts\[io\]"):
        results["lyapunov"].save(tmp_path / "x.nc")


def test_load_refuses_foreign_files(tmp_path):
    import xarray as xr
    xr.Dataset({"a": ("x", [1.0])}).to_netcdf(tmp_path / "f.nc", engine="h5netcdf")
    with pytest.raises(ValueError, match="not a charts result"):
        load(tmp_path / "f.nc")
    with pytest.raises(FileNotFoundError):
        load(tmp_path / "missing.nc")


def _plain(a, key, cast=float):
    """The native attribute ``key`` of a plain file as ``cast`` (None where it is absent:
    a setting that was None, e.g. ``project_every``)."""
    return cast(a[key]) if key in a else None


def _member_view(ds, i):
    """Member ``i``'s settings in an ensemble file as a member's own file names them
    (``params_dt``): the shared attributes ``member.params.*`` and row i of the variables."""
    prefix = "member.params."
    a = {f"params_{k[len(prefix):]}": v for k, v in ds.attrs.items() if k.startswith(prefix)}
    a.update({f"params_{k[len(prefix):]}": ds[k].values[i] for k in ds.data_vars
              if k.startswith(prefix)})
    return a


def _rebuild(ds, name, a=None):
    """The call that made the file ``ds`` (or its member of settings ``a``), repeated from its
    plain attributes alone (no charts reading): the system, the initial state and every
    setting."""
    a = ds.attrs if a is None else a
    system = charts.RotorSystem(int(a["params_n"]), masses=np.atleast_1d(a["params_masses"]).tolist(),
                                weights=np.atleast_1d(a["params_weights"]).tolist(),
                                level=float(a["params_level"]))
    state = (np.atleast_1d(a["params_theta0"]), np.atleast_1d(a["params_u0"]))
    if name.startswith("trajectory"):
        rk4, chart = a["method"] == "rk4", a["formulation"] == "chart"
        # only what applies, not even as None: the method's own options, the chart's for it
        named = {k for k in a if k.startswith("options_")} | {
            k for k in a.get("charts_none", "").split() if k.startswith("options_")}
        assert {"options_dt"} & named == ({"options_dt"} if rk4 else set())
        assert {"options_rtol", "options_atol"} & named == (set() if rk4 else {"options_rtol",
                                                                               "options_atol"})
        assert {"options_tau", "options_chart"} & named == (
            {"options_tau", "options_chart"} if chart else set())
        assert set(a.get("charts_none", "").split()) & named <= {"options_chart"}
        span = np.atleast_1d(a["options_t_span"])
        return charts.integrate(
            system, *state, float(span[1]), method=a["method"], formulation=a["formulation"],
            dt=_plain(a, "options_dt"), rtol=_plain(a, "options_rtol"),
            atol=_plain(a, "options_atol"), project=bool(a["options_project"]),
            **({"tau": float(a["options_tau"]), "chart": _plain(a, "options_chart", int)}
               if chart else {}),
            transport=ds["transported"].values[0] if "transported" in ds else None,
            t_eval=ds["t"].values if a["options_output"] == "t_eval" else None)
    common = dict(dt=float(a["params_dt"]), t_transient=float(a["params_t_transient"]),
                  project_every=_plain(a, "params_project_every"),
                  seed=_plain(a, "params_vectors_seed", int))
    t_final = float(a["params_t_final"])
    if name == "lyapunov":
        return charts.lyapunov_spectrum(
            system, *state, t_final, n_exponents=int(a["params_n_exponents"]),
            inner=str(a["params_inner"]), space=str(a["params_space"]),
            n_batches=int(a["params_n_batches"]), reorth_every=float(a["params_reorth_every"]),
            record_every=float(a["params_record_every"]), **common)
    if name == "curvature":
        return charts.curvature_along_trajectory(
            system, *state, t_final, sample_every=float(a["params_sample_every"]),
            exact=bool(a["params_exact"]), **common)
    if name == "angles":
        return charts.hyperbolicity_angles(
            system, *state, t_final, n_unstable=int(a["params_n_unstable"]),
            sample_every=float(a["params_sample_every"]),
            checkpoint_every=float(a["params_checkpoint_every"]), **common)
    if name == "covariant":
        return charts.covariant_lyapunov_vectors(
            system, *state, t_final, variant=str(a["params_variant"]),
            n_unstable=int(a["params_n_unstable"]), sample_every=float(a["params_sample_every"]),
            keep_vectors=bool(a["params_keep_vectors"]), **common)
    if name == "waveform":
        common.pop("seed")
        return charts.waveform(system, *state, t_final, sample_every=float(a["dt_sample"]),
                               **common)
    raise AssertionError(name)


#: A variable of each result type that the repeated call must give bit for bit.
REBUILT = {"trajectory": "theta", "trajectory_plain": "theta", "trajectory_chart": "theta",
           "lyapunov": "exponents",
           "curvature": "K_numeric", "angles": "phi_restricted", "covariant": "vectors",
           "waveform": "u"}


@pytest.mark.parametrize("name", ["trajectory", "trajectory_plain", "trajectory_chart", "lyapunov",
                                  "curvature", "angles", "covariant", "waveform", "ensemble",
                                  "angle_ensemble"])
def test_a_reader_without_charts_can_rebuild_the_call(results, name, tmp_path):
    """Opened with plain xarray (no charts): CF global attributes, every dimension labelled,
    units on every variable, and the system (N, masses, weights, level) as native attributes;
    for every rotor result also the initial state and the settings, from which the same call
    gives the same numbers."""
    import xarray as xr
    path = results[name].save(tmp_path / f"{name}.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert ds.attrs["Conventions"].startswith("CF-")
        for key in ("title", "history", "source", "references"):
            assert ds.attrs[key], key
        # the settings' units, which attributes cannot carry, are said once in the CF comment
        assert "time units of the flow" in ds.attrs["comment"]
        assert "vectors_seed seeds the random tangent vectors" in ds.attrs["comment"]
        assert all(dim in ds.coords for dim in ds.sizes), (name, set(ds.sizes) - set(ds.coords))
        for v in list(ds.data_vars.values()) + list(ds.coords.values()):
            assert "units" in v.attrs, (name, v.name)
        n = int(ds.attrs["params_n"])
        masses = np.atleast_1d(ds.attrs["params_masses"])
        weights = np.atleast_1d(ds.attrs["params_weights"])
        assert masses.shape == weights.shape == (n,)
        assert float(ds.attrs["params_level"]) == 0.0
        if name.startswith("trajectory"):
            assert list(ds["rotor"].values) == list(range(n))          # from 0, as scenes
        if name in REBUILT:
            again = _rebuild(ds, name).to_xarray()
            var = REBUILT[name]
            assert np.array_equal(again[var].values, ds[var].values), name
            if name.startswith("trajectory"):            # and the same chart switches
                for key in ("switch_t", "switch_from", "switch_to", "t"):
                    assert np.array_equal(again[key].values, ds[key].values), (name, key)
        if name == "lyapunov":
            assert np.array_equal(again["energy_share_counts"].values,
                                  ds["energy_share_counts"].values)
        if name.endswith("ensemble"):       # each member from its row, the whole from the top
            member = "lyapunov" if name == "ensemble" else "angles"
            for i in range(ds.sizes["member"]):
                again = _rebuild(ds, member, _member_view(ds, i)).to_xarray()
                assert np.array_equal(again[REBUILT[member]].values,
                                      ds[REBUILT[member]].values[i]), (name, i)
            a = ds.attrs
            system = charts.RotorSystem(n, masses=masses.tolist(), weights=weights.tolist())
            top = dict(t_transient=float(a["params_t_transient"]), dt=float(a["params_dt"]),
                       seed=int(a["params_members_seed"]), speed=float(a["params_speed"]),
                       workers=1,
                       sample_every=float(a["params_sample_every"]),
                       n_unstable=int(a["params_n_unstable"])) if member == "angles" else dict(
                       t_transient=float(a["params_t_transient"]), dt=float(a["params_dt"]),
                       seed=int(a["params_members_seed"]), speed=float(a["params_speed"]),
                       workers=1,
                       n_exponents=int(a["params_n_exponents"]),
                       reorth_every=float(a["params_reorth_every"]))
            run = charts.lyapunov_ensemble if member == "lyapunov" else charts.hyperbolicity_ensemble
            again = run(system, int(a["params_n_trajectories"]), float(a["params_t_final"]), **top)
            assert again == results[name]


def test_an_ensemble_file_keeps_its_members_settings_flat(results, tmp_path):
    """No JSON inside JSON: the members' shared settings are one attribute each
    (``member.params.n``; lists of numbers native), the differing ones (the seed) a variable
    along ``member``, a nested setting entry by entry (``member.params.curvature.route``);
    loading gives every member its own settings back."""
    import copy

    import xarray as xr
    ens = results["ensemble"]
    path = ens.save(tmp_path / "ensemble.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert "member_attrs" not in ds.attrs
        assert int(ds.attrs["member.params.n"]) == ens.params["n"]
        assert np.array_equal(ds.attrs["member.params.masses"], ens.members[0].params["masses"])
        for seed in ("vectors_seed", "state_seed"):     # each member's, a variable along member
            assert list(ds[f"member.params.{seed}"].values) == [m.params[seed]
                                                                 for m in ens.members]
        assert not any(isinstance(v, str) and v.startswith("json:") for v in ds.attrs.values())
    back = load(path)
    assert [m.params for m in back.members] == [m.params for m in ens.members]
    nested = copy.deepcopy(ens)             # a nested setting: its entries, native, one level down
    for m, every in zip(nested.members, (0.1, 0.2)):
        m.params["curvature"] = {"sample_every": every, "exact": True, "route": "both"}
    with xr.open_dataset(nested.save(tmp_path / "nested.nc"), engine="h5netcdf") as ds:
        assert ds["member.params.curvature.sample_every"].values.tolist() == [0.1, 0.2]
        assert ds.attrs["member.params.curvature.route"] == "both"
        assert ds.attrs["member.params.curvature.exact"] == 1
        assert "member.params.curvature.exact" in ds.attrs["charts_booleans"].split()
        assert not any(isinstance(v, str) and v.startswith("json:") for v in ds.attrs.values())
    back = load(tmp_path / "nested.nc")
    for m, mb in zip(nested.members, back.members):
        _same(mb.params, m.params, "member params")


@pytest.mark.parametrize("name", ["ensemble", "angle_ensemble"])
def test_an_ensemble_file_keeps_units_and_states_as_numbers(results, name, tmp_path):
    """Every variable and coordinate of an ensemble file has the units and the description of
    the same variable in a member's file; the members' initial states are float arrays over
    (member, rotor), not JSON text; files that held them as JSON still load."""
    import xarray as xr
    ens = results[name]
    with xr.open_dataset(ens.save(tmp_path / "e.nc"), engine="h5netcdf") as ds, \
            xr.open_dataset(ens.members[0].save(tmp_path / "m.nc"), engine="h5netcdf") as one:
        for k, v in one.variables.items():
            assert ds[k].attrs == v.attrs, (name, k, ds[k].attrs, v.attrs)
        theta0 = ds["member.params.theta0"]
        assert theta0.dims == ("member", "rotor") and theta0.dtype == np.float64
        assert theta0.attrs["units"] == "rad" and ds["member.params.u0"].attrs["units"] == "rad / time"
        assert np.array_equal(theta0.values, [m.params["theta0"] for m in ens.members])
        assert not any(v.dtype.kind in "OUS" for v in ds.data_vars.values()), name
        ds = ds.load()
    old = ds.copy()                       # the earlier form: JSON text along member
    for key in ("member.params.theta0", "member.params.u0"):
        old[key] = ("member", ["json:" + json.dumps(row.tolist()) for row in ds[key].values])
    from charts.analyses.ensemble import EnsembleResult
    assert EnsembleResult.from_xarray(old) == ens


def test_an_ensemble_records_its_resolved_settings(results, tmp_path):
    """The ensemble's params are the settings as resolved (defaults filled in): a call that
    writes a default gives an equal result, and the file's top level names every setting."""
    ens = results["ensemble"]
    written = charts.lyapunov_ensemble(SYS4, 2, 10, speed=1, t_transient=1.0, workers=1,
                                       dt=0.01, n_batches=20, inner="theta")
    assert written == ens and written.params == ens.params
    for key in ("dt", "reorth_every", "n_exponents", "inner", "space", "record_every",
                "n_batches", "project_every"):
        assert key in ens.params, key
    assert ens.params["dt"] == 0.01 and ens.params["t_final"] == 10.0
    assert type(written.params["speed"]) is float and ens.params["members_seed"] == 0
    assert "theta0" not in ens.params
    ds = ens.to_xarray()
    assert ds.attrs["params_dt"] == 0.01 and ds.attrs["params_n_trajectories"] == 2


@pytest.mark.parametrize("content, says", [
    (b"", "is empty"), (b"hello\n", "not a NetCDF-4 file"), (b"CDF\x01" + bytes(20), "NetCDF-3"),
    (b"\x89HDF\r\n\x1a\n" + bytes(40), "could not be read as NetCDF-4")])
def test_load_names_the_file_and_what_it_is_not(tmp_path, content, says):
    path = tmp_path / "f.nc"
    path.write_bytes(content)
    with pytest.raises(ValueError, match=rf"f\.nc .*{says}|f\.nc {says}"):
        load(path)


def test_load_refuses_a_folder_by_name(tmp_path):
    (tmp_path / "d.nc").mkdir()
    with pytest.raises(ValueError, match=r"d\.nc is not a regular file"):
        load(tmp_path / "d.nc")


def _native_form(value) -> bool:
    """Whether NetCDF holds a decoded setting natively (written here apart from the package):
    a number, a string, a non-empty list of integers only, of floats only or of strings only;
    a boolean or None (an integer, no attribute: their names are listed)."""
    if value is None or isinstance(value, (bool, float)):
        return True
    if isinstance(value, int):
        return -2 ** 63 <= value < 2 ** 63
    if isinstance(value, str):
        return not value.startswith("json:")
    if isinstance(value, list) and value:
        return any(all(type(x) is t for x in value) for t in (int, float, str))
    return False                            # a dict, an empty list, ...


def test_no_attribute_is_json_where_netcdf_has_a_native_form(results, tmp_path):
    """Every result file (a linkage run's too) holds its settings as native attributes, the
    settings dicts entry by entry with no JSON copy; ``json:`` text only for a value NetCDF
    has no form for; and the file loads equal to the result."""
    import xarray as xr
    L = charts.LinkageSystem(0.1)
    files = dict(results, linkage=charts.linkage_run(L, *L.random_state(seed=2), 2.0,
                                                     t_transient=0.0, n_batches=2))
    for name, res in files.items():
        path = res.save(tmp_path / f"{name}.nc")
        with xr.open_dataset(path, engine="h5netcdf") as ds:
            assert not {"params", "options", "drift"} & set(ds.attrs), name
            for key, value in ds.attrs.items():
                if isinstance(value, str) and value.startswith("json:"):
                    assert not _native_form(json.loads(value[5:])), (name, key, value)
            assert any(k.startswith("params_") for k in ds.attrs), name
        assert load(path) == res, name


#: Settings of every kind a file must give back as they were: a boolean stays a boolean, an
#: int an int, a list of one entry a list, None None; nested dicts (a member's curvature
#: settings); and what NetCDF cannot hold natively (an empty list or dict, lists of lists or
#: of mixed types, keys that cannot be parts of names, a string that looks like JSON, an
#: integer beyond int64), which stays JSON.
AWKWARD = dict(n=4, dt=0.01, vectors_seed=7, exact=True, project=False, project_every=None,
               masses=[1.0], counts=[3], names=["theta"], label="θ₀ ≤ π", empty=[],
               mixed=[1, "a", None], rows=[[1.0, 2.0]], dotted={"a.b": 1},
               text="json:not json", huge=2 ** 70,
               curvature={"sample_every": 0.1, "exact": False, "none": {},
                          "route": {"numeric": True, "every": [2]}})


def _tiny_lyapunov(params):
    return charts.LyapunovResult(np.zeros(2), np.zeros(2), None, np.zeros(1), np.zeros((1, 2)),
                                 np.zeros((2, 2)), params=params)


def test_settings_of_every_type_come_back_with_their_types(tmp_path):
    """Booleans, None, lists (of one entry too) and nested dicts are native attributes named
    in ``charts_booleans``, ``charts_none`` and ``charts_lists``; what has no native form is
    JSON; a result and an ensemble of such results load with every type as saved."""
    import xarray as xr

    from charts.analyses.ensemble import EnsembleResult
    lyap = _tiny_lyapunov(AWKWARD)
    with xr.open_dataset(lyap.save(tmp_path / "l.nc"), engine="h5netcdf") as ds:
        a = ds.attrs
        assert a["params_exact"] == 1 and a["params_curvature.sample_every"] == 0.1
        assert a["params_curvature.route.every"] == 2 and "params_project_every" not in a
        assert set(a["charts_booleans"].split()) == {"params_exact", "params_project",
                                                     "params_curvature.exact",
                                                     "params_curvature.route.numeric"}
        assert a["charts_none"].split() == ["params_project_every"]
        assert set(a["charts_lists"].split()) == {"params_masses", "params_counts", "params_names",
                                                  "params_curvature.route.every"}
        assert {k for k, v in a.items() if isinstance(v, str) and v.startswith("json:")} == {
            "params_empty", "params_mixed", "params_rows", "params_dotted", "params_text",
            "params_huge", "params_curvature.none"}
    _same(load(tmp_path / "l.nc").params, AWKWARD, "params")
    members = [_tiny_lyapunov({**AWKWARD, "vectors_seed": seed, "curvature": {
        **AWKWARD["curvature"], "sample_every": every}}) for seed, every in ((1, 0.1), (2, 0.2))]
    ens = EnsembleResult(members, params={"n": 4, "exact": True, "masses": [1.0]})
    with xr.open_dataset(ens.save(tmp_path / "e.nc"), engine="h5netcdf") as ds:
        assert ds["member.params.curvature.sample_every"].values.tolist() == [0.1, 0.2]
        assert "member.params.curvature.route.numeric" in ds.attrs["charts_booleans"].split()
        assert "member.params.counts" in ds.attrs["charts_lists"].split()
        assert "member.params.project_every" in ds.attrs["charts_none"].split()
    back = load(tmp_path / "e.nc")
    _same(back.params, ens.params, "params")
    for m, mb in zip(members, back.members):
        _same(mb.params, m.params, "member params")


def _as_written_before(ds):
    """``ds`` (read from a file) as the code before the native settings wrote it: each
    settings dict also as one JSON text, the copy that load read, beside its entries
    (booleans 1 or 0, None left out, no lists of names); other values that are not numbers
    or strings, and the members' shared booleans, None and lists of strings, as JSON."""
    from charts.io.archive import attributes
    from charts.io.file_settings import MARKS
    old = ds.copy()
    marks = {m: str(ds.attrs.get(m, "")).split() for m in MARKS}
    old.attrs = {k: v for k, v in ds.attrs.items() if k not in MARKS}
    for key, value in attributes(ds).items():
        if isinstance(value, bool) or not isinstance(value, (str, int, float)):
            old.attrs[key] = "json:" + json.dumps(value)
    for key in marks["charts_booleans"] + marks["charts_none"] + marks["charts_lists"]:
        if key.startswith("member."):
            value = (None if key in marks["charts_none"] else bool(ds.attrs[key])
                     if key in marks["charts_booleans"] else np.atleast_1d(ds.attrs[key]).tolist())
            if not isinstance(value, list) or isinstance(value[0], str):
                old.attrs[key] = "json:" + json.dumps(value)
    return old


def test_files_with_the_json_copy_of_the_settings_still_load(results, tmp_path):
    """A file written before the native attributes became the copy that load reads (each
    settings dict also as JSON text, booleans among its entries as 1 or 0) loads equal."""
    import xarray as xr

    from charts.io.archive import save
    for name, res in results.items():
        ds = xr.load_dataset(res.save(tmp_path / f"{name}.nc"), engine="h5netcdf")
        old = _as_written_before(ds)
        assert old.attrs["params"].startswith("json:{"), name
        assert not any(k.startswith("charts_") and k != "charts_kind" and k != "charts_version"
                       for k in old.attrs), name
        back = load(save(old, tmp_path / f"old_{name}.nc"))
        assert back == res, name
        for field in ("params", "options", "drift"):       # types too: a boolean stays one
            if hasattr(res, field):
                _same(getattr(back, field), getattr(res, field), f"{name}.{field}")
        for i, (m, mb) in enumerate(zip(getattr(res, "members", []), back.members if
                                        hasattr(res, "members") else [])):
            _same(mb.params, m.params, f"{name} member {i}")
