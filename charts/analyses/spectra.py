"""Waveforms and power spectra of the angular velocities, figures 2 and 3.

`waveform` samples u(t) of eq (8) (RK4, the same fused kernel as `charts.lyapunov`
with no tangent vectors, state projected back onto the manifold every 100 steps).
`power_spectrum` estimates the spectral density of one rotor's velocity by Welch's
method (`scipy.signal.welch`: segments much longer than the signal's correlation time,
Hann window, averaged squared amplitudes), as described in section 1.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..flows.ambient import project_state
from .lyapunov import _initial_state, _rk4_step

__all__ = ["Waveform", "waveform", "power_spectrum"]


@njit(cache=True)
def _sample_kernel(y, minv, m, speed, dt, every, out):
    """RK4 of eq (8); out[k] = y after (k+1)·every steps, shape (S, 2N)."""
    n = y.size // 2
    s = np.empty(n)
    c = np.empty(n)
    ky = np.empty((4, 2 * n))
    X = np.empty((0, 2 * n))
    kX = np.empty((4, 0, 2 * n))
    yt = np.empty(2 * n)
    step = 0
    for k in range(out.shape[0]):
        for _ in range(every):
            _rk4_step(y, X, minv, dt, s, c, ky, kX, yt, X)
            step += 1
            if step % 100 == 0:
                project_state(y, m, speed)
        out[k] = y


@dataclass
class Waveform:
    """Sampled trajectory: t (S,), theta (S, N), u (S, N); sample spacing ``dt_sample``."""
    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    dt_sample: float


def waveform(system, theta0, u0, t_final, *, dt=0.01, sample_every=5, t_transient=0.0):
    """u(t) and θ(t) from (theta0, u0) every ``sample_every`` RK4 steps up to t_final
    (after discarding t_transient)."""
    y, speed = _initial_state(system, theta0, u0)
    args = (system.minv, system.masses, speed, float(dt))
    if t_transient > 0:
        _sample_kernel(y, *args, int(round(t_transient / dt)), np.empty((1, y.size)))
    S = int(round(t_final / dt)) // int(sample_every)
    if S < 2:
        raise ValueError(f"t_final={t_final} gives fewer than 2 samples; increase it")
    out = np.empty((S, y.size))
    _sample_kernel(y, *args, int(sample_every), out)
    t = np.arange(1, S + 1) * sample_every * dt
    n = system.n
    return Waveform(t, out[:, :n], out[:, n:], sample_every * dt)


def power_spectrum(signal, dt_sample, *, segment_time=200.0):
    """Welch estimate of the one-sided power spectral density of ``signal`` (shape (S,))
    sampled every ``dt_sample``: segments of ``segment_time`` with 50 % overlap and a
    Hann window.  Returns (angular frequency ω = 2πf, shape (F,), density per unit ω)."""
    signal = np.asarray(signal, dtype=float)
    nper = int(round(segment_time / dt_sample))
    if nper > signal.size // 4:
        raise ValueError(f"signal of {signal.size * dt_sample:g} time units is too short for "
                         f"Welch segments of {segment_time:g}; need at least 4 segments")
    from scipy.signal import welch  # imported here: scipy.signal costs seconds at import

    f, p = welch(signal, fs=1.0 / dt_sample, window="hann", nperseg=nper, detrend="constant")
    return 2 * np.pi * f, p / (2 * np.pi)
