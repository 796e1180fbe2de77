"""Waveforms and power spectra of the angular velocities, figures 2 and 3.

`waveform` samples θ(t), u(t) of eq (8) (the tangent kernel of ``charts.solvers.tangent``
with no tangent vectors: RK4, the state projected onto the invariants every
``project_every``).  `power_spectrum` estimates the spectral density of one rotor's velocity
by Welch's method (`scipy.signal.welch`: segments much longer than the signal's correlation
time, Hann window, averaged squared amplitudes), as described in section 1.

Frequency convention (the project's, everywhere): angular frequency ω in rad per unit time,
spectral density per unit ω (its integral over ω ≥ 0 is the signal's variance).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..jit.compilation import announces_compilation
from ..geometry.checks import finite_array
from ..solvers.tangent import TangentFlow
from ..io.archive import Archivable, attributes, dataset
from ..io.result_words import ANGULAR_VELOCITY, counted
from .arguments import (positive_time, progress_reporter, project_steps, samples_of,
                        start_state, steps_of, Documented)
from .arguments import rotor_system

__all__ = ["Waveform", "PowerSpectrum", "waveform", "power_spectrum"]


@dataclass(eq=False, repr=False)
class Waveform(Archivable):
    """Sampled trajectory: t (S,), theta (S, N), u (S, N); sample spacing ``dt_sample``;
    ``params``: the system, the initial state and the settings of the call."""
    t: np.ndarray
    theta: np.ndarray
    u: np.ndarray
    dt_sample: float
    params: dict = field(default_factory=dict)

    def summary_parts(self):
        """The sample spacing and the largest |uᵢ|."""
        top = f"max |u| {np.abs(self.u).max():.3g} {ANGULAR_VELOCITY}" if self.u.size else ""
        return [f"every {self.dt_sample:g}", top]

    KIND = "waveform"

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``)."""
        return dataset(self.KIND, {"theta": (("t", "rotor"), self.theta, "rad"),
                                   "u": (("t", "rotor"), self.u, ANGULAR_VELOCITY)},
                       coords={"t": (("t",), self.t, "time"),
                               "rotor": (("rotor",), np.arange(self.theta.shape[1]), "1",
                                         "rotor index, from 0 as in scenes")},
                       attrs={"dt_sample": self.dt_sample, "params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        a = attributes(ds)
        return cls(ds["t"].values, ds["theta"].values, ds["u"].values, a["dt_sample"],
                   a.get("params", {}))

    def plot(self, ax=None, kind="angles", **kw):
        """``kind="angles"``: θᵢ(t) wrapped to (−π, π], ``(fig, ax)``
        (``charts.plotting.plot_angles_time``); ``"velocities"``: uᵢ(t), one panel per rotor
        (``rotors=[...]`` to choose), the paper's figure 2, ``(fig, axes)``
        (``charts.plotting.plot_velocities_time``); ``window=(t0, t1)`` for a span; the title
        names the system."""
        from ..plotting import plot_angles_time, plot_velocities_time, system_label
        if kind == "velocities":
            kw.setdefault("title", f"angular velocities, {system_label(self.params)}")
            return plot_velocities_time(self.t, self.u, axes=ax, **kw)
        if kind != "angles":
            raise ValueError(f"kind must be 'angles' or 'velocities', got {kind!r}")
        kw.setdefault("system", system_label(self.params))
        return plot_angles_time(self.t, self.theta, ax=ax, **kw)


class PowerSpectrum(Archivable, tuple):
    """``(omega, density)`` of :func:`power_spectrum` — still unpacks as that pair — with
    ``params`` (dt_sample, segment_time), ``to_xarray``/``save`` and ``plot``."""

    def summary_parts(self):
        """The frequencies, the segment length and the frequency of the largest density."""
        om, S = self.omega, self.density
        peak = f"peak at ω = {om[np.argmax(S)]:.3g}" if S.size else ""
        seg = self.params.get("segment_time")
        top = f" up to ω = {om.max():.3g} {ANGULAR_VELOCITY}" if om.size else ""
        return [counted(om.size, "frequency", "frequencies") + top,
                f"segments of {seg:g}" if seg is not None else "", peak]

    KIND = "spectrum"

    def __new__(cls, omega, density, params):
        obj = tuple.__new__(cls, (np.asarray(omega), np.asarray(density)))
        obj.params = dict(params)
        return obj

    def __getnewargs__(self):       # pickling (worker processes)
        return self[0], self[1], self.params

    @property
    def omega(self):
        return self[0]

    @property
    def density(self):
        return self[1]

    def to_xarray(self):
        """This result as an ``xarray.Dataset``: named dimensions, units, settings as
        attributes (``charts.io.archive``)."""
        return dataset(self.KIND, {"density": (("omega",), self.density, "signal² · time / rad",
                                               "one-sided power spectral density per unit ω")},
                       coords={"omega": (("omega",), self.omega, ANGULAR_VELOCITY,
                                         "angular frequency ω")},
                       attrs={"params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        return cls(ds["omega"].values, ds["density"].values, attributes(ds)["params"])

    def plot(self, ax=None, **kw):
        """Log density against ω (rad per unit time); ``(fig, ax)``
        (``charts.plotting.plot_spectrum``)."""
        from ..plotting import plot_spectrum
        return plot_spectrum(self.omega, self.density, ax=ax, **kw)


@announces_compilation
def waveform(system, theta0, u0, t_final, *, dt=0.01, sample_every=Documented(0.05),
             t_transient=0.0, project_every=Documented(1.0), progress=False) -> Waveform:
    """θ(t) and u(t) from (theta0, u0) every ``sample_every`` up to ``t_final`` after
    discarding ``t_transient`` (times written whole numbers of RK4 steps ``dt``; a default
    left, ``sample_every`` 0.05 and ``project_every`` 1.0, the nearest whole number of steps
    at other dt: README, "Conventions"); ``progress``:
    True or callable(t_done, t_total)."""
    rotor_system(system)
    dt = positive_time("dt", dt)
    total = steps_of("t_final", t_final, dt)
    sample = steps_of("sample_every", sample_every, dt, divides=total)
    transient = steps_of("t_transient", t_transient, dt, allow_zero=True)
    project = project_steps(project_every, dt)
    S = samples_of(total, sample, t_final, sample_every)
    if S < 2:
        raise ValueError(f"t_final={t_final:g} gives fewer than 2 samples of sample_every="
                         f"{sample * dt:g} ({sample} step(s) of dt={dt:g}); increase t_final "
                         "or decrease dt")
    theta0, u0 = start_state(system, theta0, u0, dt)
    flow = TangentFlow(system, theta0, u0, 0, dt=dt, project_every=project)
    out = np.empty((S, 2 * system.n))
    total = transient + S * sample
    rep = progress_reporter(progress, total * dt, f"waveform N={system.n}")
    c = min(total, 100)
    for size in np.diff([total * i // c for i in range(c + 1)]):
        flow.advance(size, rec_start=transient + sample, rec_every=sample, states=out,
                     where="waveform (ambient RK4)")
        rep.update(size * dt)
    rep.close()
    t = np.arange(1, S + 1) * sample * dt
    n = system.n
    params = dict(**system.describe(), speed=flow.speed, dt=dt,
                  theta0=np.asarray(theta0, float).tolist(), u0=np.asarray(u0, float).tolist(),
                  t_final=total * dt, t_transient=transient * dt,
                  project_every=project * dt or None)
    return Waveform(t, out[:, :n], out[:, n:], sample * dt, params)


def power_spectrum(signal, dt_sample, *, segment_time=200.0):
    """Welch estimate of the one-sided power spectral density of ``signal`` (shape (S,))
    sampled every ``dt_sample``: segments of ``segment_time`` with 50 % overlap and a
    Hann window.  Returns a :class:`PowerSpectrum`, the pair (ω (F,), rad per unit time;
    density per unit ω (F,))."""
    signal = finite_array("signal", signal, ndim=1)
    dt_sample = positive_time("dt_sample", dt_sample)
    segment_time = positive_time("segment_time", segment_time)
    nper = int(round(segment_time / dt_sample))
    if abs(nper * dt_sample - segment_time) > 1e-9 * segment_time:
        raise ValueError(f"segment_time={segment_time:g} is not a whole number of samples "
                         f"dt_sample={dt_sample:g}")
    if nper < 2 or nper > signal.size // 4:
        raise ValueError(f"signal ({signal.size} samples of dt_sample={dt_sample:g}) is too short "
                         f"for Welch segments of segment_time={segment_time:g}: need at least 4 "
                         "segments of at least 2 samples")
    from scipy.signal import welch  # imported here: scipy.signal costs seconds at import

    f, p = welch(signal, fs=1.0 / dt_sample, window="hann", nperseg=nper, detrend="constant")
    return PowerSpectrum(2 * np.pi * f, p / (2 * np.pi),
                         {"dt_sample": dt_sample, "segment_time": segment_time})
