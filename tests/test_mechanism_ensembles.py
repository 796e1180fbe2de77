"""Ensembles on a Mechanism (charts.analyses.mechanism_ensemble) through the public names
charts.lyapunov_ensemble, hyperbolicity_ensemble and covariant_ensemble, and the pickling
that sends a mechanism to the worker processes."""
import pickle

import numpy as np
import pytest
import sympy as sp

import charts
from charts.mechanism import Mechanism, MechanismError


@pytest.fixture(scope="module")
def linkage():
    return charts.triple_linkage(0.2)


def arm():
    """The user-defined arm on a rail of docs/mechanisms.md (a configuration-dependent
    metric, parameters)."""
    th, l, m, qd = (sp.symbols(s) for s in ("theta1:4", "l1:4", "m1:4", "qd1:4"))
    P, T = sp.zeros(2, 1), 0
    for i in range(3):
        P = P + l[i] * sp.Matrix([sp.cos(th[i]), sp.sin(th[i])])
        Pd = sum((P.diff(t) * d for t, d in zip(th, qd)), sp.zeros(2, 1))
        T += m[i] / 2 * (Pd.T * Pd)[0]
    return Mechanism(th, [P[1]], sp.hessian(T, qd), periodic=th, name="arm on a rail",
                     parameters={**dict(zip(l, (1.0, 0.8, 0.6))), **dict(zip(m, (1.0, 1.0, 0.5)))})


def test_a_users_mechanism_pickles_with_its_description_and_parameters():
    mech = arm()
    q, v = mech.random_state(seed=1)
    copy = pickle.loads(pickle.dumps(mech))
    again = pickle.loads(pickle.dumps(mech))
    assert copy.name == mech.name and copy.parameter_values == mech.parameter_values
    assert copy._num is again._num            # one lambdification per process and model
    q2, v2 = copy.random_state(seed=1)
    assert np.array_equal(q, q2) and np.array_equal(v, v2)
    # the same numbers from the copy: its lambdified and compiled jets are the original's
    assert np.array_equal(copy.mass_matrix(q), mech.mass_matrix(q))
    a = charts.lyapunov_spectrum(mech, q, v, 0.5, t_transient=0.0, n_batches=2)
    b = charts.lyapunov_spectrum(copy, q, v, 0.5, t_transient=0.0, n_batches=2)
    assert np.array_equal(a.exponents, b.exponents)
    # with_parameters still shares the functions (a copy, not a pickle)
    other = copy.with_parameters(l1=1.1)
    assert other._num is copy._num and other.parameter_values["l1"] == 1.1
    # and it travels to worker processes: an ensemble there gives the bits of one here
    kw = dict(t_transient=0.0, n_batches=2)
    assert charts.lyapunov_ensemble(mech, 2, 0.5, workers=2, **kw) == \
        charts.lyapunov_ensemble(mech, 2, 0.5, workers=1, **kw)


def _same_bits(e1, e2, fields):
    assert len(e1) == len(e2)
    for a, b in zip(e1, e2):
        for f in fields:
            assert np.array_equal(getattr(a, f), getattr(b, f)), f
        assert a.params == b.params


# (public ensemble, its single analysis, the member's arrays, settings of a short run)
CASES = {
    "lyapunov": (charts.lyapunov_ensemble, charts.lyapunov_spectrum,
                 ("exponents", "batches"), dict(t_transient=1.0, n_batches=2)),
    "angles": (charts.hyperbolicity_ensemble, charts.hyperbolicity_angles,
               ("phi_restricted", "forward_exponents", "adjoint_exponents"),
               dict(t_transient=0.5)),
    "covariant": (charts.covariant_ensemble, charts.covariant_lyapunov_vectors,
                  ("phi", "phi_vectors", "growth", "gs_rates", "states"), dict(t_transient=0.5)),
}


