"""Waveforms (figure 2) and Welch power spectra (figure 3)."""
import numpy as np
import pytest

from charts.geometry.projection import invariants
from charts.analyses.spectra import power_spectrum, waveform
from charts.geometry.system import RotorSystem

#: RK4 dt = 0.01 with projection every 100 steps: drift of the invariants between
#: projections is ~1e-8 (measured 2e-8).
INVARIANT_TOL = 1e-6
#: a continuous spectrum has no line: no bin stands far above the median of its ±10
#: neighbours (a pure tone stands > 1e3 above; Welch noise of ~40 averaged segments
#: gives ratios ≲ 2 for a smooth density).
MAX_LINE_RATIO = 10.0


def _line_ratio(p, half=10):
    """Largest ratio of a bin to the median of its ±half neighbours."""
    r = 0.0
    for i in range(half, p.size - half):
        nb = np.concatenate([p[i - half:i], p[i + 1:i + half + 1]])
        r = max(r, p[i] / np.median(nb))
    return r


@pytest.mark.parametrize("n", [3, 5])
def test_waveform_stays_on_manifold_at_unit_speed(n):
    system = RotorSystem(n)
    theta, u = system.random_state(seed=1)
    w = waveform(system, theta, u, 500.0)
    F, G, E = invariants(w.theta, w.u, system.masses)
    assert np.abs(F).max() < INVARIANT_TOL
    assert np.abs(G).max() < INVARIANT_TOL
    assert np.abs(E - 0.5).max() < INVARIANT_TOL
    assert w.t[1] - w.t[0] == pytest.approx(w.dt_sample)


def test_welch_finds_a_pure_tone():
    dt = 0.05
    t = np.arange(0, 4000.0, dt)
    om, p = power_spectrum(np.sin(1.7 * t), dt)
    assert om[np.argmax(p)] == pytest.approx(1.7, abs=2 * (om[1] - om[0]))
    assert _line_ratio(p) > 1e3


@pytest.mark.parametrize("n", [3, 4, 5])
def test_velocity_spectrum_is_continuous(n):
    system = RotorSystem(n)
    theta, u = system.random_state(seed=2)
    w = waveform(system, theta, u, 4000.0)
    om, p = power_spectrum(w.u[:, 0], w.dt_sample)
    band = om < 10.0  # above ω ≈ 10 the density is ~1e-20, pure rounding
    assert _line_ratio(p[band]) < MAX_LINE_RATIO
    # Parseval: the density integrates to the variance (minus the per-segment means
    # removed by detrending, which only touch the lowest bins)
    var = np.trapezoid(p, om)
    assert 0.7 * w.u[:, 0].var() < var < 1.05 * w.u[:, 0].var()


def test_rejects_short_signal():
    with pytest.raises(ValueError, match="too short"):
        power_spectrum(np.zeros(100), 0.05)
