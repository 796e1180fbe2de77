"""A mechanism's results saved, loaded and plotted; scenes with a [mechanism] table; sweeps
over a mechanism's parameters."""
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
