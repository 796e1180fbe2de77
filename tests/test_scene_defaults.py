"""A scene's defaults are the API's: every key a scene forwards to an API call takes that
call's default from its signature, so a scene that writes nothing and the API call that
writes nothing compute the same numbers, bit for bit."""
import inspect

import numpy as np
import pytest

from charts import (RotorSystem, covariant_lyapunov_vectors, curvature_along_trajectory,
                    hyperbolicity_angles, lyapunov_spectrum, waveform)
from charts.analyses.linkage import linkage_run
from charts.analyses.transients import scaled_transient
from charts.analyses.linkage_angles import linkage_angles
from charts.runs.runner import run_scene
from charts.runs.scene import parse_scene
from charts.runs.scene_schema import API, EFFECTS, SCHEMA, FromAPI


def default(fn, name):
    return inspect.signature(fn).parameters[name].default


#: (section, key) of the scene → (API function, parameter) it forwards to.
FORWARDED = {
    ("integrator", "project_every"): [(f, "project_every") for f in (
        lyapunov_spectrum, curvature_along_trajectory, hyperbolicity_angles,
        covariant_lyapunov_vectors, waveform, linkage_run, linkage_angles)],
    ("effects.lyapunov", "n_batches"): [(lyapunov_spectrum, "n_batches"), (linkage_run, "n_batches")],
    ("effects.lyapunov", "reorth_every"): [(lyapunov_spectrum, "reorth_every"),
                                           (linkage_run, "reorth_every")],
    ("effects.lyapunov", "inner_product"): [(lyapunov_spectrum, "inner")],
    ("effects.curvature", "sample_every"): [(curvature_along_trajectory, "sample_every")],
    ("effects.angles", "sample_every"): [(hyperbolicity_angles, "sample_every"),
                                         (linkage_angles, "sample_every")],
    ("effects.clv", "sample_every"): [(covariant_lyapunov_vectors, "sample_every")],
}


def _key(section, key):
    table = EFFECTS[section.split(".")[1]] if section.startswith("effects.") else SCHEMA[section]
    return table[key]


@pytest.mark.parametrize("where", sorted(FORWARDED))
def test_schema_defaults_are_the_apis(where):
    k = _key(*where)
    assert isinstance(k.default, FromAPI)           # read from the signature, not copied
    for fn, name in FORWARDED[where]:
        assert k.value == default(fn, name), (where, fn.__name__)


#: (section, key) of a linkage scene whose default is another call's than a rotor scene's.
LINKAGE_FORWARDED = {("effects.curvature", "sample_every"): (linkage_run, "sample_every")}


@pytest.mark.parametrize("where", sorted(LINKAGE_FORWARDED))
def test_a_linkage_scenes_defaults_are_its_apis(where):
    """Read from linkage_run's signature, not copied; a linkage scene that leaves the key
    out gets it (at the default dt as written there), a rotor scene the rotors' call's."""
    k = _key(*where)
    fn, name = LINKAGE_FORWARDED[where]
    assert isinstance(k.linkage, FromAPI) and k.linkage.value == default(fn, name)
    section, effect = where[0].split(".")
    sc = parse_scene({"system": {"kind": "linkage", "eps": 0.05}, "run": {"t_final": 10.0},
                      "effects": {effect: {}}})
    assert sc.effects[effect][where[1]] == default(fn, name)
    assert _resolved({effect: {}}).effects[effect][where[1]] == k.value != k.linkage.value
    written = parse_scene({"system": {"kind": "linkage", "eps": 0.05}, "run": {"t_final": 10.0},
                           "effects": {effect: {where[1]: 0.5}}})
    assert written.effects[effect][where[1]] == 0.5


def test_every_api_default_in_the_schema_resolves():
    for table in list(SCHEMA.values()) + list(EFFECTS.values()):
        for k in table.values():
            for d in (k.default, k.linkage):
                if isinstance(d, FromAPI):
                    fn = API[d.effect].split(":")[1]
                    assert fn in str(d) and d.value is not inspect.Parameter.empty


