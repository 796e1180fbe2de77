"""The result of a Lyapunov spectrum (``charts.analyses.lyapunov.lyapunov_spectrum``, section 2):
the exponents with their batch-means errors, the convergence history, the spectrum
reconstructed from its leading half (pairs ±λ and two zeros), the energy shares of the
vectors; saved to NetCDF and plotted."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..io.archive import Archivable, attributes, dataset, exponent_coordinate
from ..io.result_words import RATE, exponent_words
from ..geometry.energy_shares import (LOCALISED_SHARE, SHARE_BINS, localised_fraction, share_bin,
                                      share_edges)
from .spectrum_quantities import SpectrumQuantities, reconstructed_spectra

__all__ = ["LyapunovResult"]


@dataclass(eq=False, repr=False)
class LyapunovResult(SpectrumQuantities, Archivable):
    """Result of `lyapunov_spectrum`.

    exponents : (k,)  the computed exponents (1/time), in the order of eq (18)'s
        Gram–Schmidt: largest first once converged (a short run's estimates may be unsorted).

    stderr : (k,)  two-sided standard errors (batch means).

    spectrum : (2N−2,) or None  the relevant spectrum: reconstructed from the leading N−2
        (pairs ±λ and two zeros) if only those were computed, else the computed values.

    history_t : (n_rec,)  times (after the transient) of the convergence history.
    history : (n_rec, k)  running estimates of the exponents at ``history_t``.
    batches : (n_batches, k)  per-block estimates behind ``stderr``.

    energy_shares : (bins,) or None  histogram of the largest kinetic-energy share
        max_i mᵢuᵢ² / Σ mⱼuⱼ², sampled at every re-orthonormalisation of the averaging time
        (bin b: shares in [b/bins, (b+1)/bins)); `localised_fraction` reads it.
    """
    exponents: np.ndarray
    stderr: np.ndarray
    spectrum: np.ndarray | None
    history_t: np.ndarray
    history: np.ndarray
    batches: np.ndarray
    params: dict = field(default_factory=dict)
    energy_shares: np.ndarray | None = None

    KIND = "lyapunov"

    def to_xarray(self):
        """Dataset: exponents, stderr (exponent); history (record, exponent) at history_t;
        batches (batch, exponent); full_spectrum (spectrum_index); the settings as attributes."""
        k = len(self.exponents)
        data = {"exponents": (("exponent",), self.exponents, RATE,
                              "Lyapunov exponents λᵢ (eq 18), λ₁ the largest"),
                "stderr": (("exponent",), self.stderr, RATE, "two-sided standard error"),
                "history": (("record", "exponent"), self.history, RATE,
                            "running estimates"),
                "batches": (("batch", "exponent"), self.batches, RATE, "batch estimates")}
        coords = {"exponent": exponent_coordinate(k),
                  "history_t": (("record",), self.history_t, "time", "averaging time")}
        if self.spectrum is not None:
            data["full_spectrum"] = (("spectrum_index",), self.spectrum, RATE,
                                     "the whole spectrum of the 2N−2 dimensional phase "
                                     "space, (λ…, 0, 0, −λ…): reconstructed from the "
                                     "leading N−2, or computed")
            coords["spectrum_index"] = (("spectrum_index",),
                                        np.arange(1, len(self.spectrum) + 1, dtype=np.int64), "1",
                                        "i of λᵢ in the relevant spectrum, from 1 as in the "
                                        "paper (as exponent)")
        if self.energy_shares is not None:
            data["energy_share_counts"] = (("share_bin",), self.energy_shares, "1",
                                           "samples of the largest kinetic-energy share of one "
                                           "rotor, per bin, every re-orthonormalisation")
            coords["share_bin"] = (("share_bin",), share_edges(len(self.energy_shares)), "1",
                                   "lower edge of the bin of the largest share")
        return dataset(self.KIND, data, attrs={"params": self.params}, coords=coords)

    @classmethod
    def from_xarray(cls, ds):
        return cls(exponents=ds["exponents"].values, stderr=ds["stderr"].values,
                   spectrum=ds["full_spectrum"].values if "full_spectrum" in ds else None,
                   history_t=ds["history_t"].values, history=ds["history"].values,
                   batches=ds["batches"].values, params=attributes(ds)["params"],
                   energy_shares=(ds["energy_share_counts"].values
                                  if "energy_share_counts" in ds else None))

    def localised_fraction(self, share=LOCALISED_SHARE) -> float:
        """Fraction of the averaging time in which one rotor held at least ``share`` of the
        kinetic energy (from ``energy_shares``; ``share`` a real number in [0, 1], a multiple
        of 0.01: ``charts.geometry.energy_shares.share_bin``)."""
        share_bin(share, SHARE_BINS if self.energy_shares is None
                  else np.shape(self.energy_shares)[-1])
        if self.energy_shares is None:
            raise ValueError("this result holds no energy shares (computed before they were "
                             "recorded)")
        return float(localised_fraction(self.energy_shares, share))

    def plot(self, ax=None, **kw):
        """Running estimates against the averaging time (log axis) with the final estimate ±
        its standard error as bands; ``(fig, ax)`` (``charts.plotting.plot_lyapunov``;
        ``paper=[...]`` adds reference values)."""
        from ..plotting import plot_lyapunov, system_label
        kw.setdefault("system", system_label(self.params))
        return plot_lyapunov(self.history_t, self.history, self.exponents, self.stderr, ax=ax, **kw)

    def plot_spectrum(self, ax=None, **kw):
        """λᵢ ± standard error against i/(N − 2), so that spectra of several N share one axis
        (``charts.plotting.plot_lyapunov_spectrum``); ``(fig, ax)``."""
        from ..plotting import plot_lyapunov_spectrum, system_label
        kw.setdefault("label", system_label(self.params))
        return plot_lyapunov_spectrum(self.exponents, self.stderr, self.params["n"], ax=ax, **kw)

    def _spectra(self):
        """(the spectrum, its batch estimates as spectra): what the entropy and the dimension
        are computed from; ValueError where not every positive exponent was computed."""
        if self.spectrum is None:
            raise ValueError(f"this result holds {len(self.exponents)} exponents, not the whole "
                             "relevant spectrum; compute n_exponents=None (the N-2 positive ones) "
                             "or every exponent of the space")
        k, total = len(self.exponents), len(self.spectrum)
        rows = self.batches if k == total else reconstructed_spectra(self.batches, k, total)
        return self.spectrum, rows

    def summary_parts(self):
        """The averaging time and the exponents ± their standard errors."""
        T = self.params.get("t_final")
        return [f"T = {T:g}" if T is not None else "", exponent_words(self.exponents, self.stderr)]