@pytest.mark.parametrize("case", list(CASES))
def test_ensemble_in_one_or_two_processes_gives_the_single_runs(linkage, case):
    ensemble, single, fields, kw = CASES[case]
    one = ensemble(linkage, 2, 1.0, seed=3, workers=1, **kw)
    two = ensemble(linkage, 2, 1.0, seed=3, workers=2, **kw)
    _same_bits(one, two, fields)              # the worker processes change no bit
    assert one.params["members_seed"] == 3
    assert one.params["mechanism"] == linkage.name
    # member i is the single analysis from mech.random_state(seed=3 + i), vectors seed 3 + i
    runs = [single(linkage, *linkage.random_state(seed=3 + i), 1.0, seed=3 + i, **kw)
            for i in range(2)]
    for i, (m, r) in enumerate(zip(one, runs)):
        assert m.params["state_seed"] == 3 + i and m.params["vectors_seed"] == 3 + i
        for f in fields:
            assert np.array_equal(getattr(m, f), getattr(r, f)), f
    if case != "angles":                      # exponents: mean and s.e. across members
        E = np.array([r.exponents for r in runs])
        assert np.array_equal(one.exponents, E.mean(axis=0))
        assert np.allclose(one.stderr, E.std(axis=0, ddof=1) / np.sqrt(2), rtol=1e-12)


def test_an_ensembles_bad_arguments_are_refused_by_name(linkage):
    with pytest.raises(ValueError, match="n_trajectories"):
        charts.lyapunov_ensemble(linkage, 1, 1.0)
    with pytest.raises(ValueError, match="workers"):
        charts.hyperbolicity_ensemble(linkage, 2, 1.0, workers=0)
    with pytest.raises(ValueError, match="speed"):
        charts.covariant_ensemble(linkage, 2, 1.0, speed=-1.0)
    with pytest.raises(ValueError, match="dt"):
        charts.lyapunov_ensemble(linkage, 2, 1.0, dt=0.0)
    with pytest.raises(ValueError, match="n_batches"):
        charts.lyapunov_ensemble(linkage, 2, 1.0, n_batches=1)
    with pytest.raises(ValueError, match="n_unstable"):
        charts.hyperbolicity_ensemble(linkage, 2, 1.0, n_unstable=5)
    with pytest.raises(TypeError, match="reorth_every"):     # a setting of another analysis
        charts.hyperbolicity_ensemble(linkage, 2, 1.0, reorth_every=0.1)
    with pytest.raises(ValueError, match="variant"):
        charts.covariant_ensemble(linkage, 2, 1.0, variant="full", t_transient=0.0)
    with pytest.raises(ValueError, match="t_final"):
        charts.lyapunov_ensemble(linkage, 2, -1.0)
    circle = Mechanism(["x", "y"], [sp.Symbol("x") ** 2 + sp.Symbol("y") ** 2 - 1],
                       masses=[1, 1], name="circle")
    with pytest.raises(MechanismError, match="1-dimensional"):
        charts.lyapunov_ensemble(circle, 2, 1.0)


def test_the_linkage_ensemble_is_the_generic_ensemble_with_linkage_run_members():
    """linkage_ensemble runs on mechanism_ensemble with linkage_run as its member; its
    exponents are those of charts.lyapunov_ensemble on the same LinkageSystem, bit for bit
    (both members advance the same MechanismTangentFlow from the same states and seeds)."""
    from charts.mechanism.linkage import LinkageSystem
    system = LinkageSystem(0.1)
    kw = dict(t_transient=1.0, n_batches=2, n_exponents=2)
    link = charts.linkage_ensemble(system, 2, 2.0, workers=1, seed=4, sample_every=1.0, **kw)
    generic = charts.lyapunov_ensemble(system, 2, 2.0, workers=1, seed=4, **kw)
    assert type(link[0]).__name__ == "LinkageResult"
    assert type(generic[0]).__name__ == "MechanismLyapunov"
    for a, b in zip(link, generic):
        assert np.array_equal(a.exponents, b.exponents)
        assert np.array_equal(a.batches, b.batches)
        assert a.params["state_seed"] == b.params["state_seed"]
    assert np.array_equal(link.exponents, generic.exponents)