def _resolved(effects, **run):
    return parse_scene({"system": {"n": 4}, "run": {"t_final": 10.0, **run}, "effects": effects})


def test_parsed_defaults_are_the_apis():
    sc = _resolved({"lyapunov": {}, "angles": {}, "clv": {}})
    # a rule ("scaled") resolved as the API resolves it: by N and the speed (N = 4: 80)
    assert default(lyapunov_spectrum, "t_transient") == "scaled"
    assert sc.run["t_transient"] == scaled_transient(4, 1.0) == 80.0
    assert sc.transient_rule.startswith("scaled")
    assert sc.integrator["dt"] == default(lyapunov_spectrum, "dt") == default(hyperbolicity_angles, "dt")
    assert sc.effects["angles"]["t_transient"] == default(hyperbolicity_angles, "t_transient")
    assert sc.effects["clv"]["t_transient"] == default(covariant_lyapunov_vectors, "t_transient")
    # the main pass of lyapunov and curvature together: the two APIs agree
    assert default(lyapunov_spectrum, "t_transient") == default(curvature_along_trajectory,
                                                                 "t_transient")
    assert _resolved({"curvature": {}}).run["t_transient"] == scaled_transient(4, 1.0)
    assert _resolved({"waveforms": {}}).run["t_transient"] == default(waveform, "t_transient")
    assert _resolved({"angles": {}}).run["t_transient"] == default(hyperbolicity_angles,
                                                                   "t_transient")
    # written once, it is every pass's transient
    sc = _resolved({"lyapunov": {}, "angles": {}}, t_transient=3.0)
    assert sc.run["t_transient"] == sc.effects["angles"]["t_transient"] == 3.0


def test_lyapunov_scene_with_nothing_written_is_the_api_call(tmp_path):
    sc = parse_scene({"system": {"n": 3, "masses": [1.0, 1.5, 0.8]}, "run": {"t_final": 60.0},
                      "effects": {"lyapunov": {}}})
    res = run_scene(sc, tmp_path / "ly", quiet=True)["results"]["lyapunov"]
    system = RotorSystem(3, [1.0, 1.5, 0.8])
    theta0, u0 = system.random_state(seed=0)
    api = lyapunov_spectrum(system, theta0, u0, 60.0)
    assert res["exponents"] == api.exponents.tolist()
    assert res["stderr"] == api.stderr.tolist()
    assert res["energy_localisation"]["fraction"] == api.localised_fraction()
    with np.load(tmp_path / "ly" / "arrays.npz") as a:
        assert np.array_equal(a["energy_share_counts"], api.energy_shares)


def test_angles_scene_with_nothing_written_is_the_api_call(tmp_path):
    sc = parse_scene({"system": {"n": 3}, "initial": {"seed": 2}, "run": {"t_final": 5.0},
                      "effects": {"angles": {}}})
    run_scene(sc, tmp_path / "an", quiet=True)
    system = RotorSystem(3)
    theta0, u0 = system.random_state(seed=2)
    api = hyperbolicity_angles(system, theta0, u0, 5.0, seed=2)
    with np.load(tmp_path / "an" / "arrays.npz") as a:
        assert np.array_equal(a["angles_t"], api.t)
        assert np.array_equal(a["angles_full"], api.phi_full, equal_nan=True)
        assert np.array_equal(a["angles_restricted"], api.phi_restricted, equal_nan=True)


