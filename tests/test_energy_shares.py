"""Energy localisation (``charts.geometry.energy_shares``): the histogram of the largest
kinetic-energy share that the Lyapunov drivers record at every re-orthonormalisation.

Independent route: the same trajectory from ``charts.integrate`` (ambient RK4, bit for bit the
tangent kernel's where projection has the same phases: tests/test_ambient_tangent_identity.py)
sampled at the re-orthonormalisation times, its shares computed in NumPy and binned by
``np.histogram``.  The lanes, the device driver's CPU twin, scenes and saved files must hold
the same counts (tests/test_lanes.py, tests/test_device.py, tests/test_scene_defaults.py)."""
import numpy as np
import pytest

from charts import RotorSystem, integrate, lyapunov_ensemble, lyapunov_spectrum
from charts.geometry.energy_shares import (SHARE_BINS, largest_shares, localised_fraction,
                                           share_edges)

SYSTEM = RotorSystem(5, masses=[1.0, 2.0, 0.5, 1.5, 1.1])


def _reference_histogram(system, theta, u, t_transient, t_final, dt=0.01, every=10):
    """The histogram from an `integrate` run (projected every step) sampled every ``every``
    steps after the transient."""
    steps = round((t_transient + t_final) / dt)
    first = round(t_transient / dt)
    t_eval = np.arange(first + every, steps + 1, every) * dt
    r = integrate(system, theta, u, steps * dt, formulation="ambient", method="rk4", dt=dt,
                  project=True, t_eval=t_eval)
    shares = largest_shares(r.u, system.masses)
    return np.histogram(shares, bins=np.append(share_edges(), 1.0))[0], shares


def test_recorded_histogram_is_the_integrated_trajectorys():
    """lyapunov_spectrum with a transient, projecting every step: the counts equal those of
    the same trajectory integrated by `integrate` and binned by NumPy, sample for sample;
    the transient's samples are not counted."""
    theta, u = SYSTEM.random_state(seed=3)
    res = lyapunov_spectrum(SYSTEM, theta, u, 30.0, t_transient=5.0, project_every=0.01)
    ref, shares = _reference_histogram(SYSTEM, theta, u, 5.0, 30.0)
    assert res.energy_shares.sum() == 300 == len(shares)
    assert np.array_equal(res.energy_shares, ref)
    assert res.localised_fraction(0.4) == np.mean(shares >= 0.4)
    assert 0.0 < res.localised_fraction(0.4) < 1.0          # the test is not empty


def test_shares_are_bounded_by_one_rotor_and_by_equipartition():
    """The largest of N shares lies in [1/N, 1]: no count below bin floor(100/N)."""
    theta, u = SYSTEM.random_state(seed=4)
    res = lyapunov_spectrum(SYSTEM, theta, u, 20.0, t_transient=0.0)
    assert res.energy_shares[: SHARE_BINS // SYSTEM.n].sum() == 0
    assert res.localised_fraction(0.0) == 1.0 and res.localised_fraction(1.0) == 0.0


def test_the_histogram_does_not_change_the_exponents():
    """Recording is an observer: a flow without it gives the same exponents, bit for bit."""
    from charts.analyses.lyapunov import lyapunov_settings
    from charts.solvers.tangent import TangentFlow
    theta, u = SYSTEM.random_state(seed=5)
    cfg = lyapunov_settings(SYSTEM, 5.0)
    flows = [TangentFlow(SYSTEM, theta, u, 3, dt=0.01, reorth_every=cfg.reorth,
                         project_every=cfg.project, share_bins=b) for b in (0, SHARE_BINS)]
    for f in flows:
        f.advance(500)
    assert np.array_equal(flows[0].Z, flows[1].Z)
    assert np.array_equal(flows[0].logsum, flows[1].logsum)
    assert flows[0].shares.size == 0 and flows[1].shares.sum() == 50


def test_localised_fraction_reads_bin_edges_only():
    hist = np.zeros(SHARE_BINS, dtype=np.int64)
    hist[[25, 39, 40, 70]] = [5, 1, 2, 2]
    assert localised_fraction(hist, 0.4) == 0.4
    assert localised_fraction(hist, 0.39) == 0.5
    assert np.array_equal(localised_fraction(np.stack([hist, hist]), 0.7), [0.2, 0.2])
    for bad in (0.405, -0.01, 1.5):
        with pytest.raises(ValueError, match="multiple of 1/100"):
            localised_fraction(hist, bad)
    with pytest.raises(ValueError, match="no samples"):
        localised_fraction(np.zeros(SHARE_BINS), 0.4)


def test_ensemble_fractions_and_files_keep_the_counts(tmp_path):
    """An ensemble's members hold their counts (lanes), `localised_fractions` reads them, and
    a saved ensemble reads back with the same counts."""
    import charts
    pytest.importorskip("xarray")
    ens = lyapunov_ensemble(SYSTEM, 3, 10.0, seed=2, workers=1, lanes=True)
    fr = ens.localised_fractions(0.3)
    assert fr.shape == (3,)
    assert np.array_equal(fr, [m.localised_fraction(0.3) for m in ens.members])
    path = tmp_path / "ens.nc"
    ens.save(path)
    back = charts.load(path)
    for a, b in zip(ens.members, back.members):
        assert np.array_equal(a.energy_shares, b.energy_shares)
    ds = ens.to_xarray()
    assert ds["energy_share_counts"].dims == ("member", "share_bin")
    assert ds["share_bin"].values[40] == 0.4


def test_a_resumed_scene_keeps_its_histogram_and_an_old_checkpoint_is_named(tmp_path):
    """Interrupted and resumed, a Lyapunov scene gives the uninterrupted histogram; resumed
    from a checkpoint written before the histogram existed (no ``flow_shares``), it says the
    localisation is not given instead of reporting part of the run."""
    from charts.runs.runner import run_scene
    from charts.runs.scene import parse_scene
    sc = parse_scene({"system": {"n": 5}, "run": {"t_final": 4.0, "t_transient": 1.0,
                                                  "checkpoint_every": 0.5},
                      "effects": {"lyapunov": {"n_batches": 2}}})
    full = run_scene(sc, tmp_path / "full", quiet=True)["results"]["lyapunov"]

    def stop(i, n):
        if i == 3:
            raise KeyboardInterrupt

    for name in ("cut", "old"):
        with pytest.raises(KeyboardInterrupt):
            run_scene(sc, tmp_path / name, quiet=True, on_chunk=stop)
    ck = tmp_path / "old" / "checkpoint.npz"
    with np.load(ck) as a:
        arrays = {k: a[k] for k in a.files if k not in ("flow_shares", "shares_partial")}
    np.savez(ck, **arrays)
    cut = run_scene(sc, tmp_path / "cut", quiet=True, resume=True)["results"]["lyapunov"]
    old = run_scene(sc, tmp_path / "old", quiet=True, resume=True)["results"]["lyapunov"]
    assert cut["energy_localisation"] == full["energy_localisation"]
    assert full["energy_localisation"]["samples"] == 40
    assert "before the energy shares" in old["energy_localisation"]["note"]
    assert old["exponents"] == full["exponents"]