def test_a_mechanisms_curvature_is_saved_by_its_coordinates_and_loads_back(linkage, tmp_path):
    q, v = linkage.random_state(seed=1)
    res = charts.curvature_along_trajectory(linkage, q, v, 0.3, t_transient=0.0)
    ds = res.to_xarray()
    assert ds.attrs["charts_kind"] == "mechanism_curvature"
    assert "rotor" not in ds.dims and ds["q"].dims == ("t", "coordinate")
    assert ds["frames"].dims == ("t", "frame", "coordinate")
    assert ds["coordinate"].values.tolist() == ["theta1", "theta2", "theta3", "x", "y"]
    assert ds["coordinate_units"].values.tolist() == ["rad"] * 3 + ["length"] * 2
    res.save(tmp_path / "c.nc")
    back = charts.load(tmp_path / "c.nc")
    assert type(back) is type(res) and back.params == res.params
    for f in ("t", "theta", "u", "frames", "K_numeric", "K_exact"):
        assert np.array_equal(getattr(back, f), getattr(res, f)), f
    # the rotors' files keep their names
    rotors = charts.RotorSystem(3)
    ds = charts.curvature_along_trajectory(rotors, *rotors.random_state(seed=1), 0.2,
                                           t_transient=0.0, exact=False).to_xarray()
    assert ds.attrs["charts_kind"] == "curvature" and ds["theta"].dims == ("t", "rotor")
    assert ds["frames"].dims == ("t", "frame", "rotor") and "coordinate" not in ds.dims


def test_a_mechanisms_ensembles_save_and_load_back(linkage, tmp_path):
    ens = charts.lyapunov_ensemble(linkage, 2, 1.0, workers=1, t_transient=0.0, n_batches=2)
    ens.save(tmp_path / "e.nc")
    back = charts.load(tmp_path / "e.nc")
    assert np.array_equal(back.exponents, ens.exponents)
    assert np.array_equal(back.stderr, ens.stderr)
    assert [m.params["state_seed"] for m in back] == [0, 1]
    assert back.params["mechanism"] == linkage.name
    angles = charts.hyperbolicity_ensemble(linkage, 2, 0.5, workers=1, t_transient=0.0)
    angles.save(tmp_path / "a.nc")
    back = charts.load(tmp_path / "a.nc")
    assert type(back[0]).__name__ == "MechanismAngles" and back == angles
    assert back[1].params == angles[1].params and back[1].statistics() == angles[1].statistics()


def test_a_mechanisms_tally_is_the_tally_of_its_ensembles_angles(linkage, tmp_path):
    """hyperbolicity_tally on a mechanism: the same sums in one process and in two with a
    chunk per member; they equal a tally fed the angles of hyperbolicity_ensemble's members
    (the same states and seeds), and it saves and loads with its one variant."""
    from charts.analyses.angle_tally import SUMS, AngleTally
    kw = dict(t_transient=0.5, seed=2)
    one = charts.hyperbolicity_tally(linkage, 3, 1.0, workers=1, **kw)
    two = charts.hyperbolicity_tally(linkage, 3, 1.0, workers=2, chunk=1, **kw)
    ens = charts.hyperbolicity_ensemble(linkage, 3, 1.0, workers=1, **kw)
    fed = AngleTally.empty(3, {"members_seed": 2}, ("restricted",))
    for i, m in enumerate(ens):
        fed.add(m.phi_restricted[None, :], i)
    assert one.variants == ("restricted",)
    for k in SUMS:
        assert np.array_equal(getattr(one, k), getattr(two, k)), k
        assert np.array_equal(getattr(one, k), getattr(fed, k)), k
    s = one.statistics()
    assert s["min"] == ens.concatenate("phi_restricted").min() and s["n"] == 30
    lowest = ens[s["min_seed"] - 2]                 # the member and time of the minimum
    assert s["min_t"] == pytest.approx(lowest.t[np.argmin(lowest.phi_restricted)], abs=1e-12)
    with pytest.raises(ValueError, match="variant"):
        one.statistics("full")
    one.save(tmp_path / "t.nc")
    back = charts.load(tmp_path / "t.nc")
    assert back.variants == ("restricted",) and back.statistics() == s
    with pytest.raises(TypeError, match="device"):
        charts.hyperbolicity_tally(linkage, 2, 1.0, device="cuda")