def test_defaults_follow_dt_where_written_values_must_be_whole():
    """A default left to the signature follows dt (the nearest whole number of steps, dividing
    t_final where it must); the same value written by the caller is refused, as any duration
    that is not a whole number of steps."""
    system = RotorSystem(4)
    theta0, u0 = system.random_state(seed=0)
    r = lyapunov_spectrum(system, theta0, u0, 40.0, dt=0.04, t_transient=0.0)
    assert r.params["reorth_every"] == pytest.approx(0.08)            # 2.5 steps → 2
    with pytest.raises(ValueError, match="reorth_every=0.1 is not a whole number of steps"):
        lyapunov_spectrum(system, theta0, u0, 40.0, dt=0.04, reorth_every=0.1)
    a = hyperbolicity_angles(system, theta0, u0, 6.0, dt=0.04, t_transient=1.0)
    assert a.params["sample_every"] == pytest.approx(0.08)
    assert repr(default(lyapunov_spectrum, "reorth_every")) == "0.1"   # the signature reads plainly
    # at the default dt nothing changes: 0.1 is 10 steps
    assert lyapunov_spectrum(system, theta0, u0, 40.0, t_transient=0.0).params[
        "reorth_every"] == 0.1


def test_scene_that_only_sets_dt_is_the_api_call(tmp_path):
    """dt = 0.04, nothing else written: the scene runs (it was refused: reorth_every = 0.1 is
    not a multiple of dt) and gives the API's numbers bit for bit."""
    sc = parse_scene({"system": {"n": 4}, "integrator": {"dt": 0.04}, "run": {"t_final": 40.0},
                      "effects": {"lyapunov": {}}})
    assert sc.effects["lyapunov"]["reorth_every"] == pytest.approx(0.08)
    res = run_scene(sc, tmp_path / "ly", quiet=True)["results"]["lyapunov"]
    system = RotorSystem(4)
    api = lyapunov_spectrum(system, *system.random_state(seed=0), 40.0, dt=0.04)
    assert res["exponents"] == api.exponents.tolist()


def test_rotor_scene_that_only_sets_dt_003_is_the_api_call(tmp_path):
    """dt = 0.03 and nothing else but the times: [integrator] project_every is left to the
    API's 1.0, which follows dt as the API's does (0.99; it was refused: 1.0 is not a
    multiple of 0.03); the exponents, curvatures and angles equal the API calls' bit for
    bit.  A project_every written in the scene is still checked strictly."""
    masses = [1.0, 2.0, 3.0, 1.0]
    scene = {"system": {"n": 4, "masses": masses}, "integrator": {"dt": 0.03},
             "run": {"t_final": 3.0, "t_transient": 0.6},
             "effects": {"lyapunov": {}, "curvature": {}, "angles": {}}}
    sc = parse_scene(scene)
    assert sc.integrator["project_every"] == pytest.approx(0.99)
    res = run_scene(sc, tmp_path / "r", quiet=True)["results"]
    system = RotorSystem(4, masses)
    theta0, u0 = system.random_state(seed=0)
    times = dict(dt=0.03, t_transient=0.6)
    ly = lyapunov_spectrum(system, theta0, u0, 3.0, **times)
    assert res["lyapunov"]["exponents"] == ly.exponents.tolist()
    assert res["lyapunov"]["stderr"] == ly.stderr.tolist()
    cu = curvature_along_trajectory(system, theta0, u0, 3.0, **times)
    an = hyperbolicity_angles(system, theta0, u0, 3.0, **times)
    with np.load(tmp_path / "r" / "arrays.npz") as a:
        assert np.array_equal(a["curvature_t"], cu.t + 0.6)
        assert np.array_equal(a["curvature_exact"], cu.diagonal("exact"))
        assert np.array_equal(a["curvature_numerical"], cu.diagonal("numerical"))
        assert np.array_equal(a["angles_t"], an.t)
        assert np.array_equal(a["angles_full"], an.phi_full, equal_nan=True)
        assert np.array_equal(a["angles_restricted"], an.phi_restricted, equal_nan=True)
    scene["integrator"]["project_every"] = 1.0
    with pytest.raises(ValueError, match=r"project_every = 1.0 is not allowed.*nearest: 0.99"):
        parse_scene(scene)
